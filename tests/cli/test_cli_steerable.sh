#!/usr/bin/env bash
# --noise steerable with --steer-dir U, --steer-field circular and --steer-k K on field, sample and animate
# (issue 27 item 3, seed 002):
# - it runs in 2D-4D with a constant and the circular direction field; U and -U (and 2U) write the same
#   bytes; K changes the output; the JSON report records the steering;
# - bad input (zero direction, wrong length, K out of range, N > 4, steer options without --noise
#   steerable, steerable without a direction, both direction fields, beside --stretch): one line,
#   non-zero exit, no output file.
set -u
source "$(dirname "${BASH_SOURCE[0]}")/harness.sh"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
cp "$here/../../data/points_3d_example.csv" "$work/points_3d.csv"
cd "$work" || exit 1
cut -d, -f1,2 points_3d.csv >points_2d.csv
paste -d, points_3d.csv <(cut -d, -f1 points_3d.csv) >points_4d.csv
paste -d, points_4d.csv <(cut -d, -f1 points_3d.csv) >points_5d.csv

for n in 2 3 4; do
  dir=$(seq -s, 1 "$n")
  minus=$(seq -s, 1 "$n" | sed 's/\([0-9]\)/-\1/g')
  double=$(seq -s, 2 2 $((2 * n)))
  "$bin" field --input "points_${n}d.csv" --noise steerable --steer-dir "$dir" -o plus.csv && ok || bad "field ${n}D steerable"
  "$bin" field --input "points_${n}d.csv" --noise steerable --steer-dir "$minus" -o minus.csv && cmp -s plus.csv minus.csv && ok ||
    bad "${n}D: U and -U differ"
  "$bin" field --input "points_${n}d.csv" --noise steerable --steer-dir "$double" -o double.csv && cmp -s plus.csv double.csv && ok ||
    bad "${n}D: U and 2U differ"
  "$bin" field --input "points_${n}d.csv" --noise steerable --steer-dir "$dir" --steer-k 0.2 -o k.csv && ok || bad "field ${n}D --steer-k"
  cmp -s plus.csv k.csv && bad "${n}D: --steer-k changed nothing" || ok
  "$bin" field --input "points_${n}d.csv" --noise steerable --steer-field circular -o circ.csv && ok || bad "field ${n}D circular"
  cmp -s plus.csv circ.csv && bad "${n}D: circular equals constant" || ok
  [[ $(wc -l <circ.csv) -eq $(wc -l <plus.csv) && $(head -1 circ.csv) == "$(head -1 plus.csv)" ]] && ok ||
    bad "${n}D circular: other rows or columns"
done
"$bin" field --diagnose --diagnose-points 2000 --dim 3 --noise steerable --steer-dir 1,0,0 -o diag.csv && ok || bad "diagnose steerable"
"$bin" --dim 2 --grid 5 --methods cnj --no-stats --points - -q --domain cube --noise steerable --steer-field circular >s.csv && ok ||
  bad "sample steerable in the cube"
"$bin" --dim 3 --grid 4 --methods cnj --domain cube --noise steerable --steer-dir 0,0,2 --steer-k 0.3 -q --no-timing -o /dev/null \
  --json t.json && /usr/bin/python3 -c '
import json
cnj = json.load(open("t.json"))["parameters"]["cnj"]
assert cnj["steer"] == {"field": "constant", "direction": [0.0, 0.0, 2.0], "k": 0.3}, cnj' && ok ||
  bad "the JSON report lacks the steering"

check_bad() {
  local name=$1 pattern=$2
  shift 2
  expect_error "$name" "" "$pattern" "$@" -o bad.csv
  [[ -e bad.csv ]] && bad "$name wrote bad.csv" || ok
  rm -f bad.csv
}
steer=(field --input points_2d.csv --noise steerable)
check_bad "zero direction" "non-zero direction" "${steer[@]}" --steer-dir 0,0
check_bad "wrong length" "has 3 components" "${steer[@]}" --steer-dir 1,0,0
check_bad "not a number" "not a number" "${steer[@]}" --steer-dir 1,x
check_bad "non-finite" "non-finite|non-zero" "${steer[@]}" --steer-dir 1,inf
for k in 0 -0.5 1.5 nan; do check_bad "--steer-k $k" "steer-k" "${steer[@]}" --steer-dir 1,0 --steer-k "$k"; done
check_bad "--steer-k 1 in 4D" "steer-k" field --input points_4d.csv --noise steerable --steer-dir 1,0,0,0 --steer-k 1
check_bad "5D" "2D to 4D" field --input points_5d.csv --noise steerable --steer-field circular
check_bad "no direction" "needs a direction" "${steer[@]}"
check_bad "both fields" "not both" "${steer[@]}" --steer-dir 1,0 --steer-field circular
check_bad "beside --stretch" "no --stretch" "${steer[@]}" --steer-dir 1,0 --stretch 1,0:2
check_bad "steer without steerable" "steer --noise steerable" field --input points_2d.csv --steer-dir 1,0
check_bad "steer-k without steerable" "steer --noise steerable" field --input points_2d.csv --steer-k 0.3
check_bad "sample 5D" "2D to 4D" --dim 5 --grid 3 --methods cnj --domain cube --noise steerable --steer-field circular
check_bad "sample on the torus" "periodic" --dim 2 --grid 3 --methods cnj --noise steerable --steer-dir 1,0
expect_error "animate without steerable" "" "steer --noise steerable" animate --steer-field circular --out anim
[[ -e anim ]] && bad "animate wrote its folder" || ok
finish cli_steerable
