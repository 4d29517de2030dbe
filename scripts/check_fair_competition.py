#!/usr/bin/python3
"""Checks the main job from outside, with SciPy: runs `dfvn-sample ARGS --points DIR --format npy`, then
 - every row has one domain and one domain_side (fair protocol) and the same point count;
 - every row's nn_min, nn_q01, nn_median and nn_median_scaled equal scipy.spatial.cKDTree's on the written
   points in the row's domain (boxsize on the torus) to 1e-7 relative;
 - `dfvn-sample stats DIR/*.npy` (no flags: the sidecars say where the points live) gives the same
   nearest-neighbour columns, density-scaled ones included, as the job's rows;
 - with --rdf: each set's RDF averaged over 1-2.5 mean spacings (printed; for uniform random points it
   must be 1 within --rdf-tolerance).
Prints one line per method and exits 1 on any mismatch. --paper: the paper protocol's run, whose rows
live in several boxes (each measured in its own); the one-domain check is skipped.
Usage: check_fair_competition.py BINARY [--rdf-tolerance T] [--paper] -- ARGS...
"""
import argparse
import csv
import json
import os
import subprocess
import sys
import tempfile

import numpy as np
from scipy.spatial import cKDTree


def nearest(points, domain):
    if domain["kind"] == "torus":
        lo, side = domain["lo"], domain["side"]
        tree = cKDTree(points - lo, boxsize=side)
        d, _ = tree.query(points - lo, k=2)
    else:
        tree = cKDTree(points)
        d, _ = tree.query(points, k=2)
    return d[:, 1]


def volume(domain, n):
    from math import gamma, pi
    side = domain["side"]
    if domain["kind"] in ("torus", "cube"):
        return side ** n
    if domain["kind"] == "ball":
        return pi ** (n / 2) / gamma(n / 2 + 1) * (side / 2) ** n
    raise ValueError(domain["kind"])


def close(a, b, tolerance=1e-7):
    return abs(a - b) <= tolerance * max(abs(a), abs(b), 1e-300)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("binary")
    parser.add_argument("--rdf-tolerance", type=float, default=0.0)
    parser.add_argument("--paper", action="store_true")
    split = sys.argv.index("--") if "--" in sys.argv else len(sys.argv)
    a = parser.parse_args(sys.argv[1:split])
    args = sys.argv[split + 1:]
    failures = []
    with tempfile.TemporaryDirectory(prefix="dfvn-fair-") as work:
        pts = os.path.join(work, "pts")
        stats_csv = os.path.join(work, "stats.csv")
        rdf_csv = os.path.join(work, "rdf.csv")
        command = [a.binary, *args, "--points", pts, "--format", "npy", "-o", stats_csv, "-q", "--no-timing"]
        if a.rdf_tolerance > 0:
            command += ["--rdf", rdf_csv]
        subprocess.run(command, check=True)
        rows = list(csv.DictReader(open(stats_csv)))  # data rows only
        domains = {(r["domain"], r["domain_side"]) for r in rows}
        counts = {r["points"] for r in rows}
        print(f"rows {len(rows)}: domains {sorted(domains)}, counts {sorted(counts)}")
        if not a.paper and (len(domains) != 1 or len(counts) != 1):
            failures.append("more than one domain or count in one table")
        files = [os.path.join(pts, f"{r['method']}.npy") for r in rows]
        again = subprocess.run([a.binary, "stats", *files, "--no-timing", "-q"], check=True, capture_output=True,
                               text=True).stdout
        again_rows = {os.path.basename(r["input"])[:-4]: r for r in csv.DictReader(again.splitlines())}
        n = int(rows[0]["dim"])
        for r in rows:
            method = r["method"]
            points = np.load(os.path.join(pts, f"{method}.npy"))
            domain = json.load(open(os.path.join(pts, f"{method}.npy.json")))["domain"]
            d = nearest(points, domain)
            ours = {k: float(r[k]) for k in ("nn_min", "nn_q01", "nn_median", "nn_median_scaled")}
            scipy = {"nn_min": d.min(), "nn_q01": np.quantile(d, 0.01), "nn_median": np.median(d)}
            scipy["nn_median_scaled"] = scipy["nn_median"] * (len(points) / volume(domain, n)) ** (1.0 / n)
            bad = [k for k in ours if not close(ours[k], scipy[k])]
            redo = [k for k in ours if again_rows[method][k] != r[k]]
            print(f"{method:15s} {domain['kind']} side {domain['side']:g}: {len(points)} points, nn_min {ours['nn_min']:.9g} "
                  f"(cKDTree {scipy['nn_min']:.9g}), median {ours['nn_median']:.9g} ({scipy['nn_median']:.9g}), "
                  f"scaled {ours['nn_median_scaled']:.9g}; stats on the file: {'same' if not redo else 'DIFFERS ' + str(redo)}")
            if bad:
                failures.append(f"{method}: {bad} differ from cKDTree")
            if redo:
                failures.append(f"{method}: stats on its file differs in {redo}")
        if a.rdf_tolerance > 0:
            curves = {}
            for row in csv.DictReader(open(rdf_csv)):
                curves.setdefault(row["method"], []).append((float(row["r"]), float(row["g"])))
            for method, curve in curves.items():
                r_max = max(r for r, _ in curve) * len(curve) / (len(curve) - 0.5)  # bin centres to r_max
                spacing = r_max / 2.5
                tail = [g for r, g in curve if spacing <= r <= 2.5 * spacing]
                mean = sum(tail) / len(tail)
                print(f"{method:15s} RDF mean over 1-2.5 spacings {mean:.4f} (min {min(tail):.3f}, max {max(tail):.3f})")
                if method == "random" and abs(mean - 1) > a.rdf_tolerance:
                    failures.append(f"random's RDF {mean:.4f} is not 1 within {a.rdf_tolerance}")
    for f in failures:
        print("FAIL:", f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
