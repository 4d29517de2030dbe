#!/usr/bin/env python3
"""One vocabulary: every option name means one thing across subcommands.

Reads `dfvn-sample --help-all`, finds every option name that more than one subcommand takes and
checks that each of its descriptions states the meaning and unit the table SHARED gives (phrases
compared lowercased, whitespace collapsed). A name newly shared without an entry here fails, as does
a description that departs from its entry. Also: --help-all holds every subcommand, reproduce's
included; `reproduce --help` lists its subcommands; the usage and every --methods description list
every method of src/sampling/method.hpp's kAllMethods; the old spellings are refused with a line
naming the new one.

    DFVN_SAMPLE=build/dfvn-sample DFVN_SOURCE_DIR=. tests/cli/test_cli_vocabulary.py
"""
import os
import re
import subprocess
import sys
import tempfile

BIN = os.environ["DFVN_SAMPLE"]
SOURCE = os.environ.get("DFVN_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))

# name -> the phrases every description of it must hold (docs/CLI.md's table "Options that mean the same
# everywhere" says the same in words). Names taken by one subcommand today but meant to be shared are
# listed too, so that they keep one meaning when a second subcommand takes them.
SHARED = {
    "--help": ["print this help message"],
    "--help-all": ["print the help of every subcommand"],
    "--dim": ["dimension n"],
    "--seed": ["seed of every random choice; same seed, same output"],
    "--threads": ["worker threads: 0 = all cores", "output never depends on it"],
    "--progress": ["progress on stderr"],
    "--quiet": ["no progress on stderr"],
    "--output": ["main output:", "('-' = standard output)"],
    "--out": ["output directory"],
    "--input": ["point file to read"],
    "--format": ["point file format", "csv", "npy", "dat"],
    "--json": ["also write the", "as json", "('-' = standard output)"],
    "--summary": ["also write the summary over", "the mean, sd and standard error", "('-' = standard output)"],
    "--no-timing": ["leave the seconds column", "empty"],
    "--knn": ["kd-tree backend: nanoflann or flann"],
    "--periodic": ["on the torus", "minimum-image"],
    "--realizations": ["realizations r", "independently seeded repeats, seeds s..s+r-1"],
    "--dims": ["dimensions: a range or list within 3..7"],
    "--methods": ["comma list of methods"],
    "--noise": ["noise basis"],
    "--field": ["divergence-free field: dfvn", "curl (bridson et al. 2007's curl noise, 2d and 3d"],
    "--phase": ["noise phase alpha in radians", "0 is the field without a phase, bit for bit"],
    "--stretch": ["stretch the noise along a direction, u:s", "f_i(a x) with a = i + (s - 1) u u^t"],
    "--time": ["time as an extra noise dimension", "in the units of x"],
    "--lift": ["lift the noise onto a surface z = h(x)", "plane:sx,sy", "bump:h,r[,cx,cy[,sx,sy]]"],
    "--lift-ramp": ["the vertical ramp of the paper's figure 9"],
    "--steer-dir": ["with --noise steerable: the direction u the noise is elongated along"],
    "--steer-field": ["with --noise steerable: constant (--steer-dir) or circular"],
    "--steer-quality": ["with --noise steerable: the quality q in 0..n"],
    "--steer-image": ["with --noise steerable in 2d: steer along an image's direction field"],
    "--steer-k": ["with --noise steerable: the metric's eigenvalue k along u, in (0, 1]"],
    "--octaves": ["octaves k of the noise (bridson et al. 2007, section 2.2)", "1 is the field without"],
    "--octave-gain": ["with --octaves: the velocity ratio g from one octave to the next", "kolmogorov's 2^(-1/3)"],
    "--amplitude": ["modulate the potential by a(x)", "constant:a, height:z0,z1", "obstacles:d"],
    "--viscous": ["no-slip solids (bridson section 2.4)"],
    "--body": ["a moving rigid sphere", "sphere:cx,cy,cz,r,vx,vy,vz,wx,wy,wz"],
    "--vortex": ["particle:cx,cy,cz,wx,wy,wz,r", "ring:cx,cy,cz,nx,ny,nz,rr,w,r"],
    "--rotation": ["how --noise simplex's gradients turn with --phase in 3d", "two-vector", "fast", "well-behaved"],
    "--frequency": ["cycles per unit length"],
    "--cycles-per-spacing": ["cycles per lattice spacing"],
    "--steps": ["cnj integration steps m"],
    "--domain": ["torus ([0,1)^n", "cube ([0,1]^n", "ball (its inscribed ball"],
    "--bound": ["eq13 (the paper's eq. 13) or ramp (bridson et al. 2007"],
    "--boundary-width": ["transition width in length units"],
    "--boundary-spacings": ["transition width in lattice spacings"],
    "--rdf": ["radial distribution function"],
    "--rdf-max": ["largest r of the rdf"],
    "--rdf-bins": ["rdf bins"],
    "--rdf-queries": ["rdf query points"],
    "--domain-side": ["[0, s]^n"],
    "--grid": ["lattice points per axis k"],
    "--domain-mode": ["conformant: cnj along the field bounded by the domain", "drop: the", "free field, points that leave are dropped"],
    "--step-scale": ["cnj trace time t = c * dbar(n) * lattice spacing"],
    "--lattice": ["start lattice"],
    "--frames": ["frames f, frame 0 included"],
    "--phase-step": ["phase step da in radians per frame, in [2^-30, 2 pi]"],
    "--width": ["image width in pixels"],
    "--trace-time": ["trace time t of every", "rms |c| = 1: unit lengths"],
    "--rk4-steps": ["rk4 steps per trace, each followed by gauss-newton reprojection"],
    "--slope": ["slope sx,sy of the plane h = sx x + sy y"],
    "--segments": ["trace points drawn and written after the start"],
    "--image": ["side of the png in pixels"],
    "--drop-margin": ["drop mode: how far the start set reaches beyond the domain, in whole lattice spacings"],
}
# Names whose meaning moved: given, each is refused with a line naming the option to use instead.
REFUSED = [
    (["--dim", "3", "--grid", "4", "--frequency", "0.2"], "--cycles-per-spacing"),
    (["sample", "--dim", "3", "--frequency"], "--cycles-per-spacing"),
    (["--dim", "3", "--grid", "4", "--domain", "cube", "--boundary-width", "1"], "--boundary-spacings"),
    (["reproduce", "cnj-study", "--dims", "3", "--seeds", "2"], "--realizations"),
    (["reproduce", "cnj-study", "--dims", "3", "--frequencies", "0.2,0.5"], "--cycles-per-spacing"),
    (["-d", "2", "-n", "64", "-o", "pts.dat"], "--points"),
    (["-d", "2", "-n", "64", "--stats", "pts.NPY"], "--points"),
]

failures = []


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        failures.append(what)


def run(*args, cwd=None):
    return subprocess.run([BIN, *args], capture_output=True, text=True, cwd=cwd)


def normalise(text):
    return re.sub(r"\s+", " ", text).strip().lower()


def sections(help_all):
    """{'dfvn-sample sample': text, ...}: the subcommand sections of --help-all."""
    parts = re.split(r"^(dfvn-sample(?: [a-z0-9-]+)+):$", help_all, flags=re.M)
    return {parts[i]: parts[i + 1] for i in range(1, len(parts) - 1, 2)}


def options(section):
    """{long name: (value kind, description)} of one section's option list (the help's layout: in
    --help-all a subcommand's option line starts at column 4 with its names, "-d, --dim", then its
    value's label, "N (2..8, default 7)" or "{a,b} (default a)"; the description follows on lines
    indented by 8). The kind is the label's name (N, FILE), CHOICE for a list of choices, FLAG for none."""
    found, current = {}, None
    for line in section.split("\n"):
        head = re.match(r"^    (-[-a-zA-Z0-9]+(?:, -[-a-zA-Z0-9]+)*)(?: (\S+))?", line)
        if head:
            current = [n for n in head.group(1).split(", ") if n.startswith("--")]
            label = head.group(2)
            kind = "FLAG" if label is None else "CHOICE" if label.startswith("{") else label.rstrip(".")
            for n in current:
                found[n] = (kind, "")
        elif current and line.startswith(" " * 8) and line.strip():
            for n in current:
                found[n] = (found[n][0], (found[n][1] + " " + line.strip()).strip())
        else:
            current = None
    return found


def kall_methods():
    text = open(os.path.join(SOURCE, "src", "sampling", "method.hpp")).read()
    body = re.search(r"kAllMethods\[\]\s*=\s*\{([^}]*)\}", text).group(1)
    return [name.replace("_", "-") for name in re.findall(r"Method::(\w+)", body)]


help_all = run("--help-all")
check(help_all.returncode == 0, "--help-all exits 0")
parts = sections(help_all.stdout)
expected = ["dfvn-sample " + s for s in ["sample", "field", "reproduce", "reproduce table1", "reproduce table2",
                                          "reproduce cnj-study", "reproduce integration", "reproduce figure8", "reproduce constructions", "reproduce figure6",
                                          "reproduce figure7", "reproduce figure9", "reproduce figure10", "reproduce bridson", "stats",
                                          "animate"]]
check(sorted(parts) == sorted(expected), f"--help-all has a section per subcommand: {sorted(parts)}")

per_section = {name: options(text) for name, text in parts.items()}
check(all(len(o) >= 5 or s == "dfvn-sample reproduce" for s, o in per_section.items()), "every section lists its options: "
      + ", ".join(f"{k} {len(v)}" for k, v in per_section.items()))


def takers_of(per_section):
    """{name: [(section, value type, description), ...]} over every section."""
    takers = {}
    for section, opts in per_section.items():
        for name, (kind, description) in opts.items():
            takers.setdefault(name, []).append((section, kind, description))
    return takers


def vocabulary_problems(per_section):
    """Each departure from SHARED, as a line: a shared name without an entry, a description without its
    entry's phrases, two value types under one name."""
    problems = []
    for name, uses in sorted(takers_of(per_section).items()):
        if len(uses) < 2:
            continue
        where = ", ".join(s.replace("dfvn-sample ", "") for s, _, _ in uses)
        if name not in SHARED:
            problems.append(f"{name} ({where}) is shared but has no entry in SHARED (and docs/CLI.md's table)")
            continue
        for section, kind, description in uses:
            missing = [p for p in SHARED[name] if p not in normalise(description)]
            if missing:
                problems.append(f"{name} in {section}: missing {missing} in {normalise(description)!r}")
        kinds = sorted({kind for _, kind, _ in uses})
        if len(kinds) != 1:
            problems.append(f"{name}: value types {kinds} across {where}")
    return problems


takers = takers_of(per_section)
shared = sorted(name for name, uses in takers.items() if len(uses) > 1)
check(len(shared) >= 15, f"{len(shared)} names are shared: {' '.join(shared)}")
problems = vocabulary_problems(per_section)
check(not problems, "every shared name states its one meaning and unit" + "".join("\n     " + p for p in problems))

# docs/CLI.md's table "Options that mean the same everywhere" has a row for every shared name (--help
# and --help-all aside).
source_dir = os.environ.get("DFVN_SOURCE_DIR", os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
reference = open(os.path.join(source_dir, "docs", "CLI.md"), encoding="utf-8").read()
start = reference.find("## Options that mean the same everywhere")
table = reference[start:reference.find("\n## ", start + 1)] if start >= 0 else ""
rows = [line for line in table.split("\n") if line.startswith("| `")]
for name in shared:
    if name not in ("--help", "--help-all"):  # the paragraph above the table describes them
        check(any(re.search(rf"`(-[a-zA-Z], )?{re.escape(name)}[` ,]", row.split("|")[1]) for row in rows),
              f"docs/CLI.md's table of shared options has a row for {name}")

# The check itself fails on the departures it is there for: a shared name's unit changed in one
# subcommand, a name newly shared without an entry, a second value type.
for what, mutate in [
    ("table2's --frequency per image width", lambda ps: ps["dfvn-sample reproduce table2"].__setitem__(
        "--frequency", ("F", "Noise frequency in cycles per image width"))),
    ("a new shared name without an entry", lambda ps: [ps[s].__setitem__("--brand-new", ("INT", "x"))
                                                       for s in ["dfvn-sample sample", "dfvn-sample stats"]]),
    ("--seed as a float in field", lambda ps: ps["dfvn-sample field"].__setitem__(
        "--seed", ("X", ps["dfvn-sample field"]["--seed"][1]))),
]:
    mutated = {s: dict(o) for s, o in per_section.items()}
    mutate(mutated)
    check(len(vocabulary_problems(mutated)) == 1, f"the check catches {what}: {vocabulary_problems(mutated)}")

# Every name that speaks of a frequency says in what unit.
for name, uses in takers.items():
    if "frequenc" in name or "cycles" in name:
        for section, _, description in uses:
            check("cycles per" in normalise(description), f"{name} in {section}: a frequency with its unit")

# Every method, from kAllMethods, in the usage, sample's description and every --methods.
methods = kall_methods()
check(len(methods) == 8, f"kAllMethods read from method.hpp: {methods}")
usage = run().stdout
check(all(m in usage for m in methods), "the usage lists every method")
for section, opts in per_section.items():
    if "--methods" in opts:
        listed = re.findall(r"[a-z][a-z-]*", opts["--methods"][1].split("methods, of", 1)[-1])
        check(all(m in listed for m in methods), f"{section} --methods lists every method")
check(all(m in parts["dfvn-sample sample"].split("Usage:")[0] for m in methods), "sample's description lists every method")

reproduce_help = run("reproduce", "--help").stdout
for sub in ["table1", "table2", "cnj-study", "integration"]:
    check(re.search(rf"^  {sub} ", reproduce_help, re.M) is not None and sub in reproduce_help.split("Subcommands:")[-1],
          f"reproduce --help lists {sub}")

# The refused spellings: one line, exit 2, naming the new option, and no output file.
with tempfile.TemporaryDirectory() as work:
    for args, new_name in REFUSED:
        r = run(*args, cwd=work)
        lines = r.stderr.strip().split("\n")
        check(r.returncode != 0 and len(lines) == 1 and new_name in lines[0] and "error" in lines[0],
              f"{' '.join(args)}: refused naming {new_name}: {r.stderr.strip()!r}")
    check(os.listdir(work) == [], f"no file written by a refused command: {os.listdir(work)}")
    # The refused names stay out of the help.
    for hidden in ["--seeds", "--frequencies"]:
        check(hidden not in per_section["dfvn-sample reproduce cnj-study"], f"cnj-study --help does not list {hidden}")
    for hidden in ["--frequency", "--boundary-width"]:
        check(hidden not in per_section["dfvn-sample sample"], f"sample --help does not list {hidden}")
    # -o, --output and --stats are one option: the statistics CSV.
    for spelling in ["-o", "--output", "--stats"]:
        r = run("-d", "2", "--grid", "4", "--methods", "jitter", "-q", "--no-timing", spelling, "s.csv", cwd=work)
        header = open(os.path.join(work, "s.csv")).readline() if r.returncode == 0 else ""
        check(header.startswith("dim,grid,method,") and ",cycles_per_spacing,field_frequency," in header,
              f"sample {spelling} writes the statistics CSV with cycles_per_spacing: {r.stderr.strip()!r}")
        os.remove(os.path.join(work, "s.csv")) if os.path.exists(os.path.join(work, "s.csv")) else None

print(f"{len(failures)} failure(s)")
sys.exit(1 if failures else 0)
