#!/usr/bin/env bash
# Issue 23, "Hardening the new surfaces": one section per class of the outside probe, each run against
# the real binary ($DFVN_SAMPLE). The Python module's side of the classes is in tests/python, the
# library's in the GoogleTest suite, and the readers are fuzzed by tests/fuzz.
set -u
source "$(dirname "${BASH_SOURCE[0]}")/harness.sh"

# field CSV COLUMN: the value of COLUMN (by header name) in the first data row.
field() { awk -F, -v name="$2" 'NR == 1 { for (i = 1; i <= NF; ++i) if ($i == name) c = i } NR == 2 { print $c }' "$1"; }

cd "$work" || exit 1
printf 'x,y\n0.1,0.2\n0.5,0.7\n0.9,0.4\n' >p.csv

# ---------------------------------------------------------------------------------------------------
# NPY size arithmetic: shape (2^62, 8) of '<f8' with no data wrapped rows x 8 x 8 past 2^64 to 0.
python3 - <<'EOF'
import struct
header = "{'descr': '<f8', 'fortran_order': False, 'shape': (4611686018427387904, 8), }"
header += " " * ((64 - (10 + len(header) + 1) % 64) % 64) + "\n"
open("wraps.npy", "wb").write(b"\x93NUMPY\x01\x00" + struct.pack("<H", len(header)) + header.encode())
EOF
expect_error "npy shape whose size wraps" "" "wraps.npy, npy: shape \(4611686018427387904, 8\) of dtype '<f8' needs 2.951e\+20 data bytes, the file has 0" \
  stats --input wraps.npy

# ---------------------------------------------------------------------------------------------------
# Extreme scales: the statistics of a set in [0, S]^2 are those of the unit set times S, or S is refused.
printf '0,0\n1e200,1e200\n5e199,0\n' >big.csv
printf '0,0\n1e-300,1e-300\n5e-301,0\n' >small.csv
for threads in 1 2; do
  "$bin" stats --input big.csv --domain-side 1e200 --threads $threads --no-timing >big$threads.out 2>err && ok ||
    bad "domain side 1e200, $threads thread(s): $(cat err)"
  expect_finite "domain side 1e200, $threads thread(s)" big$threads.out
  [[ $(field big$threads.out nn_min) == 5e+199 && $(field big$threads.out nn_median_scaled) == 0.866025404 ]] && ok ||
    bad "domain side 1e200: $(cat big$threads.out)"
done
"$bin" stats --input small.csv --domain-side 1e-300 --no-timing >small.out 2>err && ok || bad "domain side 1e-300: $(cat err)"
expect_finite "domain side 1e-300" small.out
[[ $(field small.out nn_min) == 5e-301 && $(field small.out nn_median_scaled) == 0.866025404 ]] && ok ||
  bad "domain side 1e-300: $(cat small.out)"
cmp <(cut -d, -f9 big1.out) <(cut -d, -f9 small.out) >/dev/null && ok || bad "the scaled median depends on the scale"
for side in 1e+302 1e-302; do
  expect_error "domain side $side" "" "--domain-side: the side ${side/+/\\+} is outside \[2\^-1000, 2\^1000\]" \
    stats --input p.csv --domain-side $side
done
printf '0.25,0.25\n1e-200,0\n0,0\n' >tiny.csv
expect_error "neighbours closer than squares resolve" "" "closer than 2\^-510" stats --input tiny.csv

# ---------------------------------------------------------------------------------------------------
# Figures: gnuplot's work directory goes on every exit path, and gnuplot dies with us on SIGINT/SIGTERM.
mkdir -p slow failing tmp
printf '#!/bin/sh\necho $$ >"$SLOW_PID_FILE"\nexec sleep 60\n' >slow/gnuplot
printf '#!/bin/sh\necho "broken on purpose" >&2\nexit 3\n' >failing/gnuplot
chmod +x slow/gnuplot failing/gnuplot
set -m  # job control: SIGINT reaches a background job
for signal in TERM INT; do
  rm -f slow.pid
  SLOW_PID_FILE=$work/slow.pid TMPDIR=$work/tmp PATH="$work/slow:$PATH" "$bin" stats --input p.csv --spectrum spec-$signal \
    --spectrum-frequency 2 -q >/dev/null 2>err &
  pid=$!
  for ((i = 0; i < 3000; ++i)); do [[ -s slow.pid ]] && break; sleep 0.02; done  # up to 60 s under ASan
  if [[ ! -s slow.pid ]]; then
    bad "SIG$signal: gnuplot never started: $(cat err)"
    kill "$pid"
    wait "$pid"
    continue
  fi
  gnuplot_pid=$(cat slow.pid)
  [[ -n $(find tmp -name 'dfvn-plot-*') ]] && ok || bad "SIG$signal: no work directory while gnuplot runs"
  kill "-$signal" "$pid"
  wait "$pid"
  rc=$?
  [[ $rc -eq $((128 + $(kill -l $signal))) ]] && ok || bad "SIG$signal: exit status $rc"
  kill -0 "$gnuplot_pid" 2>/dev/null && bad "SIG$signal: gnuplot ($gnuplot_pid) outlived dfvn-sample" || ok
  [[ -z $(ls -A tmp) ]] && ok || bad "SIG$signal: left in TMPDIR: $(ls -A tmp)"
  [[ ! -e spec-$signal.png ]] && ok || bad "SIG$signal: a figure was written"
done
set +m
TMPDIR=$work/tmp PATH="$work/failing:$PATH" "$bin" stats --input p.csv --spectrum spec-fail --spectrum-frequency 2 -q >/dev/null 2>err
[[ $? -ne 0 && -z $(ls -A tmp) ]] && ok || bad "a failing gnuplot left its work directory: $(ls -A tmp); $(cat err)"
saved_tmpdir=${TMPDIR-}
export TMPDIR=$work/no-such-folder
expect_error "missing TMPDIR" "" \
  "cannot draw the figures: the temporary folder '.*no-such-folder' \(TMPDIR\) is not a directory; set TMPDIR to a writable directory" \
  stats --input p.csv --spectrum spec-tmp
if [[ -n $saved_tmpdir ]]; then export TMPDIR=$saved_tmpdir; else unset TMPDIR; fi
[[ ! -e spec-tmp.csv ]] && ok || bad "missing TMPDIR: the spectrum was written before the check"

# ---------------------------------------------------------------------------------------------------
# Outputs of one run on one file: one check, every subcommand.
expect_error "stats -o over the spectrum" "" "--output and --spectrum \(P.csv\) would write the same file" \
  stats --input p.csv --spectrum P -o P.csv
expect_error "stats --json over the spectrum" "" "--json and --spectrum \(P_radial.csv\) would write the same file" \
  stats --input p.csv --spectrum P --json P_radial.csv
[[ ! -e P.csv && ! -e P_radial.csv && ! -e P.png ]] && ok || bad "a refused run wrote: $(ls P* 2>/dev/null)"
mkdir -p linked
ln -s table1.csv linked/rdf.csv
expect_error "reproduce outputs through a link" "" "--out \(table1.csv\) and --out \(rdf.csv\) would write the same file" \
  reproduce table1 --dims 3 --realizations 1 --out linked
"$bin" reproduce table2 --width 16 --height 8 --second-width 0 --out t2 -q >t2.txt 2>err && ok || bad "table2: $(cat err)"
# The outputs checked before the run are the outputs written (reproduce/table2.cpp, table2_output_files).
[[ $(ls t2 | wc -l) -eq 21 ]] && ok ||
  bad "table2 wrote $(ls t2 | wc -l) files, expected 21 (3 texts, 12 variants, 3 times, source, reference, figure)"

# ---------------------------------------------------------------------------------------------------
# The spectrum of identical points: a constant power, whose anisotropy is not written as -inf.
printf '0.3,0.4\n0.3,0.4\n0.3,0.4\n' >same_points.csv
"$bin" stats --input same_points.csv --spectrum same --spectrum-frequency 4 -q >same.out 2>err && ok || bad "identical points: $(cat err)"
expect_finite "identical points" same.out same.csv same_radial.csv
[[ $(cut -d, -f3 same_radial.csv | sort -u | tr -d '\n') == anisotropy_db ]] && ok ||
  bad "the anisotropy of a constant spectrum: $(cat same_radial.csv)"

# ---------------------------------------------------------------------------------------------------
# Seeds s..s+R-1 never wrap past 2^64 - 1.
wrap="needs seeds up to 18446744073709551614 \+ 2, past 2\^64 - 1"
expect_error "sample seeds wrap" "" "--seed 18446744073709551614 with --realizations 3 $wrap" \
  -d 2 --grid 4 --methods jitter --seed 18446744073709551614 --realizations 3
expect_error "table1 seeds wrap" "" "with --realizations 3 $wrap" reproduce table1 --dims 3 --seed 18446744073709551614 --realizations 3 --out r1
expect_error "integration seeds wrap" "" "with --realizations 3 $wrap" reproduce integration --dims 3 --seed 18446744073709551614 --realizations 3 --out ri
expect_error "cnj-study seeds wrap" "" "with --realizations 3 $wrap" reproduce cnj-study --dims 3 --seed 18446744073709551614 --realizations 3 --out rc
[[ ! -e r1 && ! -e ri && ! -e rc ]] && ok || bad "a refused reproduction made its folder"
"$bin" -d 2 --grid 4 --methods jitter --seed 18446744073709551613 --realizations 3 -q --no-timing >seeds.csv 2>err &&
  grep -q ',18446744073709551615,' seeds.csv && ok || bad "the last seed 2^64 - 1: $(cat err)"

# ---------------------------------------------------------------------------------------------------
# Reports name only what was run.
expect_error "integration methods repeated" "" "--methods names 'cnj' twice" reproduce integration --methods cnj,cnj --out ri
expect_error "integration below the smallest 7D lattice" "" "--max-points 64 is below the smallest lattice of 7D, 2\^7 = 128 points" \
  reproduce integration --dims 3,7 --max-points 64 --out ri
"$bin" reproduce integration --dims 3 --max-points 64 --realizations 2 --methods cnj,random --out ri -q >ri.txt 2>err &&
  ok || bad "integration of one size: $(cat err)"
! grep -q "0\.0000" ri/integration_slopes.csv && [[ $(cut -d, -f4 ri/integration_slopes.csv | sort -u | tr -d '\n') == slope ]] &&
  ok || bad "slopes from one size: $(head -3 ri/integration_slopes.csv)"
! grep -E -q "jitter's|Why CNJ loses|Sobol|Poisson|[4-7]D" ri/integration.md && ok ||
  bad "the integration reading names what was not run: $(grep -E -o ".{30}(jitter's|Why CNJ loses|Sobol|Poisson|[4-7]D).{20}" ri/integration.md | head -2)"
! grep -E -q "RMSE 384|at 384,|RMSE 8 " t2/table2.md t2.txt && ok || bad "table2 --second-width 0 reports a second resolution"
[[ $(cut -d, -f11 t2/table2.csv | sort -u | tr -d '\n') == rmse_second ]] && ok || bad "table2.csv: rmse_second without a second resolution"

# ---------------------------------------------------------------------------------------------------
# Escaping of odd file names in the CSV and the JSON.
cp p.csv 'q"uo.csv'
"$bin" stats --input 'q"uo.csv' --no-timing >quote.out 2>err && ok || bad "q\"uo.csv: $(cat err)"
[[ $(python3 -c 'import csv, sys; print(list(csv.reader(open(sys.argv[1])))[1][0])' quote.out) == 'q"uo.csv' ]] && ok ||
  bad "q\"uo.csv in the CSV: $(sed -n 2p quote.out)"
odd=$(printf 'odd\xff.csv')
cp p.csv "$odd"
"$bin" stats --input "$odd" --json odd.json -o odd.out 2>err && ok || bad "a name with 0xFF and --json: $(cat err)"
python3 -c 'import json, sys; assert json.load(open(sys.argv[1]))["parameters"]["input"] == "odd\ufffd.csv"' odd.json && ok ||
  bad "0xFF in the JSON: $(grep input odd.json | cat -v)"

# ---------------------------------------------------------------------------------------------------
# One number parser: the dat reader refuses what the CSV reader refuses.
printf '0.1 +-0\n0.2 0.3\n' >signs.dat
printf '++0.5 0.1\n0.2 0.3\n' >signs2.dat
expect_error "dat +-0" "" "signs.dat, line 1, column 2: '\+-0' is not a number" stats --input signs.dat
expect_error "dat ++0.5" "" "signs2.dat, line 1, column 1: '\+\+0.5' is not a number" stats --input signs2.dat

# ---------------------------------------------------------------------------------------------------
# Messages name the option the user gave.
expect_error "cnj-study frequency" "" "--cycles-per-spacing 1e\+14 is a field frequency of 1.2e\+15 cycles per unit length in 3D" \
  reproduce cnj-study --dims 3 --cycles-per-spacing 1e14 --out rc
expect_error "-n beyond memory" "" "-n 1099511627776 in 3D gives 1099511627776 points, which need about" \
  -d 3 -n 1099511627776 --methods random
! grep -q -- "--grid" err && ok || bad "-n mentions --grid: $(cat err)"

finish "cli_surfaces"
