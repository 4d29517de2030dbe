#!/usr/bin/env bash
# The seeds' noise options (issue 44 items 3-4): --rotation two-vector|fast|well-behaved (seed 001) for 3D simplex
# noise on field and sample, and --steer-quality Q and --steer-image FILE (seed 002) for --noise steerable.
# - --rotation two-vector is the field without the option, byte for byte; fast and well-behaved differ from it and
#   from each other; a phase of pi flips every f_i for each;
# - bad values: one line, non-zero exit, nothing written.
set -u
source "$(dirname "${BASH_SOURCE[0]}")/harness.sh"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
cp "$here/../../data/points_3d_example.csv" "$work/points_3d.csv"
cd "$work" || exit 1
cut -d, -f1,2 points_3d.csv >points_2d.csv

s3=(field --input points_3d.csv --noise simplex)
"$bin" "${s3[@]}" --phase 0.7 -o plain.csv && "$bin" "${s3[@]}" --phase 0.7 --rotation two-vector -o two.csv && cmp -s plain.csv two.csv &&
  ok || bad "--rotation two-vector is not the default"
for r in fast well-behaved; do
  "$bin" "${s3[@]}" --phase 0.7 --rotation "$r" -o "$r.csv" && ! cmp -s plain.csv "$r.csv" && ok || bad "--rotation $r changed nothing"
  "$bin" "${s3[@]}" --rotation "$r" -o "${r}0.csv" && "$bin" "${s3[@]}" --rotation "$r" --phase 3.141592653589793 -o "${r}pi.csv" &&
    /usr/bin/python3 - "${r}0.csv" "${r}pi.csv" <<'PY' && ok || bad "--rotation $r: a phase of pi does not flip the f_i"
import sys, numpy as np
a, b = (np.loadtxt(f, delimiter=",", skiprows=1) for f in sys.argv[1:])
assert np.max(np.abs(a[:, 6:] + b[:, 6:])) < 1e-12 * max(1, np.max(np.abs(a[:, 6:])))
PY
done
! cmp -s fast.csv well-behaved.csv && ok || bad "fast and well-behaved are the same"
"$bin" --dim 3 --grid 4 --methods cnj --domain cube --noise simplex --rotation fast --phase 1 --no-stats --points - -q >cnj.csv &&
  [[ $(wc -l <cnj.csv) -gt 60 ]] && ok || bad "sample --rotation fast"

check_bad() {
  local name=$1 pattern=$2
  shift 2
  expect_error "$name" "" "$pattern" "$@" -o bad.csv
  [[ -e bad.csv ]] && bad "$name wrote bad.csv" || ok
  rm -f bad.csv
}
check_bad "unknown rotation" "rotation" "${s3[@]}" --rotation slow
check_bad "rotation of turning bands" "simplex in 3D" field --input points_3d.csv --rotation fast
check_bad "rotation in 2D" "3D only" field --input points_2d.csv --noise simplex --rotation well-behaved
check_bad "rotation with --time" "without --stretch, --time" "${s3[@]}" --rotation fast --time 1
finish cli_seeds_noise
