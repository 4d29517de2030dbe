#!/usr/bin/env bash
# Command-line tests of `dfvn-sample animate` and `reproduce figure8` (src/animate/, src/reproduce/figure8.*):
# the files and their shapes, the conformant run's counts, drop mode's NaN rows, every real with a
# decimal point, and bad input refused with one line, a non-zero exit and no file.
set -u
source "$(dirname "${BASH_SOURCE[0]}")/harness.sh"

py=/usr/bin/python3
is_png() { [[ -s $1 && $(head -c 8 "$1" | od -An -tx1 | tr -d ' \n') == 89504e470d0a1a0a ]]; }

# 2D conformant: every frame holds every particle; the files are there.
"$bin" animate --dim 2 --grid 8 --frames 40 --out "$work/c2" --quiet >"$work/out" 2>"$work/err" && ok || bad "animate 2D: $(cat "$work/err")"
for f in frames.npy frames.csv trails.csv; do [[ -s $work/c2/$f ]] && ok || bad "animate 2D wrote no $f"; done
if command -v gnuplot >/dev/null; then is_png "$work/c2/animation.png" && ok || bad "animate 2D drew no animation.png"; fi
grep -q "inside per frame: 64..64; entered 0, left 0" "$work/out" && ok || bad "animate 2D summary: $(cat "$work/out")"
[[ $(head -1 "$work/c2/frames.csv") == frame,phase,inside,entered,left,largest_jump,rms_move,retraced,kept_at_start,projected,nn_min,nn_q01,nn_median,nn_median_scaled ]] \
  && ok || bad "frames.csv header: $(head -1 "$work/c2/frames.csv")"
[[ $(wc -l <"$work/c2/frames.csv") -eq 41 ]] && ok || bad "frames.csv: one row per frame"
awk -F, 'NR > 1 && ($3 != 64 || $4 != 0 || $5 != 0) { exit 1 }' "$work/c2/frames.csv" && ok || bad "conformant frames.csv: a particle left"
awk -F, 'NR > 1 && ($2 !~ /[.e]/ || $6 !~ /[.e]/ || $7 !~ /[.e]/ || $11 !~ /[.e]/ || $14 !~ /[.e]/) { exit 1 }' "$work/c2/frames.csv" && ok || bad "frames.csv: a real without a decimal point"
grep -q "cnj mode: frame k is CNJ of the start sites" "$work/out" && grep -q "^packing: median nearest-neighbour distance" "$work/out" \
  && grep -q "^per-frame moves (frame 0's mean spacings): median" "$work/out" && ok || bad "animate summary: $(cat "$work/out")"
# --mode advect: today's mode before issue 46, still there; a bad mode is refused.
"$bin" animate --dim 2 --grid 6 --frames 10 --mode advect --out "$work/adv" --quiet >"$work/out" 2>"$work/err" && ok || bad "animate advect: $(cat "$work/err")"
grep -q "advect mode: frame 0 is CNJ, frame k is frame k-1 traced" "$work/out" && ok || bad "advect summary: $(cat "$work/out")"
expect_error "bad mode" "" "mode" animate --dim 2 --grid 4 --mode flow --out "$work/bad1"
if [[ -x $py ]] && $py -c 'import numpy' 2>/dev/null; then
  $py - "$work/c2/frames.npy" <<'PY' && ok || bad "frames.npy of the conformant run"
import sys, numpy as np
a = np.load(sys.argv[1])
assert a.shape == (40, 64, 2), a.shape
assert np.isfinite(a).all() and (a >= 0).all() and (a <= 1).all()
assert (np.abs(np.diff(a, axis=0)) > 0).any()
PY
fi

# 3D drop mode with the bcc start lattice: NaN rows for the particles outside, popping events.
"$bin" animate --dim 3 --grid 4 --lattice bcc --frames 60 --domain-mode drop --drop-margin 1 --out "$work/d3" --quiet \
  >"$work/out" 2>"$work/err" && ok || bad "animate 3D drop: $(cat "$work/err")"
grep -q "341 particles (bcc lattice, drop mode in the cube)" "$work/out" && ok || bad "6^3 + 5^3 bcc sites: $(cat "$work/out")"
awk -F, 'NR > 2 { events += $4 + $5 } END { exit !(events > 0) }' "$work/d3/frames.csv" && ok || bad "drop mode did not pop"
if [[ -x $py ]] && $py -c 'import numpy' 2>/dev/null; then
  $py - "$work/d3/frames.npy" "$work/d3/frames.csv" <<'PY' && ok || bad "frames.npy's NaN rows are the particles outside"
import sys, csv, numpy as np
a = np.load(sys.argv[1])
rows = list(csv.DictReader(open(sys.argv[2])))
assert a.shape == (60, 341, 3), a.shape
for k, r in enumerate(rows):
    shown = ~np.isnan(a[k, :, 0])
    assert shown.sum() == int(r["inside"]), (k, shown.sum(), r["inside"])
    assert (np.isnan(a[k]).all(axis=1) == ~shown).all()
PY
fi
# 5D: no figure, the two data files.
"$bin" animate --dim 5 --grid 2 --frames 5 --out "$work/c5" --quiet >/dev/null 2>"$work/err" && ok || bad "animate 5D: $(cat "$work/err")"
[[ -s $work/c5/frames.npy && ! -e $work/c5/trails.csv && ! -e $work/c5/animation.png ]] && ok || bad "animate 5D files: $(ls "$work/c5")"
# The same seed gives the same bytes, whatever the thread count.
"$bin" animate --dim 2 --grid 8 --frames 40 --threads 1 --out "$work/c2t" --quiet >/dev/null 2>&1
cmp -s "$work/c2/frames.npy" "$work/c2t/frames.npy" && cmp -s "$work/c2/frames.csv" "$work/c2t/frames.csv" \
  && ok || bad "animate depends on the thread count"

# Bad input: one line, non-zero exit, no output folder.
expect_error "nan phase step" "" "phase step" animate --dim 2 --grid 4 --phase-step nan --out "$work/bad1"
expect_error "inf phase step" "" "phase step" animate --dim 2 --grid 4 --phase-step inf --out "$work/bad1"
expect_error "zero phase step" "" "phase step" animate --dim 2 --grid 4 --phase-step 0 --out "$work/bad1"
expect_error "nan phase" "" "phase" animate --dim 2 --grid 4 --phase nan --out "$work/bad1"
expect_error "zero frames" "" "frames" animate --dim 2 --grid 4 --frames 0 --out "$work/bad1"
expect_error "huge frames" "" "frames" animate --dim 2 --grid 4 --frames 1000000000 --out "$work/bad1"
expect_error "too many bytes" "" "GiB" animate --dim 4 --grid 64 --frames 3000 --out "$work/bad1"
expect_error "torus" "" "torus|domain" animate --dim 2 --grid 4 --domain torus --out "$work/bad1"
[[ ! -e $work/bad1 ]] && ok || bad "a refused animate made its folder"
printf 'x' >"$work/afile"
expect_error "unwritable DIR" "" "afile" animate --dim 2 --grid 4 --frames 3 --out "$work/afile/sub"
mkdir -p "$work/ro" && chmod 555 "$work/ro"
if [[ ! -w $work/ro ]]; then
  expect_error "read-only DIR" "" "ro" animate --dim 2 --grid 4 --frames 3 --out "$work/ro/x" && ok
  [[ -z $(ls -A "$work/ro") ]] && ok || bad "a refused animate left files in a read-only folder"
fi
chmod 755 "$work/ro"

# reproduce figure8, small: both CSVs, the Markdown reading with the numbers that were run.
"$bin" reproduce figure8 --frames 30 --grid-2d 6 --grid-3d 3 --drop-margin 1 --out "$work/f8" --quiet >"$work/f8.txt" 2>"$work/err" \
  && ok || bad "figure8: $(cat "$work/err")"
for f in figure8_frames.csv figure8_tracks.csv figure8.md; do [[ -s $work/f8/$f ]] && ok || bad "figure8 wrote no $f"; done
if command -v gnuplot >/dev/null; then is_png "$work/f8/figure8.png" && ok || bad "figure8 drew no figure8.png"; fi
[[ $(grep -c '^2,drop,cubic,' "$work/f8/figure8_frames.csv") -eq 30 && $(grep -c '^3,conformant,bcc,' "$work/f8/figure8_frames.csv") -eq 30 ]] \
  && ok || bad "figure8_frames.csv: 30 frames per dimension and mode"
grep -q -- "--frames 30 --phase-step 0.05 --grid-2d 6 --grid-3d 3 --lattice-3d bcc --drop-margin 1 --seed 1" "$work/f8/figure8.md" \
  && ok || bad "figure8.md does not quote the run: $(head -5 "$work/f8/figure8.md")"
grep -q "| 2D | conformant | cubic 6^2 | 36 | 36..36 | 0 | 0 | 0.0 |" "$work/f8/figure8.md" && ok || bad "figure8.md 2D conformant row: $(grep '| 2D |' "$work/f8/figure8.md")"
grep -q "| 3D | conformant | bcc 3^3 | 35 | 35..35 | 0 | 0 | 0.0 |" "$work/f8/figure8.md" && ok || bad "figure8.md 3D conformant row: $(grep '| 3D |' "$work/f8/figure8.md")"
! grep -q "| ---" "$work/f8.txt" && ok || bad "figure8 printed Markdown"
expect_error "figure8 one frame" "" "frames" reproduce figure8 --frames 1 --out "$work/bad8"
[[ ! -e $work/bad8 ]] && ok || bad "a refused figure8 made its folder"

finish test_cli_animate
