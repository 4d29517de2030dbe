#!/usr/bin/env bash
# The seeds' figures (issue 44): `reproduce bridson` (Bridson et al. 2007's Figure 2, reproduce/bridson.hpp):
# - it writes its files, PNGs included, and every check of bridson_checks.csv passes (divergence, c . n on the
#   walls and the fixed sphere, the moving body's normal velocity, no-slip with --viscous, energy per octave);
#   its Markdown quotes the run; the octaves' measured energies follow the gain asked (0.5: ratio 1/4);
# - bad values: one line, non-zero exit, nothing written.
set -u
source "$(dirname "${BASH_SOURCE[0]}")/harness.sh"
cd "$work" || exit 1
is_png() { [[ $(head -c 8 "$1" | od -An -tx1 | tr -d ' \n') == 89504e470d0a1a0a ]]; }
csv_column() { /usr/bin/python3 -c 'import csv,sys; print("\n".join(r[sys.argv[2]] for r in csv.DictReader(open(sys.argv[1]))))' "$1" "$2"; }

"$bin" reproduce bridson --grid 8 --trace-steps 48 --image 96 --check-points 1500 --octave-gain 0.5 --out b -q >b.txt 2>err &&
  ok || bad "bridson: $(cat err)"
for f in bridson.md bridson_checks.csv bridson_octaves.csv wake_traces.csv ring_traces.csv; do
  [[ -s b/$f ]] && ok || bad "bridson wrote no $f"
done
for f in wake_traces ring_traces; do is_png "b/$f.png" && ok || bad "bridson wrote no $f.png"; done
if command -v gnuplot >/dev/null; then
  for f in wake ring; do is_png "b/$f.png" && ok || bad "bridson wrote no titled $f.png"; done
fi
[[ $(csv_column b/bridson_checks.csv passed | sort -u) == 1 ]] && ok || bad "bridson: a check failed: $(grep ',0$' b/bridson_checks.csv)"
[[ $(grep -c . b/bridson_checks.csv) -ge 14 ]] && ok || bad "bridson_checks.csv: fewer checks than expected"
grep -q -- "--octave-gain 0.5 --boundary-width 0.06 --grid 8 --trace-steps 48" b/bridson.md && ok || bad "bridson.md does not quote the run"
# gain 0.5: energies 1, 1/4, 1/16 over 21/16, measured within 10%
/usr/bin/python3 - b/bridson_octaves.csv <<'PY' && ok || bad "bridson: the octaves' energies do not follow the gain 0.5"
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
assert len(rows) == 3, rows
for o, r in enumerate(rows):
    law = 0.25 ** o / (1 + 0.25 + 0.0625)
    assert abs(float(r["law"]) / law - 1) < 1e-6, r
    assert abs(float(r["measured"]) / law - 1) < 0.1, r
PY
[[ $(wc -l <b/wake_traces.csv) -eq $((64 * 7 + 1)) ]] && ok || bad "wake_traces.csv: 64 particles x 7 points"
! grep -q "| ---" b.txt && ok || bad "bridson printed Markdown"

check_bad() {
  local name=$1 pattern=$2
  shift 2
  expect_error "$name" "" "$pattern" reproduce bridson "$@" --out bad
  [[ -e bad ]] && bad "$name wrote its folder" || ok
  rm -rf bad
}
check_bad "octaves 0" "octaves" --octaves 0
check_bad "octave gain 0" "octave-gain" --octave-gain 0
check_bad "boundary width 0.1" "boundary-width" --boundary-width 0.1
check_bad "grid 1" "grid" --grid 1
check_bad "steps 2" "trace-steps" --trace-steps 2
check_bad "frequency 100" "frequency" --frequency 100
check_bad "check points 10" "check-points" --check-points 10
finish cli_seed_figures
