#!/usr/bin/python3
"""Make the reference discrepancies that tests/stats/test_discrepancy.cpp checks against: SciPy's
scipy.stats.qmc.discrepancy (Debian python3-scipy) on point sets in 2D-8D. Run once; the output is
committed beside this script's name in tests/stats/data/.

For each dimension d = 2..8 it writes two sets, uniform random points (n = 61) and scrambled Sobol
points (n = 128), to tests/stats/data/discrepancy_set_<d>d_<kind>.csv (header x0..x{d-1}, 17
significant digits, so they read back bit for bit), and every set's CD, WD, MD and L2-star to
tests/stats/data/discrepancy_reference.csv.

Usage: /usr/bin/python3 scripts/make_discrepancy_reference.py
"""
import csv
import os

import numpy as np
import scipy
from scipy.stats import qmc

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
OUT = os.path.join(ROOT, "tests", "stats", "data")
METHODS = ["CD", "WD", "MD", "L2-star"]


def main():
    os.makedirs(OUT, exist_ok=True)
    rows = []
    for d in range(2, 9):
        rng = np.random.default_rng(1000 + d)
        sets = {"random": rng.random((61, d)),
                "sobol": qmc.Sobol(d=d, scramble=True, seed=2000 + d).random(128)}
        for kind, points in sets.items():
            name = f"discrepancy_set_{d}d_{kind}.csv"
            with open(os.path.join(OUT, name), "w") as f:
                f.write(",".join(f"x{k}" for k in range(d)) + "\n")
                for p in points:
                    f.write(",".join(repr(float(v)) for v in p) + "\n")
            for method in METHODS:
                value = qmc.discrepancy(points, method=method, workers=1)
                rows.append([name, d, len(points), method, repr(float(value))])
    with open(os.path.join(OUT, "discrepancy_reference.csv"), "w", newline="") as f:
        f.write(f"# scipy.stats.qmc.discrepancy, SciPy {scipy.__version__}, NumPy {np.__version__}; "
                "made by scripts/make_discrepancy_reference.py\n")
        w = csv.writer(f)
        w.writerow(["file", "dim", "points", "method", "value"])
        w.writerows(rows)


if __name__ == "__main__":
    main()
