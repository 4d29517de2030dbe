#!/usr/bin/python3
"""Checks `dfvn-sample animate` from outside, with SciPy (issue 46's acceptance), on frames.npy:
 - every particle in every frame (no NaN row, every point in the domain) unless --drop;
 - the packing of each frame, the nearest-neighbour distances of the particles shown (scipy cKDTree,
   Euclidean: the cube and the ball) in mean spacings (measure / count)^(1/N): every frame's median at
   least --median-floor (0.9) of frame 0's, the mean of the medians over the frames within --median-mean
   (5%) of frame 0's, every frame's 1% quantile at least --q01-floor (0.6) of frame 0's, frame 0's median
   above --frame0-median (0.7) mean spacings;
 - the per-frame moves |x_k - x_{k-1}| over all frames and the particles shown in both, in frame 0's mean
   spacings: median at most --move-median (0.1), 99th percentile at most --move-p99 (4) times the median,
   largest at most --move-max (10) times the median;
 - frames.csv's packing columns (nn_min, nn_q01, nn_median, nn_median_scaled) equal SciPy's on the frame
   to 1e-7 relative.
Prints the numbers, one line per criterion, and exits 1 when a criterion fails (0 when all hold). With
--expect-decay it exits 0 only when a packing criterion fails and the files are sound: the advect mode
(frame after frame along the flow) mixes the lattice towards uniform, and this run shows it.
Any error (the binary failed, a file is missing or malformed) exits 2.

Usage: check_animation.py BINARY [options] -- ANIMATE-ARGS...   (runs animate --out TMP -q ANIMATE-ARGS)
       check_animation.py --dir DIR --domain cube|ball [options] (checks DIR/frames.npy and DIR/frames.csv)
"""
import argparse
import csv
import math
import os
import subprocess
import sys
import tempfile

import numpy as np
from scipy.spatial import cKDTree


def ball_volume(n, radius):
    return math.pi ** (n / 2) / math.gamma(n / 2 + 1) * radius ** n


def measure(domain, n):
    return 1.0 if domain == "cube" else ball_volume(n, 0.5)


def inside(points, domain):
    if domain == "cube":
        return ((points >= 0) & (points <= 1)).all(axis=1)
    return np.linalg.norm(points - 0.5, axis=1) <= 0.5


def frame_packing(points, domain):
    """(min, q01, median, median in mean spacings) of the nearest-neighbour distances."""
    n = points.shape[1]
    d, _ = cKDTree(points).query(points, k=2)
    d = d[:, 1]
    spacing = (measure(domain, n) / len(points)) ** (1.0 / n)
    return d.min(), np.quantile(d, 0.01), np.median(d), np.median(d) / spacing, spacing


def check(frames, rows, domain, args):
    """Returns (lines, failed packing criteria, failed move criteria, file errors)."""
    lines, packing_fail, move_fail, errors = [], [], [], []
    count, particles, n = frames.shape
    shown = ~np.isnan(frames[:, :, 0])
    if not args.drop:
        ok = bool(shown.all())
        for k in range(count):
            ok = ok and bool(inside(frames[k][shown[k]], domain).all())
        lines.append(f"every particle in every frame: {'yes' if ok else 'NO'}")
        if not ok:
            packing_fail.append("every particle in every frame")
    packing = np.array([frame_packing(frames[k][shown[k]], domain) for k in range(count)])
    median, q01 = packing[:, 3], packing[:, 1] / packing[:, 4]
    m0, q0 = median[0], q01[0]
    lines.append(f"frame 0: median {m0:.4f}, q01 {q0:.4f} mean spacings ({particles} particles, {n}D {domain})")
    lines.append(f"median / frame 0's: min {median.min() / m0:.4f} (frame {median.argmin()}), "
                 f"mean over frames {median.mean() / m0:.4f}, max {median.max() / m0:.4f}")
    lines.append(f"q01 / frame 0's: min {q01.min() / q0:.4f} (frame {q01.argmin()}), max {q01.max() / q0:.4f}")
    for name, value, good in [
        (f"every median >= {args.median_floor} of frame 0's", median.min() / m0, median.min() >= args.median_floor * m0),
        (f"mean median within {args.median_mean} of frame 0's", abs(median.mean() / m0 - 1), abs(median.mean() / m0 - 1) <= args.median_mean),
        (f"every q01 >= {args.q01_floor} of frame 0's", q01.min() / q0, q01.min() >= args.q01_floor * q0),
        (f"frame 0's median > {args.frame0_median} spacings", m0, m0 > args.frame0_median),
    ]:
        lines.append(f"  {'ok  ' if good else 'FAIL'} {name}: {value:.4f}")
        if not good:
            packing_fail.append(name)
    if count > 1:
        both = shown[1:] & shown[:-1]
        moves = np.linalg.norm(frames[1:] - frames[:-1], axis=2)[both] / packing[0, 4]
        med, p99, top = np.median(moves), np.quantile(moves, 0.99), moves.max()
        lines.append(f"moves (frame 0's mean spacings, {moves.size} of them): median {med:.5f}, 99th {p99:.5f} "
                     f"({p99 / med:.3f}x), largest {top:.5f} ({top / med:.3f}x)")
        for name, good in [(f"median move <= {args.move_median}", med <= args.move_median),
                           (f"99th percentile <= {args.move_p99}x median", p99 <= args.move_p99 * med),
                           (f"largest <= {args.move_max}x median", top <= args.move_max * med)]:
            lines.append(f"  {'ok  ' if good else 'FAIL'} {name}")
            if not good:
                move_fail.append(name)
    # frames.csv: its packing columns are SciPy's.
    if len(rows) != count:
        errors.append(f"frames.csv has {len(rows)} rows for {count} frames")
    for k, row in enumerate(rows[:count]):
        for column, index in [("nn_min", 0), ("nn_q01", 1), ("nn_median", 2), ("nn_median_scaled", 3)]:
            if column not in row:
                errors.append(f"frames.csv has no column {column}")
                return lines, packing_fail, move_fail, errors
            value, want = float(row[column]), packing[k, index]
            if not abs(value - want) <= 1e-7 * abs(want):
                errors.append(f"frames.csv frame {k} {column} = {value}, SciPy {want}")
    lines.append(f"frames.csv packing columns equal SciPy's: {'yes' if not errors else 'NO'}")
    return lines, packing_fail, move_fail, errors


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("binary", nargs="?")
    parser.add_argument("--dir", help="check DIR/frames.npy and DIR/frames.csv instead of running the binary")
    parser.add_argument("--domain", choices=["cube", "ball"], help="with --dir: where the particles live")
    parser.add_argument("--drop", action="store_true", help="drop mode: particles outside are NaN rows")
    parser.add_argument("--expect-decay", action="store_true")
    parser.add_argument("--median-floor", type=float, default=0.9)
    parser.add_argument("--median-mean", type=float, default=0.05)
    parser.add_argument("--q01-floor", type=float, default=0.6)
    parser.add_argument("--frame0-median", type=float, default=0.7)
    parser.add_argument("--move-median", type=float, default=0.1)
    parser.add_argument("--move-p99", type=float, default=4.0)
    parser.add_argument("--move-max", type=float, default=10.0)
    argv = sys.argv[1:]
    split = argv.index("--") if "--" in argv else len(argv)
    args = parser.parse_args(argv[:split])
    args.animate_args = argv[split + 1:]
    try:
        with tempfile.TemporaryDirectory() as tmp:
            if args.dir:
                folder, domain = args.dir, args.domain or "cube"
            else:
                folder = os.path.join(tmp, "animate")
                cmd = [args.binary, "animate", *args.animate_args, "--out", folder, "-q"]
                subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
                domain = "ball" if "ball" in args.animate_args else "cube"
                args.drop = args.drop or "drop" in args.animate_args
                print("ran:", " ".join(cmd[1:]))
            frames = np.load(os.path.join(folder, "frames.npy"))
            with open(os.path.join(folder, "frames.csv")) as f:
                rows = list(csv.DictReader(f))
            lines, packing_fail, move_fail, errors = check(frames, rows, domain, args)
    except Exception as error:  # noqa: BLE001 - any failure to run or read is an error, not a verdict
        print(f"check_animation.py: error: {error}", file=sys.stderr)
        return 2
    print("\n".join(lines))
    for e in errors[:5]:
        print("error:", e)
    if errors:
        return 2
    if args.expect_decay:
        print("expected the packing to decay:", "it does" if packing_fail else "it does NOT")
        return 0 if packing_fail else 1
    return 1 if packing_fail or move_fail else 0


if __name__ == "__main__":
    sys.exit(main())
