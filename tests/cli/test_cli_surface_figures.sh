#!/usr/bin/env bash
# Command-line tests of `reproduce figure6`, `figure7`, `figure9` and `figure10` (src/reproduce/surface_figures.hpp,
# issue 27 item 4), each on a small run: its files exist, its CSVs have one type per column with every real
# written as a real, the targets read from the CSV hold, and bad input is one line with no folder made.
set -u
source "$(dirname "${BASH_SOURCE[0]}")/harness.sh"
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)

is_png() { [[ -s $1 && $(head -c 8 "$1" | od -An -tx1 | tr -d ' \n') == 89504e470d0a1a0a ]]; }
# csv_value FILE ROW COLUMN: the value in data row ROW (1 = the first after the header) of the named column.
csv_value() {
  awk -F, -v row="$2" -v name="$3" 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == name) c = i; next }
    NR == row + 1 { print $c }' "$1"
}
# holds EXPRESSION: a Python comparison of numbers, true or false.
holds() { python3 -c "import sys; sys.exit(0 if ($1) else 1)"; }

# ---- figure6: the sphere ----
"$bin" reproduce figure6 --width 32 --out "$work/f6" -q >"$work/f6.txt" 2>"$work/err" && ok || bad "figure6: $(cat "$work/err")"
for f in figure6.csv figure6.md; do [[ -s $work/f6/$f ]] && ok || bad "figure6 wrote no $f"; done
for f in source reference rk4-32 rk4-32-projected rk4-128 rk4-128-projected error-rk4-32 error-rk4-128-projected \
  time-0.125 time-0.25 time-0.5; do
  is_png "$work/f6/$f.png" && ok || bad "figure6 wrote no $f.png"
done
# The titled montages (gnuplot): figure6's row of increasing t and its error maps, figure7's labelled panels.
if command -v gnuplot >/dev/null; then
  is_png "$work/f6/figure6.png" && ok || bad "figure6 wrote no figure6.png"
fi
# The default map is at least 512 x 256 pixels (the effect of projection is visible there).
"$bin" reproduce figure6 --help | grep -q -- "--width W (.*default 512)" && ok || bad "figure6's default width is not 512"
[[ $(wc -l <"$work/f6/figure6.csv") -eq 6 ]] && ok || bad "figure6.csv: header + 5 rows: $(cat "$work/f6/figure6.csv")"
for steps in 32 128; do
  free=$(grep "^rk4-$steps," "$work/f6/figure6.csv" | cut -d, -f4)
  proj=$(grep "^rk4-$steps-projected," "$work/f6/figure6.csv" | cut -d, -f4)
  drift=$(grep "^rk4-$steps-projected," "$work/f6/figure6.csv" | cut -d, -f5)
  holds "$proj < $free" && ok || bad "figure6: projection does not lower the RMSE at $steps steps ($proj vs $free)"
  holds "$drift <= 1e-12" && ok || bad "figure6: |x| drifts by $drift with projection at $steps steps"
done
grep -q "Projection lowers the RMSE at both step counts: yes" "$work/f6/figure6.md" && ok || bad "figure6.md reading: $(grep Targets "$work/f6/figure6.md")"
grep -q -- "--width 32 --trace-time 0.5" "$work/f6/figure6.md" && ok || bad "figure6.md does not quote the run"
! grep -q "| ---" "$work/f6.txt" && ok || bad "figure6 printed Markdown"

# ---- figure7: the disc ----
"$bin" reproduce figure7 --width 48 --rk4-steps 16 --width-3d 24 --out "$work/f7" -q >/dev/null 2>"$work/err" && ok || bad "figure7: $(cat "$work/err")"
for f in figure7.csv figure7_profile.csv figure7.md figure7_constructions_3d.csv; do [[ -s $work/f7/$f ]] && ok || bad "figure7 wrote no $f"; done
for f in source warped; do is_png "$work/f7/$f.png" && ok || bad "figure7 wrote no $f.png"; done
inside=$(csv_value "$work/f7/figure7.csv" 1 samples_inside)
[[ $(csv_value "$work/f7/figure7.csv" 1 left) == 0 ]] && ok || bad "figure7: samples left the disc: $(cat "$work/f7/figure7.csv")"
holds "$inside > 1000" && ok || bad "figure7: only $inside samples inside"
holds "$(csv_value "$work/f7/figure7.csv" 1 max_end_radius_inside) <= 0.5" && ok || bad "figure7: a trace ended beyond r = 0.5"
holds "$(csv_value "$work/f7/figure7.csv" 1 max_change_outside) <= 1e-6" && ok || bad "figure7: the pattern changed outside the disc"
holds "$(csv_value "$work/f7/figure7.csv" 1 mean_change_inside) > 0.05" && ok || bad "figure7: the warp did not move the rings inside"
[[ $(grep -c ",outside," "$work/f7/figure7_profile.csv") -ge 5 ]] && ok || bad "figure7_profile.csv has no bins outside"
# figure7's 3D half and the paper's construction beside Eq. 13 (issue 44): both confine in 2D and 3D; Eq. 13's field
# is divergence-free in the transition zone, the paper's interpolated vector is not.
for f in warped_paper slices_3d; do is_png "$work/f7/$f.png" && ok || bad "figure7 wrote no $f.png"; done
if command -v gnuplot >/dev/null; then is_png "$work/f7/figure7.png" && ok || bad "figure7 wrote no figure7.png"; fi
rows=$work/f7/figure7_constructions_3d.csv
[[ $(grep -c . "$rows") -eq 5 ]] && ok || bad "figure7_constructions_3d.csv: header + 4 rows: $(cat "$rows")"
/usr/bin/python3 - "$rows" <<'PY' && ok || bad "figure7 constructions: $(cat "$rows")"
import csv, sys
rows = {(r["dimension"], r["construction"]): r for r in csv.DictReader(open(sys.argv[1]))}
for n in ("2", "3"):
    e, p = rows[n, "eq13"], rows[n, "paper"]
    assert int(e["left"]) == 0 and int(p["left"]) == 0 and int(e["samples_inside"]) > 100, (e, p)
    assert float(e["zone_divergence_median"]) < 1e-4 < 1e-2 < float(p["zone_divergence_median"]), (e, p)
    assert float(e["max_radius_drift_outside"]) < 1e-9, e
PY
grep -q "The paper's construction beside Eq. 13" "$work/f7/figure7.md" && ok || bad "figure7.md lacks the constructions"

# ---- figure9 / figure10: the slope, a steep one (gradient covariance ratio 1 + 9 = 10) ----
"$bin" reproduce figure10 --slope 3,0 --grid 24 --rk4-steps 16 --segments 8 --image 64 --out "$work/f10" -q >/dev/null 2>"$work/err" \
  && ok || bad "figure10: $(cat "$work/err")"
"$bin" reproduce figure9 --slope 3,0 --lift-ramp 1 --bump 0,0.25 --grid 24 --rk4-steps 16 --segments 8 --image 64 --out "$work/f9" -q \
  >/dev/null 2>"$work/err" && ok || bad "figure9: $(cat "$work/err")"
for n in 9 10; do
  for f in figure$n.csv figure${n}_traces.csv figure$n.md; do [[ -s $work/f$n/$f ]] && ok || bad "figure$n wrote no $f"; done
  is_png "$work/f$n/figure${n}_traces.png" && ok || bad "figure$n wrote no figure${n}_traces.png"
  if command -v gnuplot >/dev/null; then is_png "$work/f$n/figure$n.png" && ok || bad "figure$n wrote no figure$n.png"; fi
  [[ $(wc -l <"$work/f$n/figure${n}_traces.csv") -eq $((24 * 24 * 9 + 1)) ]] && ok || bad "figure${n}_traces.csv: 576 particles x 9 points"
  # Across the slope (x) the field is faster: the principal direction is far from the slope direction.
  angle=$(csv_value "$work/f$n/figure$n.csv" 1 principal_to_slope_deg)
  holds "60 <= $angle <= 90" && ok || bad "figure$n: principal direction $angle degrees from the slope"
done
[[ $(csv_value "$work/f10/figure10.csv" 1 ramp) == 0.0 && $(csv_value "$work/f9/figure9.csv" 1 ramp) == 1.0 ]] \
  && ok || bad "figure10 has no ramp, figure9 the one asked (the paper's Figure 9 has the vertical ramp)"
# The ramp's drift 1 x (h_y, -h_x) = (0, -3) over t = 0.25: along the contour lines, at 90 degrees to the slope.
holds "85 <= $(csv_value "$work/f9/figure9.csv" 1 mean_to_slope_deg) <= 95" && ok || bad "figure9: the drift is not along the contours"
holds "abs($(csv_value "$work/f9/figure9.csv" 1 mean_dy) + 0.75) < 0.15" && ok || bad "figure9: mean dy is not the ramp's -0.75"

# The thread count changes nothing but the seconds.
"$bin" reproduce figure10 --slope 3,0 --grid 24 --rk4-steps 16 --segments 8 --image 64 --threads 1 --out "$work/f10t" -q >/dev/null 2>&1
cmp -s "$work/f10/figure10_traces.csv" "$work/f10t/figure10_traces.csv" && cmp -s "$work/f10/figure10_traces.png" "$work/f10t/figure10_traces.png" \
  && ok || bad "figure10 depends on the thread count"
"$bin" reproduce figure7 --width 48 --rk4-steps 16 --threads 1 --out "$work/f7t" -q >/dev/null 2>&1
cmp -s <(cut -d, -f1-11 "$work/f7/figure7.csv") <(cut -d, -f1-11 "$work/f7t/figure7.csv") \
  && cmp -s "$work/f7/figure7_profile.csv" "$work/f7t/figure7_profile.csv" && ok || bad "figure7 depends on the thread count"

# Every CSV: one type per column, reals with a decimal point or an exponent.
python3 "$here/check_csv_types.py" "$work"/f6/*.csv "$work"/f7/*.csv "$work"/f9/*.csv "$work"/f10/*.csv >"$work/types" 2>&1 \
  && ok || bad "CSV types: $(cat "$work/types")"
grep -q "^rk4-32,32,none,[0-9.e+-]*,[0-9.e+-]*,[0-9.e+-]*,[0-9]*,[0-9.e+-]*$" "$work/f6/figure6.csv" && ok || bad "figure6.csv row format"
! grep -E -q "(^|,)-?[0-9]+(,|$)" <(cut -d, -f4-6 "$work/f6/figure6.csv" | tail -n +2) && ok || bad "figure6.csv: a real written as an integer"

# Bad input: one line, non-zero exit, no folder made.
expect_error "figure6 odd width" "" "width" reproduce figure6 --width 33 --out "$work/bad6"
[[ ! -e $work/bad6 ]] && ok || bad "a refused figure6 made its folder"
expect_error "figure7 transition width" "" "boundary-width" reproduce figure7 --boundary-width 0.3 --out "$work/bad7"
[[ ! -e $work/bad7 ]] && ok || bad "a refused figure7 made its folder"
expect_error "figure9 flat slope" "" "slope" reproduce figure9 --slope 0,0 --out "$work/bad9"
[[ ! -e $work/bad9 ]] && ok || bad "a refused figure9 made its folder"
expect_error "figure10 steps not a multiple" "" "rk4-steps" reproduce figure10 --rk4-steps 10 --segments 4 --out "$work/bad10"
[[ ! -e $work/bad10 ]] && ok || bad "a refused figure10 made its folder"
expect_error "figure6 bad time" "" "trace-time" reproduce figure6 --trace-time -1 --out "$work/bad6b"
[[ ! -e $work/bad6b ]] && ok || bad "a refused figure6 made its folder"

# figure9's default surface: the slope along x with the hill in the middle (issue 44): its particles near the centre
# circle the hill (the paper's central vortex), those of the plane alone do not.
"$bin" reproduce figure9 --grid 24 --rk4-steps 32 --segments 16 --image 64 --out "$work/f9h" -q >/dev/null 2>"$work/err" &&
  ok || bad "figure9 (default surface): $(cat "$work/err")"
turns=$(csv_value "$work/f9h/figure9.csv" 1 centre_turns)
holds "abs($turns) > 0.3" && ok || bad "figure9: the particles by the hill turn $turns times about it"
[[ $(csv_value "$work/f9/figure9.csv" 1 centre_turns) == 0.0 ]] && ok || bad "figure9 without a hill counts turns"
grep -q "Central vortex" "$work/f9h/figure9.md" && ok || bad "figure9.md does not read the central vortex"
finish test_cli_surface_figures
