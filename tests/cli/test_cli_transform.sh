#!/usr/bin/env bash
# --stretch U:S, --time T, --lift SPEC and --lift-ramp BETA on field and sample (issue 27 items 1-2,
# issue 25 item 2):
# - without them the output is the recorded one byte for byte (cmp against tests/cli/reference/);
#   --stretch U:1 is the unstretched field byte for byte;
# - each of them changes the output; sample takes --stretch off the torus and --time on it;
# - bad input (zero direction, S <= 0, malformed specs, a non-finite time, --time in 8D, --lift outside
#   2D or beside --time, --lift-ramp without --lift, --stretch on the torus): one line, non-zero exit,
#   no output file.
set -u
source "$(dirname "${BASH_SOURCE[0]}")/harness.sh"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
cp "$here/../../data/points_3d_example.csv" "$work/points_3d.csv"
cd "$work" || exit 1
cut -d, -f1,2 points_3d.csv >points_2d.csv

# Absent: the recorded output. S = 1: the same bytes.
"$bin" field --input points_3d.csv -o field.csv && same_as_recorded "field without a transform" field.csv field.csv
"$bin" field --input points_3d.csv --stretch 1,-2,0.5:1 -o s1.csv && cmp -s s1.csv field.csv && ok || bad "--stretch U:1 changed the field"
"$bin" --dim 2 --grid 5 --methods cnj --no-stats --points - -q >points.csv && same_as_recorded "sample without a transform" points.csv main_stdout.stdout

# Each transform changes the field; the columns stay those of field.
for args in "--stretch 1,-2,0.5:3" "--time 0.25" "--time 0" "--phase 1 --time 0.25"; do
  # shellcheck disable=SC2086
  "$bin" field --input points_3d.csv $args -o t.csv || bad "field $args failed"
  if cmp -s t.csv field.csv; then bad "field $args changed nothing"; else ok; fi
  [[ $(head -1 t.csv) == "$(head -1 field.csv)" ]] && ok || bad "field $args: other columns"
done
"$bin" field --input points_2d.csv -o flat.csv --time 0 &&
  "$bin" field --input points_2d.csv -o plane0.csv --lift plane:0,0 && cmp -s flat.csv plane0.csv && ok ||
  bad "--lift plane:0,0 differs from --time 0"
"$bin" field --input points_2d.csv -o bump.csv --lift bump:1,0.5,0.5,0.5 --lift-ramp 0.3 && ok || bad "field --lift bump"
cmp -s bump.csv flat.csv && bad "--lift bump changed nothing" || ok
# sample: the torus takes --time (its periodic basis one dimension up), the cube takes --stretch.
"$bin" --dim 3 --grid 5 --methods cnj --no-stats --points - -q --time 0.5 >time.csv && ok || bad "sample --time on the torus"
"$bin" --dim 3 --grid 5 --methods cnj --no-stats --points - -q --domain cube --stretch 0,0,1:4 >stretch.csv && ok ||
  bad "sample --stretch in the cube"
"$bin" --dim 2 --grid 5 --methods cnj --no-stats --points - -q --domain cube --lift plane:1,0 >lift.csv && ok || bad "sample --lift"
"$bin" field --diagnose --diagnose-points 2000 --dim 3 --time 1.5 --stretch 1,1,0:2 -o diag.csv && ok || bad "diagnose with both"

# The JSON report records the transforms given (and nothing when none is: the recorded reports above).
"$bin" --dim 3 --grid 4 --methods cnj --domain cube --stretch 0,0,2:4 --time 0.5 -q --no-timing -o /dev/null --json t.json &&
  /usr/bin/python3 -c '
import json, sys
cnj = json.load(open("t.json"))["parameters"]["cnj"]
assert cnj["stretch"] == {"direction": [0.0, 0.0, 2.0], "factor": 4.0}, cnj
assert cnj["time"] == 0.5 and "lift" not in cnj, cnj' && ok || bad "the JSON report lacks the transforms"

# Bad input: one line, non-zero exit, no output file.
check_bad() {
  local name=$1 pattern=$2
  shift 2
  expect_error "$name" "" "$pattern" "$@" -o bad.csv
  [[ -e bad.csv ]] && bad "$name wrote bad.csv" || ok
  rm -f bad.csv
}
for spec in "" 0,0,0:2 1,0,0:0 1,0,0:-1 1,0,0:abc 1,0,0 1,0,0: :2 1,x,0:2 1,0,0:nan 1,0,0:inf 1,0:2 1,0,0:2,3 1,0,0:1e7; do
  check_bad "--stretch '$spec'" "stretch" field --input points_3d.csv --stretch "$spec"
done
for t in nan inf -inf 1e999 abc ""; do
  check_bad "--time '$t'" "time" field --input points_3d.csv --time "$t"
  check_bad "sample --time '$t'" "time" --dim 2 --grid 4 -q --time "$t"
done
check_bad "--time 1e300" "noise domain" field --input points_3d.csv --time 1e300
check_bad "--time in 8D" "--dim 7 or less" field --diagnose --dim 8 --time 1
check_bad "sample --time in 8D" "--dim 7 or less" --dim 8 --grid 2 -q --time 1
check_bad "--stretch on the torus" "torus" field --input points_3d.csv --domain torus --stretch 1,0,0:2
check_bad "sample --stretch on the torus" "torus" --dim 3 --grid 4 -q --stretch 1,0,0:2
for spec in plane plane: plane:1 plane:1,2,3 bump:1 bump:1,0 bump:1,-1 cone:1,2 plane:nan,1 "" npy:h.npy; do
  check_bad "--lift '$spec'" "lift" field --input points_2d.csv --lift "$spec"
done
# --lift npy:FILE: a 2D float array over the unit square; a bad array is one line naming the file.
/usr/bin/python3 -c '
import numpy as np
h = np.linspace(0, 1, 5)[None, :] * np.linspace(0, 1, 4)[:, None]
np.save("good.npy", h)
np.save("good32.npy", h.astype(np.float32))
bad = h.copy(); bad[1, 2] = np.nan; np.save("nan.npy", bad)
np.save("ndim1.npy", h.ravel()); np.save("ndim3.npy", h[None]); np.save("ints.npy", (h * 10).astype(np.int64))
np.save("onerow.npy", h[:1])' && ok || bad "numpy could not write the height fields"
"$bin" field --input points_2d.csv -o npy.csv --lift npy:good.npy --lift-ramp 0.3 && ok || bad "field --lift npy:good.npy"
cmp -s npy.csv flat.csv && bad "--lift npy changed nothing" || ok
"$bin" field --input points_2d.csv -o npy32.csv --lift npy:good32.npy && ok || bad "field --lift npy of float32"
for f in nan ndim1 ndim3 ints onerow; do
  check_bad "--lift npy:$f.npy" "lift npy:.*$f.npy" field --input points_2d.csv --lift "npy:$f.npy"
done
check_bad "--lift in 3D" "--dim 2" field --input points_3d.csv --lift plane:1,0
check_bad "--lift beside --time" "give one of them" field --input points_2d.csv --lift plane:1,0 --time 1
check_bad "--lift-ramp without --lift" "with --lift" field --input points_2d.csv --lift-ramp 1
check_bad "--lift-ramp nan" "lift-ramp" field --input points_2d.csv --lift plane:1,0 --lift-ramp nan
finish cli_transform
