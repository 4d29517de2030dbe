#!/usr/bin/python3
"""Hostile values against every option of the surfaces added last (issue 40 item 7), run as a test.

Each case runs the real binary ($DFVN_SAMPLE, and $DFVN_SAMPLE_MPI when set) with one hostile value in one
option of a small base command that makes the option matter, and checks the promises of
docs/ROBUSTNESS.md whatever the value:
  - the run ends by itself (no signal, no timeout) with 0, 1 or 2;
  - refused (non-zero): stdout empty, stderr exactly one line "dfvn-sample: error: ..." of at most 400
    bytes, no control byte, the offending text quoted once (no ''x''), numbers not printed as "0.000000",
    no C++ internals (std::, basic_string, max_size, bad_alloc), no output file created;
  - accepted (0): no error line on stderr (only the program's notes, warnings and relayed gnuplot lines), and no NaN or Inf in any file written
    (frames.npy in drop mode excepted: its NaN rows mean "outside", animate/animation.hpp);
  - $TMPDIR (a fresh folder) is empty afterwards.
Python (with $PYTHONPATH holding the module): every keyword of dfvn.field, dfvn.trace, dfvn.sample,
dfvn.nn_stats and dfvn.rdf with the same values must return finite arrays or raise ValueError, TypeError
or MemoryError whose message is one line that names the keyword.

Usage: probe_hostile.py [--list] [--verbose] [FILTER]   (FILTER: run the cases whose name contains it)
Prints one line per failed case and a count; exits 1 when any case failed.
"""
import concurrent.futures
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

BIN = os.environ.get("DFVN_SAMPLE")
SECONDS = []  # (seconds, case) of every command-line case run
MPI = os.environ.get("DFVN_SAMPLE_MPI")
TIMEOUT = 30

# Values every numeric option meets; lists and paths have their own below.
NUMBERS = ["0", "-0", "-1", "nan", "-nan", "inf", "-inf", "1e-310", "5e-324", "-1e-300", "1e308", "-1e308", "1e400",
           "18446744073709551616", "9223372036854775808", "4294967296", "2147483648", "99999999999999999999999",
           "", " ", "abc", "1,2", "0x10", "1e", "1.5.2", "\x1b[31m", "1" * 200]
INTEGERS = NUMBERS + ["1.5", "-2147483649", "3"]
# Lists of N reals (U of --stretch, --steer-dir): wrong dimension, malformed, extreme lengths.
DIRECTIONS = ["", ",", "1,,0", "1,0,", ",1,0", "0,0", "-0,0", "nan,0", "inf,0", "1e-300,0", "1e-300,1e-300", "1e300,1e300",
              "1e308,1e308", "5e-324,0", "1e-310,1e-310", "1", "1,0,0", "1,0,0,0,0,0,0,0,0", "a,b", "1;0", "1 0", "'1,0'"]
# A text file of two 2D points, an empty one, a directory, a missing file, an unreadable special file.
PATHS_IN = ["{in2}", "{empty}", "{dir}", "{missing}", "/dev/null", "{bad}", "{nan}", "{in3}", ""]
PATHS_OUT = ["{dir}", "{in2}/x.csv", "/proc/version", "{missing}/x.csv", "", "{ro}/x.csv", "{out}/ok.csv"]


def cli_cases():
    """(name, argv, stdin, allow_nan_files) for the command line."""
    cases = []

    def add(name, argv, stdin=None, nan_ok=()):
        cases.append((name, argv, stdin, tuple(nan_ok)))

    sample = ["sample", "--dim", "2", "--grid", "4", "--methods", "cnj", "-q", "--no-timing", "-o", "{out}/s.csv"]
    cube = sample + ["--domain", "cube"]
    lift = ["sample", "--dim", "2", "--grid", "4", "--methods", "cnj", "--domain", "cube", "-q", "--no-timing",
            "-o", "{out}/s.csv", "--lift", "plane:1,0.5"]
    field = ["field", "--dim", "2", "--input", "{in2}", "-o", "{out}/f.csv"]
    field_cube = field + ["--domain", "cube"]
    animate = ["animate", "--dim", "2", "--grid", "4", "--frames", "3", "-q", "--out", "{out}/a"]
    stream = ["sample", "--dim", "2", "--grid", "8", "--methods", "jitter,random", "--stream", "-q", "--no-timing",
              "-o", "{out}/s.csv"]
    stats = ["stats", "--input", "{in2}", "-q", "--no-timing", "-o", "{out}/s.csv"]

    for v in NUMBERS:
        for opt, base in [("--phase", sample), ("--phase", field), ("--phase", animate), ("--time", sample),
                          ("--time", field), ("--lift-ramp", lift), ("--lift-ramp", field + ["--lift", "plane:1,0.5"]),
                          ("--lift-ramp", field + ["--lift", "bump:1,0.3,0.5,0.5"]),
                          ("--cycles-per-spacing", sample), ("--cycles-per-spacing", animate), ("--frequency", field),
                          ("--step-scale", sample), ("--step-scale", animate), ("--boundary-spacings", cube),
                          ("--boundary-spacings", animate), ("--boundary-width", field_cube), ("--steer-k",
                          sample + ["--noise", "steerable", "--steer-dir", "1,0"]),
                          ("--steer-k", field + ["--noise", "steerable", "--steer-dir", "1,0"]),
                          ("--phase-step", animate), ("--rdf-max", sample + ["--rdf", "{out}/r.csv"]),
                          ("--max-memory", stream), ("--domain-side", stats), ("--rdf-max", stats + ["--rdf", "{out}/r.csv"]),
                          ("--periods", field[:2] + ["--diagnose", "--diagnose-points", "100", "-o", "{out}/f.csv"])]:
            add(f"{base[0]} {opt} {v!r}", base + [opt, v])
    for v in INTEGERS:
        for opt, base in [("--dim", sample), ("--grid", sample), ("-n", ["sample", "--methods", "random", "--dim", "2", "-q",
                          "-o", "{out}/s.csv"]), ("--steps", sample), ("--reproject-iters", sample),
                          ("--seed", sample), ("--threads", sample), ("--sets", sample), ("--slabs", stream),
                          ("--frames", animate), ("--grid", animate), ("--dim", animate), ("--drop-margin",
                          animate + ["--domain-mode", "drop"]), ("--dim", field), ("--rdf-bins", stats + ["--rdf", "{out}/r.csv"]),
                          ("--rdf-queries", stats + ["--rdf", "{out}/r.csv"]), ("--spectrum-frequency",
                          stats + ["--spectrum", "{out}/sp"]), ("--dim", stats), ("--seed", animate), ("--seed", field),
                          ("--pds-candidates", sample[:6] + ["pds", "-q", "-o", "{out}/s.csv"])]:
            if opt == "-n" and v in ("4294967296", "2147483648"):
                continue  # a valid count of billions of points: a long run, not a hostile one
            add(f"{base[0]} {opt} {v!r}", base + [opt, v], nan_ok=["frames.npy"] if opt == "--drop-margin" else ())
    for v in DIRECTIONS:
        add(f"sample --stretch {v!r}:2", sample + ["--domain", "cube", "--stretch", v + ":2"])
        add(f"field --stretch {v!r}:2", field + ["--stretch", v + ":2"])
        add(f"sample --steer-dir {v!r}", sample + ["--noise", "steerable", "--steer-dir", v])
        add(f"field --steer-dir {v!r}", field + ["--noise", "steerable", "--steer-dir", v])
        add(f"animate --steer-dir {v!r}", animate + ["--noise", "steerable", "--steer-dir", v])
    for s in ["1,0", "1,0:", ":2", "1,0:0", "1,0:-1", "1,0:nan", "1,0:1e-7", "1,0:1e7", "1,0:2:3", "1,0:1e308",
              "1,0:5e-324", "1e-300,0:2", "1e300,1e300:2", "1,0:2,3"]:
        add(f"field --stretch {s!r}", field + ["--stretch", s])
    for spec in ["", "plane", "plane:", "plane:1", "plane:1,2,3", "plane:nan,0", "plane:1e308,1e308", "plane:1e300,0",
                 "plane:1e-310,0", "plane:0,0", "bump:1", "bump:1,0", "bump:1,-1", "bump:1,1e-310", "bump:1e300,1e-300",
                 "bump:1,1e308", "bump:1e308,1", "bump:1,0.3,0.5", "bump:1,0.3,0.5,0.5,9", "npy:", "npy:{missing}",
                 "npy:{dir}", "npy:{in2}", "npy:{empty}", "npy:{npy1d}", "npy:{npy3d}", "npy:{npybig}", "npy:{npynan}",
                 "npy:{npyhuge}", "npy:{npyint}", "npy:{npy1x5}", "npy:/dev/null", "sphere:1,2", "plane:1,0;x",
                 "PLANE:1,0", "plane:1,0 "]:
        add(f"field --lift {spec!r}", field + ["--lift", spec])
        add(f"sample --lift {spec!r}", lift[:-1] + [spec])
    for spec in ["", "sphere", "sphere:", "sphere:0.5,0.5", "sphere:0.5,0.5,0", "sphere:0.5,0.5,-0.1",
                 "sphere:0.5,0.5,1e-310", "sphere:0.5,0.5,5e-324", "sphere:0.5,0.5,1e-300", "sphere:0.5,0.5,1e308",
                 "sphere:nan,0.5,0.1", "sphere:0.5,0.5,0.5,0.1", "sphere:0.5,0.1", "sphere:0.5,,0.1", "box:0.5,0.5,0.1",
                 "sphere:0.5,0.5,0.1,", "sphere:2,2,0.1", "sphere:0.5;0.5;0.1"]:
        add(f"field --obstacle {spec!r}", field_cube + ["--obstacle", spec])
        add(f"field ball --obstacle {spec!r}", field + ["--domain", "ball", "--obstacle", spec])
    add("field --obstacle 3D tiny", ["field", "--dim", "3", "--input", "{in3}", "-o", "{out}/f.csv", "--domain", "cube",
                                      "--obstacle", "sphere:0.5,0.5,0.5,1e-310"])
    add("field --obstacle 3D curl tiny", ["field", "--dim", "3", "--input", "{in3}", "-o", "{out}/f.csv", "--domain",
                                           "cube", "--field", "curl", "--bound", "ramp", "--obstacle", "sphere:0.5,0.5,0.5,1e-310"])
    add("field --obstacle at its centre", ["field", "--dim", "2", "--input", "{centre2}", "-o", "{out}/f.csv", "--domain",
                                            "cube", "--obstacle", "sphere:0.5,0.5,1e-310"])
    for v in ["", "none", "cube", "sphere", "torus", "ball"]:
        add(f"sample --on {v!r} simplex", sample + ["--dim", "3", "--on", v, "--noise", "simplex"])
    for v in ["", "x", "cnj,cnj", "cnj,", ",", "pds,,sobol", "CNJ", "cnj jitter"]:
        add(f"sample --methods {v!r}", sample[:6] + [v, "-q", "-o", "{out}/s.csv"])
    for domain in ["ball", "cube"]:
        for d in ["2", "5", "8"]:
            add(f"sample {domain} {d}D grid 2", ["sample", "--dim", d, "--grid", "2", "--methods", "cnj", "--domain", domain,
                                                 "-q", "-o", "{out}/s.csv"])
            add(f"animate {domain} {d}D grid 2", ["animate", "--dim", d, "--grid", "2", "--frames", "2", "--domain", domain,
                                                  "-q", "--out", "{out}/a"], nan_ok=["frames.npy"])
    add("animate drop ball", animate + ["--domain", "ball", "--domain-mode", "drop"], nan_ok=["frames.npy"])
    for path in PATHS_IN:
        add(f"field --input {path!r}", ["field", "--dim", "2", "--input", path, "-o", "{out}/f.csv"])
        add(f"stats --input {path!r}", ["stats", "--input", path, "-q", "-o", "{out}/s.csv"])
    for path in PATHS_OUT:
        add(f"sample -o {path!r}", sample[:-1] + [path])
        add(f"field -o {path!r}", field[:-1] + [path])
        add(f"animate --out {path!r}", animate[:-1] + [path])
        add(f"sample --points {path!r}", sample + ["--points", path])
        add(f"sample --json {path!r}", sample + ["--json", path])
        add(f"stream --points {path!r}", stream + ["--points", path])
    small = {"table2": ["--width", "8", "--height", "8"], "figure6": ["--width", "8"],
             "figure7": ["--width", "8", "--rk4-steps", "2"],
             "figure9": ["--grid", "4", "--image", "16", "--rk4-steps", "2", "--segments", "2"],
             "figure10": ["--grid", "4", "--image", "16", "--rk4-steps", "2", "--segments", "2"],
             "figure8": ["--frames", "2", "--grid-2d", "2", "--grid-3d", "2"],
             "table1": ["--dims", "3", "--realizations", "1"],
             "cnj-study": ["--dims", "3", "--realizations", "1", "--noises", "simplex", "--cycles-per-spacing", "0.2",
                           "--step-scales", "0.5", "--steps", "1"],
             "integration": ["--dims", "3", "--realizations", "2", "--max-points", "64", "--methods", "cnj"],
             "constructions": ["--divergence-points", "100", "--speed-points", "100", "--trace-starts", "1",
                               "--escape-starts", "1"]}
    for sub in ["table1", "table2", "cnj-study", "integration", "figure6", "figure7", "figure8", "figure9", "figure10",
                "constructions"]:
        for path in ["{dir}/x/..", "/proc/version", "", "{ro}/sub"]:
            add(f"reproduce {sub} --out {path!r}", ["reproduce", sub, "--out", path, "-q"] + small[sub])
    for sub, opts in [("table2", ["--frequency", "--field-magnitude", "--width", "--samples"]),
                      ("figure6", ["--width", "--trace-time", "--frequency"]),
                      ("figure7", ["--width", "--trace-time", "--frequency", "--boundary-width", "--rings", "--bins"]),
                      ("figure9", ["--lift-ramp", "--trace-time", "--frequency", "--grid", "--segments", "--slope"]),
                      ("figure10", ["--trace-time", "--slope"]), ("figure8", ["--phase-step", "--frames"])]:
        for opt in opts:
            for v in ["0", "-1", "nan", "inf", "1e-310", "1e308", "", "1,2,3", "18446744073709551616"]:
                argv = ["reproduce", sub, "--out", "{out}/r", "-q"] + small[sub]
                # the base's own value of the option is replaced
                if opt in argv:
                    i = argv.index(opt)
                    del argv[i:i + 2]
                add(f"reproduce {sub} {opt} {v!r}", argv + [opt, v])
    # The reproductions' list and range options.
    for sub, opt, values in [
            ("table1", "--dims", ["", "2", "8", "3-", "-3", "7-3", "3,3", "3-7-9", "x", "1e308", "3,,4"]),
            ("cnj-study", "--dims", ["2", "8", "7-3", "3,3", ""]),
            ("cnj-study", "--noises", ["", "x", "steerable", "simplex,simplex", "simplex,"]),
            ("cnj-study", "--cycles-per-spacing", ["0", "nan", "1e308", "-1", "1e-310", ""]),
            ("cnj-study", "--step-scales", ["0", "nan", "1e308", "-1", ""]),
            ("cnj-study", "--steps", ["0", "-1", "2000000", ""]),
            ("cnj-study", "--lattice", ["", "x", "paper"]),
            ("integration", "--dims", ["2", "8", "7-3", ""]),
            ("integration", "--methods", ["", "x", "cnj,cnj", "pds,"]),
            ("integration", "--max-points", ["0", "63", "16777217", "-1", ""]),
            ("integration", "--realizations", ["1", "0", "100001"]),
            ("table2", "--setting", ["", "x"]), ("table2", "--samples", ["0", "2", "81"]),
            ("table2", "--second-width", ["1", "20001", "-1"]), ("table2", "--height", ["1", "20001"]),
            ("figure8", "--grid-2d", ["1", "4097", "-1"]), ("figure8", "--grid-3d", ["1", "257"]),
            ("figure8", "--lattice-3d", ["", "x"]), ("figure8", "--drop-margin", ["-1", "1001"]),
            ("figure9", "--image", ["0", "-1", "100000000"]), ("figure9", "--rk4-steps", ["0", "3", "-1"]),
            ("figure9", "--segments", ["0", "64", "-1"]), ("figure10", "--grid", ["0", "1", "100000"]),
            ("figure6", "--noise", ["", "steerable", "x"]), ("figure7", "--rk4-steps", ["0", "-1"]),
            ("constructions", "--frequency", ["0", "nan", "1e308"]), ("constructions", "--trace-time", ["0", "1e-13", "101"]),
            ("constructions", "--divergence-points", ["99", "100000001"]), ("constructions", "--escape-starts", ["0"])]:
        for v in values:
            argv = ["reproduce", sub, "--out", "{out}/r", "-q"] + small[sub]
            if opt in argv:
                i = argv.index(opt)
                del argv[i:i + 2]
            add(f"reproduce {sub} {opt} {v!r}", argv + [opt, v])
    for v in ["1e-300,1e-300", "1e300,1e300", "0,0", "nan,1", "1", "1,2,3"]:
        add(f"reproduce figure9 --slope {v!r}", ["reproduce", "figure9", "--out", "{out}/r", "-q"] + small["figure9"] +
            ["--slope", v])
    # Names and combinations of the newer options: curl noise, bitangent (simplex in 3D), steering, phase, time,
    # stretch, lift, obstacles, bounds, the torus and the sphere, each where it applies and where it does not.
    names = ["", "x", "simplex", "turning-bands", "quintic-gradient", "simplex-separate", "steerable", "curl", "dfvn",
             "none", "newton", "gauss-newton", "euler", "rk4", "eq13", "ramp", "torus", "cube", "ball", "free", "drop",
             "conformant", "circular", "constant", "bcc", "cubic", "SIMPLEX", "simplex,curl"]
    for v in names:
        for opt in ["--noise", "--field", "--reproject", "--integrator", "--domain", "--bound", "--domain-mode"]:
            add(f"sample {opt} {v!r}", sample + ["--dim", "3", opt, v])
        for opt in ["--noise", "--field", "--domain", "--bound"]:
            add(f"field {opt} {v!r}", ["field", "--dim", "3", "--input", "{in3}", "-o", "{out}/f.csv", opt, v])
        for opt in ["--noise", "--domain", "--bound", "--domain-mode", "--lattice"]:
            add(f"animate {opt} {v!r}", animate + [opt, v], nan_ok=["frames.npy"])
        add(f"sample --steer-field {v!r}", sample + ["--noise", "steerable", "--steer-field", v])
    field3 = ["field", "--dim", "3", "--input", "{in3}", "-o", "{out}/f.csv"]
    combos = [
        sample + ["--dim", "4", "--field", "curl"], sample + ["--field", "curl", "--domain", "cube"],
        sample + ["--field", "curl", "--domain-mode", "drop"], sample + ["--field", "curl", "--reproject", "newton"],
        sample + ["--dim", "3", "--field", "curl", "--on", "sphere"], sample + ["--dim", "3", "--on", "sphere", "--domain", "cube"],
        sample + ["--dim", "3", "--on", "sphere", "--bound", "ramp"], sample + ["--dim", "2", "--on", "sphere"],
        sample + ["--dim", "3", "--on", "sphere", "--noise", "steerable", "--steer-dir", "1,0,0"],
        sample + ["--dim", "3", "--on", "sphere", "--stretch", "1,0,0:2"], sample + ["--dim", "3", "--on", "sphere", "--time", "1"],
        sample + ["--dim", "3", "--on", "sphere", "--phase", "1e300"], sample + ["--dim", "8", "--time", "1"],
        sample + ["--stretch", "1,0:2"], sample + ["--domain", "cube", "--stretch", "1,0:2", "--time", "0.5"],
        sample + ["--domain", "cube", "--lift", "plane:1,0", "--time", "0.5"], sample + ["--dim", "3", "--lift", "plane:1,0"],
        sample + ["--noise", "steerable"], sample + ["--noise", "steerable", "--steer-dir", "1,0", "--steer-field", "circular"],
        sample + ["--noise", "steerable", "--steer-field", "circular"], sample + ["--dim", "5", "--noise", "steerable",
        "--steer-field", "circular"], sample + ["--dim", "4", "--noise", "steerable", "--steer-dir", "1,0,0,0", "--steer-k",
        "0.99999"], sample + ["--noise", "steerable", "--steer-dir", "1,0", "--stretch", "1,0:2"],
        sample + ["--steer-dir", "1,0"], sample + ["--steer-k", "0.5"], sample + ["--domain", "torus", "--noise", "simplex"],
        sample + ["--domain", "torus", "--lift", "plane:1,0"], sample + ["--domain", "torus", "--bound", "ramp"],
        sample + ["--domain", "ball", "--boundary-spacings", "0.5", "--bound", "ramp", "--noise", "simplex"],
        sample + ["--domain", "ball", "--rdf", "{out}/r.csv"], sample + ["--domain", "ball", "--periodic"],
        sample + ["--domain", "ball", "--stream"], sample + ["--methods", "pds", "--stream"],
        sample + ["--methods", "cnj", "--stream", "--slabs", "3"], sample + ["--methods", "cnj", "--stream", "--sets", "2"],
        sample + ["--methods", "cnj", "--stream", "--domain-mode", "drop", "--points", "-", "--format", "npy"],
        sample + ["--methods", "cnj", "--stream", "--periodic", "--rdf", "{out}/r.csv", "--rdf-max", "1e-300"],
        sample + ["--methods", "cnj", "--stream", "--max-memory", "1e-9"], sample + ["--lift-ramp", "1"],
        sample + ["--phase", "1e300", "--time", "1e300"], sample + ["--phase", "-1e308", "--domain", "cube"],
        sample + ["--time", "1e15"], sample + ["--time", "-1e16"], sample + ["--cycles-per-spacing", "1e15", "--grid", "2"],
        field + ["--domain", "torus", "--stretch", "1,0:2"], field + ["--domain", "torus", "--noise", "simplex"],
        field + ["--domain", "torus", "--obstacle", "sphere:0.5,0.5,0.1"], field + ["--obstacle", "sphere:0.5,0.5,0.1"],
        field + ["--domain", "cube", "--obstacle", "sphere:0.5,0.5,0.1", "--obstacle", "sphere:0.5,0.5,0.1"],
        field + ["--domain", "cube", "--obstacle", "sphere:0.3,0.3,0.05", "--obstacle", "sphere:0.7,0.7,0.05"],
        field + ["--domain", "ball", "--obstacle", "sphere:0.5,0.5,0.3"], field + ["--domain", "cube", "--boundary-width",
        "1e-300", "--obstacle", "sphere:0.5,0.5,0.1"], field + ["--domain", "cube", "--field", "curl"],
        field + ["--domain", "cube", "--field", "curl", "--bound", "ramp", "--obstacle", "sphere:0.5,0.5,1e-300"],
        field3 + ["--domain", "ball", "--field", "curl", "--bound", "ramp", "--obstacle", "sphere:0.5,0.5,0.5,0.1"],
        field3 + ["--field", "curl", "--domain", "torus"], field3 + ["--field", "curl", "--time", "1"],
        field3 + ["--field", "curl", "--stretch", "1e-300,0,0:1e6"], field3 + ["--field", "curl", "--phase", "1e308"],
        field3 + ["--noise", "simplex", "--phase", "3.14159", "--time", "-1e15"],
        field3 + ["--noise", "steerable", "--steer-field", "circular", "--steer-k", "1e-300"],
        field3 + ["--noise", "steerable", "--steer-dir", "0,0,1e-320"], field3 + ["--dim", "2"],
        ["field", "--dim", "8", "--input", "{in3}"], field + ["--time", "1", "--lift", "plane:1,0"],
        field + ["--lift", "bump:1e15,1", "--lift-ramp", "1e15"], field + ["--lift", "bump:-1e15,1,0.1,0.2"],
        field + ["--lift", "plane:0,0", "--lift-ramp", "1e15"], field + ["--frequency", "1e15", "--lift", "plane:1,1"],
        field + ["--diagnose"], field[:2] + ["--diagnose", "--diagnose-points", "10", "--lift", "plane:1,0", "-o", "{out}/d.csv"],
        field[:2] + ["--diagnose", "--diagnose-points", "10", "--obstacle", "sphere:0.5,0.5,0.1", "--domain", "cube",
                     "-o", "{out}/d.csv"],
        field[:2] + ["--diagnose", "--diagnose-points", "10", "--periods", "1e9", "--frequency", "1e-15", "-o", "{out}/d.csv"],
        animate + ["--domain", "torus"], animate + ["--field", "curl"], animate + ["--lattice", "bcc", "--domain", "ball"],
        animate + ["--frames", "100000", "--grid", "1024"], animate + ["--domain-mode", "drop", "--drop-margin", "100"],
        animate + ["--phase", "1e308", "--phase-step", "6.283185307179586"], animate + ["--phase", "-1e308"],
        animate + ["--phase-step", "6.2832"], animate + ["--noise", "steerable", "--steer-field", "circular"],
        animate + ["--dim", "8", "--grid", "2", "--domain", "cube", "--frames", "2"],
        stats + ["--spectrum", "{out}/sp", "--dim", "2"], stats + ["--format", "bin"], stats + ["--format", "npy"],
        stats + ["--domain-side", "1e-300"], stats + ["--periodic", "--domain-side", "1e300"],
        stats + ["--rdf", "{out}/r.csv", "--rdf-max", "1e300"], stats + ["--discrepancy", "--periodic"],
        ["stats", "--input", "-", "--format", "csv", "-q", "-o", "{out}/s.csv"],
    ]
    for side in ["1e300", "1e100", "1e20", "1e-20", "1e-300"]:
        for extra in [["--periodic"], ["--rdf", "{out}/r.csv"], ["--periodic", "--rdf", "{out}/r.csv"], ["--discrepancy"],
                      ["--spectrum", "{out}/sp"]]:
            combos.append(stats + ["--domain-side", side] + extra)
    for argv in combos:
        add("combination " + " ".join(argv[:1] + argv[9:] if argv[0] == "sample" else argv), argv, nan_ok=["frames.npy"])
    # --stream at sizes that cannot fit in $TMPDIR, and its bad values
    add("stream 2^40 points", ["sample", "--dim", "2", "-n", "1099511627776", "--methods", "jitter", "--stream", "-q",
                               "-o", "{out}/s.csv"])
    add("stream 2^40 points 3D", ["sample", "--dim", "3", "-n", "1099511627776", "--methods", "random", "--stream", "-q",
                                  "-o", "{out}/s.csv"])
    if MPI:
        mpi = ["--dim", "2", "--grid", "8", "--methods", "jitter,random", "-q", "--no-timing", "-o", "{out}/s.csv"]
        # MPI_Init costs about 0.6 s a run: a few values of each kind (its options are sample's, probed above)
        for v in ["0", "-1", "nan", "1e-310", "18446744073709551616", "", "abc", "\x1b[31m", "1.5"]:
            for opt in ["--dim", "--grid", "--slabs", "--seed", "--threads", "--rdf-bins"]:
                add(f"mpi {opt} {v!r}", ["@mpi"] + mpi + ([] if opt != "--rdf-bins" else ["--rdf", "{out}/r.csv"]) + [opt, v])
        for v in ["0", "-1", "nan", "inf", "1e-310", "1e308", "", "abc"]:
            for opt in ["--cycles-per-spacing", "--step-scale", "--max-memory", "--rdf-max"]:
                add(f"mpi {opt} {v!r}", ["@mpi"] + mpi + ["--methods", "cnj,jitter"] +
                    ([] if opt != "--rdf-max" else ["--rdf", "{out}/r.csv"]) + [opt, v])
        for path in PATHS_OUT:
            add(f"mpi -o {path!r}", ["@mpi"] + mpi[:-1] + [path])
            add(f"mpi --points {path!r}", ["@mpi"] + mpi + ["--points", path])
    return cases


def make_files(root):
    import numpy as np
    files = {"out": os.path.join(root, "out"), "dir": os.path.join(root, "a_dir"), "ro": os.path.join(root, "ro"),
             "missing": os.path.join(root, "missing.csv")}
    os.makedirs(files["dir"])
    os.makedirs(files["ro"])
    os.chmod(files["ro"], 0o555)
    for name, text in [("in2", "0.1,0.2\n0.6,0.7\n0.3,0.9\n"), ("in3", "0.1,0.2,0.3\n0.6,0.7,0.5\n"), ("empty", ""),
                       ("bad", "0.1,x\n"), ("nan", "0.1,nan\n0.2,0.3\n"), ("centre2", "0.5,0.5\n0.25,0.5\n")]:
        files[name] = os.path.join(root, name + ".csv")
        with open(files[name], "w") as f:
            f.write(text)
    arrays = {"npy1d": np.zeros(5), "npy3d": np.zeros((2, 2, 2)), "npybig": np.full((3, 3), 1e308),
              "npynan": np.array([[0.0, np.nan], [1.0, 2.0]]), "npyhuge": np.array([[0.0, 1e300], [-1e300, 0.0]]),
              "npyint": np.arange(4).reshape(2, 2), "npy1x5": np.zeros((1, 5))}
    for name, array in arrays.items():
        files[name] = os.path.join(root, name + ".npy")
        np.save(files[name], array)
    return files


# NaN or Inf as a number written: delimited as CSV, JSON and tables delimit numbers (not "(NaN where ...)" prose)
NON_FINITE = re.compile(rb"(^|[\s,=:|\[])[-+]?(nan|inf(inity)?)(?=[\s,|\]]|$)", re.I | re.M)
# ''x'' (an empty text quoted is '', and stays allowed)
QUOTED_TWICE = re.compile(r"''[^\s,.;:)\]]|[^\s(\[=]''")
INTERNALS = re.compile(r"std::|basic_string|max_size|bad_alloc|what\(\)|terminate called|vector::")


def bad_file(path, nan_ok):
    """Why a written file breaks the promises, or None."""
    name = os.path.basename(path)
    if name.endswith(".npy"):
        if name in nan_ok:
            return None
        import numpy as np
        try:
            a = np.load(path)
        except Exception as e:  # a file we wrote must load
            return f"{name} does not load: {e}"
        if a.dtype.kind == "f" and not np.isfinite(a).all():
            return f"{name} holds NaN or Inf"
        return None
    if name.endswith((".png", ".bin")):
        return None
    with open(path, "rb") as f:
        data = f.read()
    # the markdown and CSV files: 'nan' or 'inf' as a word (not inside 'infinite', 'information')
    m = NON_FINITE.search(data)
    if m and name not in nan_ok:
        line = data[max(0, m.start() - 60):m.end() + 20].decode(errors="replace").replace("\n", " ")
        return f"{name} holds NaN or Inf: ...{line}..."
    return None


def run_cli(case, files, root, index):
    name, argv, stdin, nan_ok = case
    work = os.path.join(root, f"case{index}")
    out = os.path.join(work, "out")
    tmp = os.path.join(work, "tmp")
    os.makedirs(out)
    os.makedirs(tmp)
    local = dict(files, out=out)
    args = [a.format(**local) for a in argv]
    program = BIN
    if args and args[0] == "@mpi":
        program, args = MPI, args[1:]
    env = dict(os.environ, TMPDIR=tmp, OMP_NUM_THREADS="1")
    started = time.monotonic()
    try:
        p = subprocess.run([program] + args, input=(stdin or "").encode(), capture_output=True, timeout=TIMEOUT,
                           cwd=work, env=env)
    except subprocess.TimeoutExpired:
        return [f"{name}: no end within {TIMEOUT} s"]
    SECONDS.append((time.monotonic() - started, name))
    problems = []
    err = p.stderr.decode(errors="replace")
    prog = os.path.basename(program)
    written = [os.path.join(d, f) for d, _, fs in os.walk(out) for f in fs]
    if p.returncode < 0 or p.returncode not in (0, 1, 2):
        problems.append(f"exit {p.returncode}: {err[:300]!r}")
    elif p.returncode != 0:
        lines = err.split("\n")
        if p.stdout:
            problems.append(f"refused with {len(p.stdout)} bytes on stdout")
        if len(lines) != 2 or lines[1] != "" or not lines[0].startswith(prog + ": error: "):
            problems.append(f"refusal is not one error line: {err[:300]!r}")
        elif len(err) > 400 or re.search(r"[\x00-\x1f\x7f]", lines[0]):
            problems.append(f"error line too long or holds control bytes: {err[:300]!r}")
        if QUOTED_TWICE.search(err):
            problems.append(f"text quoted twice: {err.strip()[:300]}")
        if re.search(r"\b0\.000000\b", err):
            problems.append(f"a number printed as 0.000000: {err.strip()[:300]}")
        if INTERNALS.search(err):
            problems.append(f"C++ internals in the message: {err.strip()[:300]}")
        if written:
            problems.append(f"refused but wrote {', '.join(os.path.relpath(w, out) for w in written)}")
    else:
        for line in err.splitlines():
            if not line.startswith(prog + ": ") or line.startswith(prog + ": error"):
                problems.append(f"accepted with stderr {line[:200]!r}")
                break
        m = NON_FINITE.search(p.stdout)
        if m:
            problems.append(f"stdout holds NaN or Inf: {p.stdout[max(0, m.start() - 60):m.end() + 20]!r}")
        for w in written:
            why = bad_file(w, nan_ok)
            if why:
                problems.append(why)
    left = os.listdir(tmp)
    if left:
        problems.append(f"left in $TMPDIR: {left[:3]}")
    if not problems:
        shutil.rmtree(work, ignore_errors=True)
    return [f"{name}: {p}" for p in problems]


# ---- Python ----------------------------------------------------------------------------------------------
PY_VALUES = [0, -1, -0.0, float("nan"), float("inf"), -float("inf"), 1e-310, 5e-324, 1e308, -1e308, 2**64, 2**63,
             -2**63 - 1, 10**30, "", "x", None, [1, 2], "1,0", True, object()]


def python_cases(files):
    import numpy as np
    pts2 = np.array([[0.1, 0.2], [0.6, 0.7], [0.3, 0.9]])
    cases = []

    def add(name, fn, kwargs, keyword):
        cases.append((name, fn, kwargs, keyword))

    import dfvn
    for kw in ["seed", "frequency", "phase", "boundary_width", "threads", "time", "lift_ramp", "steer_k", "noise",
               "domain", "bound", "field", "obstacles", "stretch", "lift", "steer"]:
        for v in PY_VALUES:
            base = {"domain": "cube"} if kw in ("boundary_width", "bound", "obstacles") else {}
            if kw == "lift_ramp":
                base = {"lift": "plane:1,0.5"}
            if kw in ("steer_k", "steer"):
                base = {"noise": "steerable"} if kw == "steer" else {"noise": "steerable", "steer": (1.0, 0.0)}
            add(f"field({kw}={v!r})", dfvn.field, dict(base, points=pts2, **{kw: v}), kw)
            if kw in ("seed", "frequency", "phase", "time", "lift_ramp", "stretch", "obstacles", "boundary_width"):
                add(f"trace({kw}={v!r})", dfvn.trace, dict(base, points=pts2, t=0.1, **{kw: v}), kw)
    for v in PY_VALUES:
        add(f"trace(t={v!r})", dfvn.trace, dict(points=pts2, t=v), "t")
        add(f"trace(steps={v!r})", dfvn.trace, dict(points=pts2, t=0.1, steps=v), "steps")
    for spec in ["sphere:0.5,0.5,1e-310", "sphere:0.5,0.5,5e-324", "sphere:0.5,0.5,1e-300", "sphere:0.5,0.5,0",
                 "sphere:0.5,0.5", "sphere:0.5,0.5,0.1,"]:
        add(f"field(obstacles=[{spec!r}]) at its centre", dfvn.field,
            dict(points=np.array([[0.5, 0.5], [0.2, 0.5]]), domain="cube", obstacles=[spec]), "obstacles")
    for d in [(1e-300, 0.0), (1e-300, 1e-300), (1e300, 1e300), (5e-324, 0.0), (0.0, 0.0), (1.0,), (1.0, 0.0, 0.0)]:
        add(f"field(stretch=({d}, 2))", dfvn.field, dict(points=pts2, stretch=(d, 2.0)), "stretch")
        add(f"field(steer={d})", dfvn.field, dict(points=pts2, noise="steerable", steer=d), "steer")
    for spec in ["plane:1,0", "bump:1,1e-310", "bump:1e300,1e-300", "plane:1e308,0", "npy:" + files["npyhuge"],
                 "npy:" + files["missing"], "npy:" + files["npy1d"]]:
        for ramp in [0.0, 1.0, 1e20, 1e308]:
            add(f"field(lift={spec!r}, lift_ramp={ramp})", dfvn.field, dict(points=pts2, lift=spec, lift_ramp=ramp), "lift")
    for kw in ["grid", "n", "seed", "cycles_per_spacing", "step_scale", "steps", "phase", "time", "stretch", "domain",
               "bound", "noise", "max_memory_gib", "threads", "radius", "ncandidates", "protocol"]:
        for v in PY_VALUES:
            args = {"grid": 4} if kw not in ("grid", "n") else {}
            method = "pds" if kw in ("radius", "ncandidates") else "cnj"
            add(f"sample({method!r}, {kw}={v!r})", dfvn.sample, dict(args, method=method, dim=2, **{kw: v}), kw)
    for d in [2, 5, 8]:
        add(f"sample('cnj', {d}, grid=2, domain='ball')", dfvn.sample, dict(method="cnj", dim=d, grid=2, domain="ball"),
            "grid")
    for kw in ["domain_side", "knn", "threads", "periodic"]:
        for v in PY_VALUES:
            add(f"nn_stats({kw}={v!r})", dfvn.nn_stats, dict(points=pts2, **{kw: v}), kw)
    for side in [1e300, 1e100, 1e-300]:
        # refused, if at all, for the points: their distances underflow at the domain's scale
        add(f"nn_stats(domain_side={side}, periodic=True)", dfvn.nn_stats, dict(points=pts2, domain_side=side, periodic=True),
            "points")
        add(f"rdf(domain_side={side}, periodic=True)", dfvn.rdf, dict(points=pts2, domain_side=side, periodic=True),
            "domain_side")
    for kw in ["domain_side", "r_max", "bins", "max_queries", "seed"]:
        for v in PY_VALUES:
            add(f"rdf({kw}={v!r})", dfvn.rdf, dict(points=pts2, **{kw: v}), kw)
    # The engines (python/dfvn/qmc.py): constructor keywords and their draws.
    for kw in ["cycles_per_spacing", "step_scale", "phase", "time", "steps", "noise", "domain", "stretch", "seed"]:
        for v in PY_VALUES:
            add(f"CNJ({kw}={v!r}).random(grid=4)", lambda **k: dfvn.CNJ(2, **k).random(grid=4), {kw: v}, kw)
    for v in PY_VALUES:
        add(f"Sobol(2).random({v!r})", lambda n: dfvn.Sobol(2, seed=1).random(n), dict(n=v), "n")
        add(f"Sobol(2).random_base2({v!r})", lambda m: dfvn.Sobol(2, seed=1).random_base2(m), dict(m=v), "m")
        add(f"Random(2).fast_forward({v!r})", lambda n: dfvn.Random(2, seed=1).fast_forward(n), dict(n=v), "n")
        add(f"Jitter({v!r})", lambda d: dfvn.Jitter(d, seed=1).random(grid=3), dict(d=v), "d")
        add(f"discrepancy(method={v!r})", lambda method: dfvn.discrepancy(pts2, method=method), dict(method=v), "method")
    for points in [np.zeros((0, 2)), np.zeros((3, 1)), np.zeros((3, 9)), np.full((2, 2), np.nan), "x", None,
                   np.zeros((2, 2, 2)), [[1e308, 1e308]], np.zeros((3, 2), dtype=np.int64)]:
        add(f"field(points={getattr(points, 'shape', points)!r})", dfvn.field, dict(points=points), "points")
        add(f"nn_stats(points={getattr(points, 'shape', points)!r})", dfvn.nn_stats, dict(points=points), "points")
    return cases


def finite(result):
    import numpy as np
    items = result if isinstance(result, (tuple, list)) else [result]
    for item in items:
        if isinstance(item, dict):
            if not finite(list(item.values())):
                return False
        elif isinstance(item, np.ndarray) and item.dtype.kind == "f":
            if not np.isfinite(item).all():
                return False
        elif isinstance(item, float) and not math.isfinite(item):
            return False
    return True


def run_python(case):
    import warnings
    name, fn, kwargs, keyword = case
    args = dict(kwargs)
    positional = [args.pop(k) for k in ("method", "dim", "points", "t") if k in args]
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            result = fn(*positional, **args)
    except (ValueError, TypeError, MemoryError) as e:
        text = str(e)
        problems = []
        if "\n" in text or not text:
            problems.append(f"{type(e).__name__} of {text.count(chr(10)) + 1} lines: {text[:200]!r}")
        elif keyword not in text and keyword not in ("t",):
            problems.append(f"{type(e).__name__} does not name {keyword!r}: {text[:200]!r}")
        if QUOTED_TWICE.search(text):
            problems.append(f"text quoted twice: {text[:200]!r}")
        if INTERNALS.search(text) or "incompatible function arguments" in text:
            problems.append(f"internals in the message: {text[:200]!r}")
        return [f"{name}: {p}" for p in problems]
    except Exception as e:  # any other exception type is a defect
        return [f"{name}: raised {type(e).__name__}: {str(e)[:200]!r}"]
    if not finite(result):
        return [f"{name}: returned NaN or Inf"]
    return []


def main():
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    listing, verbose = "--list" in sys.argv, "--verbose" in sys.argv
    wanted = args[0] if args else ""
    if not BIN:
        sys.exit("set DFVN_SAMPLE to the dfvn-sample binary")
    root = tempfile.mkdtemp(prefix="dfvn-probe.")
    failures, total = [], 0
    try:
        files = make_files(root)
        cases = [c for c in cli_cases() if wanted in c[0]]
        if listing:
            for c in cases:
                print(c[0])
        else:
            # more workers than cores: MPI_Init and the short runs wait more than they compute
            with concurrent.futures.ThreadPoolExecutor(max_workers=2 * max(2, os.cpu_count() or 2)) as pool:
                for problems in pool.map(lambda ic: run_cli(ic[1], files, root, ic[0]), enumerate(cases)):
                    failures += problems
        total += len(cases)
        try:
            import dfvn  # noqa: F401
            have_python = True
        except ImportError:
            have_python = False
        if have_python:
            pycases = [c for c in python_cases(files) if wanted in c[0]]
            total += len(pycases)
            for c in pycases:
                if listing:
                    print(c[0])
                else:
                    failures += run_python(c)
        for f in failures:
            print("FAIL:", f)
        if verbose:
            for seconds, name in sorted(SECONDS, reverse=True)[:15]:
                print(f"{seconds:6.2f} s  {name}")
        if not listing:
            print(f"probe_hostile: {total} cases ({'with' if have_python else 'without'} Python, "
                  f"{'with' if MPI else 'without'} MPI), {len(failures)} problems")
    finally:
        os.chmod(os.path.join(root, "ro"), 0o755) if os.path.isdir(os.path.join(root, "ro")) else None
        if not failures or not verbose:
            shutil.rmtree(root, ignore_errors=True)
        else:
            print("cases kept in", root)
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
