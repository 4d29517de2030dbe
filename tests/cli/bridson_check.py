#!/usr/bin/env python3
"""Checks of dfvn-sample field's output from outside (issue 44's acceptance), by central differences.

    bridson_check.py BIN divergence N FIELD_OPTIONS...   median |div c| < 1e-5 RMS |c| on random points of the cube
                                                         where c != 0 (at least 30% of them)
    bridson_check.py BIN body C R V W FIELD_OPTIONS...   |(c - V - W x (x - C)) . n| < 1e-8 on the sphere (C, R);
                                                         with --viscous also |c - V - W x (x - C)| < 1e-8
    bridson_check.py BIN obstacle C R FIELD_OPTIONS...   |c . n| < 1e-8 on the sphere; with --viscous |c| < 1e-8
    bridson_check.py BIN wall N FIELD_OPTIONS...         |c_j| < 1e-12 on every face x_j = 0, 1 of the cube; with
                                                         --viscous |c| < 1e-12, else |c| > 0.01 somewhere
Prints the measured numbers; exits 1 when a check fails.
"""
import subprocess
import sys
import tempfile

import numpy as np


def field(binary, points, options):
    with tempfile.NamedTemporaryFile("w", suffix=".csv") as f:
        np.savetxt(f.name, points, delimiter=",", fmt="%.17g")
        done = subprocess.run([binary, "field", "--input", f.name, "-q", *options], capture_output=True, text=True)
    if done.returncode:
        sys.exit(f"field failed: {done.stderr.strip()}")
    table = np.loadtxt(done.stdout.splitlines()[1:], delimiter=",", ndmin=2)
    n = points.shape[1]
    return table[:, n:2 * n]


def vector(text):
    return np.array([float(v) for v in text.split(",")])


def sphere_points(centre, radius, count=1000):
    n = np.random.default_rng(7).normal(size=(count, len(centre)))
    n /= np.linalg.norm(n, axis=1)[:, None]
    return centre + radius * n, n


def main():
    binary, what = sys.argv[1], sys.argv[2]
    rest = sys.argv[3:]
    if what == "divergence":
        n, options = int(rest[0]), rest[1:]
        points = np.random.default_rng(3).uniform(0.01, 0.99, size=(3000, n))
        h = 1e-5
        shifted = [points]
        for j in range(n):
            for sign in (1, -1):
                q = points.copy()
                q[:, j] += sign * h
                shifted.append(q)
        c = field(binary, np.vstack(shifted), options)
        m = len(points)
        div = sum((c[m * (1 + 2 * j):m * (2 + 2 * j), j] - c[m * (2 + 2 * j):m * (3 + 2 * j), j]) / (2 * h) for j in range(n))
        speed = np.linalg.norm(c[:m], axis=1)
        rms = np.sqrt(np.mean(speed ** 2))
        # Only where the field moves: an amplitude that vanishes somewhere gives c = 0 and div c = 0 exactly there.
        moving = speed > 1e-6 * rms
        ratio = np.median(np.abs(div[moving])) / rms
        print(f"RMS |c| {rms:.4g}, median |div c| / RMS {ratio:.3g} over the {np.mean(moving):.0%} of the points where c != 0")
        ok = ratio < 1e-5 and rms > 0.01 and np.mean(moving) > 0.3
    elif what == "body":
        centre, radius, velocity, angular, options = vector(rest[0]), float(rest[1]), vector(rest[2]), vector(rest[3]), rest[4:]
        x, normal = sphere_points(centre, radius)
        relative = field(binary, x, options) - velocity - np.cross(angular, x - centre)
        normal_part = np.max(np.abs(np.sum(relative * normal, axis=1)))
        slip = np.max(np.linalg.norm(relative, axis=1))
        print(f"max |(c - V - W x r) . n| {normal_part:.3g}, max |c - V - W x r| {slip:.3g}")
        ok = normal_part < 1e-8 and ("--viscous" not in options or slip < 1e-8)
    elif what == "obstacle":
        centre, radius, options = vector(rest[0]), float(rest[1]), rest[2:]
        x, normal = sphere_points(centre, radius)
        c = field(binary, x, options)
        normal_part, speed = np.max(np.abs(np.sum(c * normal, axis=1))), np.max(np.linalg.norm(c, axis=1))
        print(f"max |c . n| {normal_part:.3g}, max |c| {speed:.3g}")
        ok = normal_part < 1e-8 and ("--viscous" not in options or speed < 1e-8)
    elif what == "wall":
        n, options = int(rest[0]), rest[1:]
        rng = np.random.default_rng(5)
        worst_normal, worst, largest = 0.0, 0.0, 0.0
        for j in range(n):
            for side in (0.0, 1.0):
                x = rng.uniform(0.05, 0.95, size=(300, n))
                x[:, j] = side
                c = field(binary, x, options)
                worst_normal = max(worst_normal, np.max(np.abs(c[:, j])))
                largest = max(largest, np.max(np.linalg.norm(c, axis=1)))
        print(f"max |c . n| {worst_normal:.3g}, max |c| {largest:.3g} on the faces")
        ok = worst_normal < 1e-12 and (largest < 1e-12 if "--viscous" in options else largest > 0.01)
    else:
        sys.exit(f"unknown check {what}")
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
