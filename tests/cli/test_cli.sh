#!/usr/bin/env bash
# Command-line tests: run the real binary ($DFVN_SAMPLE) and check exit codes, messages and files.
set -u
source "$(dirname "${BASH_SOURCE[0]}")/harness.sh"

# --help and --version
"$bin" --version >"$work/out" 2>&1 && grep -q "^dfvn-sample [0-9]" "$work/out" && ok || bad "--version"
"$bin" field --help >"$work/out" 2>&1 && grep -q -- "--frequency" "$work/out" && ok || bad "field --help"

# field: header, columns, precision
printf 'x0,x1,x2\n0.1,0.2,0.3\n' | "$bin" field --dim 3 --seed 5 >"$work/f.csv" 2>"$work/err" && ok || bad "field run"
head -1 "$work/f.csv" | grep -qx "x0,x1,x2,c0,c1,c2,f1,f2" && ok || bad "field header: $(head -1 "$work/f.csv")"
[[ $(sed -n 2p "$work/f.csv" | awk -F, '{print NF}') -eq 8 ]] && ok || bad "field column count"
sed -n 2p "$work/f.csv" | cut -d, -f1 | grep -qx "0.10000000000000001" && ok || bad "17 significant digits"

# field: bad input names the line and the problem
expect_error "wrong column count" "1,2,3\n0.5,0.5\n" "" field --dim 3
expect_message "wrong column count" "line 2: expected 3 comma-separated columns"
expect_error "non-numeric" "1,2,3\n1,zz,3\n" "" field --dim 3
expect_message "non-numeric" "line 2, column 2: 'zz' is not a number"
expect_error "nan" "1,2,nan\n" "" field --dim 3
expect_message "nan" "line 1, column 3: 'nan' is not a finite number"
expect_error "inf" "1,2,3\n4,inf,6\n" "" field --dim 3
expect_message "inf" "line 2, column 2"
expect_error "dim too large" "" "" field --dim 9
expect_message "dim too large" "dim"
expect_error "dim too small" "" "" field --dim 1
expect_error "negative frequency" "" "" field --dim 3 --frequency -2
expect_message "negative frequency" "must be a number in \[2\^-50, 2\^50\]"
expect_error "nan frequency" "" "" field --dim 3 --frequency nan
expect_error "missing input file" "" "" field --dim 3 --input "$work/does-not-exist.csv"
expect_error "unknown option" "" "" field --dim 3 --bogus
expect_error "unwritable output" "0,0,0\n" "" field --dim 3 --output "$work/no/such/dir/out.csv"

# No partial output file when the input is bad.
printf '1,2,3\n4,5\n' | "$bin" field --dim 3 --output "$work/partial.csv" 2>/dev/null
[[ ! -e $work/partial.csv ]] && ok || bad "partial output file left behind"
ls "$work" | grep -q "\.tmp\." && bad "temporary file left behind" || ok

# Same seed, same bytes, whatever the thread count.
awk 'BEGIN { for (i = 0; i < 20000; ++i) printf "%.6f,%.6f,%.6f,%.6f,%.6f\n", i*0.013, i*0.007, -i*0.011, i*0.005, i*0.017 }' >"$work/p5.csv"
"$bin" field --dim 5 --seed 9 --threads 1 --input "$work/p5.csv" --output "$work/t1.csv" &&
  "$bin" field --dim 5 --seed 9 --threads 2 --input "$work/p5.csv" --output "$work/t2.csv" &&
  cmp -s "$work/t1.csv" "$work/t2.csv" && ok || bad "field output differs between 1 and 2 threads"
"$bin" field --dim 5 --seed 10 --input "$work/p5.csv" --output "$work/s10.csv" && ! cmp -s "$work/t1.csv" "$work/s10.csv" && ok || bad "seed has no effect"

# sample (the default subcommand)
"$bin" --dim 3 --grid 5 --quiet >"$work/s.csv" 2>"$work/err" && ok || bad "default subcommand: $(cat "$work/err")"
head -1 "$work/s.csv" | grep -q "^dim,grid,method,points,nn_min,nn_q01,nn_median,nn_mean,nn_median_scaled,rms_displacement,median_displacement,frac_unmoved,neighbour_disorder,lattice_order,seconds_generate,seconds_stats,seed" &&
  ok || bad "stats header: $(head -1 "$work/s.csv")"
# lattice methods fill the displacement columns, the others leave them empty
awk -F, '$3 == "cnj" || $3 == "jitter" || $3 == "jitter-matched" { if ($10 == "" || $14 == "") exit 1 } $3 == "pds" || $3 == "sobol" { if ($10 != "" || $14 != "") exit 1 }' "$work/s.csv" &&
  ok || bad "displacement columns: $(cat "$work/s.csv")"
# field --diagnose: one CSV row, and --noise is checked
"$bin" field --diagnose --dim 4 --noise turning-bands --diagnose-points 2000 >"$work/d.csv" 2>"$work/err" &&
  [[ $(wc -l <"$work/d.csv") -eq 2 ]] && head -1 "$work/d.csv" | grep -q "^dim,noise,frequency" && ok || bad "field --diagnose: $(cat "$work/err")"
expect_error "unknown noise basis" "" "" field --dim 3 --noise perlin9
"$bin" reproduce table1 --help 2>&1 | grep -q -- "--noise" && "$bin" sample --help 2>&1 | grep -q -- "--noise" && ok ||
  bad "--noise on reproduce table1 and sample"
[[ $(wc -l <"$work/s.csv") -eq 6 ]] && ok || bad "stats rows (cnj, jitter-matched, jitter, pds, sobol)"
# jitter-matched moves exactly as far as CNJ (column 10: rms_displacement).
awk -F, '$3 == "cnj" { c = $10 } $3 == "jitter-matched" { j = $10 } END { exit !(c != "" && c == j) }' "$work/s.csv" &&
  ok || bad "jitter-matched RMS displacement: $(cut -d, -f3,10 "$work/s.csv")"
"$bin" sample --help >"$work/out" 2>&1 && grep -q -- "--step-scale" "$work/out" && grep -q -- "--protocol" "$work/out" && ok || bad "sample --help"
expect_error "sample dim" "" "" --dim 9 --grid 4
expect_error "sample grid" "" "" --dim 3 --grid 1
expect_message "sample grid" "grid"
expect_error "sample memory" "" "" --dim 8 --grid 40 --max-memory 1
expect_message "sample memory" "PiB of memory \(limit 1.00 GiB\).*--max-memory"
expect_error "sample method" "" "" --dim 3 --grid 4 --methods cnj,bogus
expect_message "sample method" "unknown method 'bogus'"
expect_error "sample duplicate method" "" "" --dim 3 --grid 4 --methods cnj,cnj
expect_error "sample step scale" "" "" --dim 3 --grid 4 --step-scale 0
expect_error "sample step scale nan" "" "" --dim 3 --grid 4 --step-scale nan
expect_error "sample frequency" "" "" --dim 3 --grid 4 --cycles-per-spacing -1
expect_error "sample reproject" "" "" --dim 3 --grid 4 --reproject bogus
expect_error "sample protocol" "" "" --dim 3 --grid 4 --protocol bogus
expect_error "sample pds radius" "" "" --dim 3 --grid 4 --pds-radius -0.1
expect_error "sample stats path" "" "" --dim 3 --grid 4 --stats "$work/no/such/dir/stats.csv"
[[ ! -e $work/no ]] && ok || bad "directory created for a bad --stats path"

# Points: CSV and NPY, same bytes on 1 and 2 threads.
"$bin" --dim 4 --grid 6 --methods cnj,jitter,sobol,random,pds --points "$work/p1" --threads 1 --quiet --stats "$work/st1.csv" &&
  "$bin" --dim 4 --grid 6 --methods cnj,jitter,sobol,random,pds --points "$work/p2" --threads 2 --quiet --stats "$work/st2.csv" &&
  ok || bad "points run"
for m in cnj jitter sobol random pds; do
  cmp -s "$work/p1/$m.csv" "$work/p2/$m.csv" && ok || bad "$m points differ between 1 and 2 threads"
done
head -1 "$work/p1/cnj.csv" | grep -qx "x0,x1,x2,x3" && ok || bad "points header"
"$bin" --dim 4 --grid 6 --methods jitter --points "$work/npy" --format npy --quiet >/dev/null && ok || bad "npy run"
if /usr/bin/python3 -c "import numpy" 2>/dev/null; then
  /usr/bin/python3 - "$work/npy/jitter.npy" "$work/p1/jitter.csv" <<'PY' && ok || bad "npy does not load or differs from csv"
import sys, numpy as np
a = np.load(sys.argv[1])
b = np.loadtxt(sys.argv[2], delimiter=",", skiprows=1)
assert a.dtype == np.float64 and a.shape == (1296, 4) and a.flags.c_contiguous, (a.dtype, a.shape)
assert np.array_equal(a, b)
PY
fi

# CNJ on the torus (the default), in a domain (Eq. 13 or the ramp) and on the sphere
"$bin" --dim 4 --grid 6 --methods cnj --quiet --stats "$work/torus.csv" 2>"$work/err" && ok || bad "torus run: $(cat "$work/err")"
# Columns: 4 points, 19 domain, 25 dropped, 32 notes.
awk -F, '$3 == "cnj" && $4 == 1296 && $19 == "torus" && $25 == "0" && /,conformant,[a-z-]*,"/ { found = 1 } END { exit !found }' "$work/torus.csv" &&
  ok || bad "torus CNJ keeps all 6^4 points: $(tail -1 "$work/torus.csv")"
for bound in eq13 ramp; do
  "$bin" --dim 4 --grid 6 --methods cnj --domain cube --bound $bound --quiet --stats "$work/dom.csv" 2>"$work/err" &&
    ok || bad "conformant run: $(cat "$work/err")"
  awk -F, '$3 == "cnj" && $4 == 1296 && $19 == "cube" && $25 == "0" && /,conformant,[a-z-]*,"/ { found = 1 } END { exit !found }' "$work/dom.csv" &&
    ok || bad "conformant CNJ ($bound) keeps all 6^4 points: $(tail -1 "$work/dom.csv")"
done
"$bin" --dim 4 --grid 6 --methods cnj --domain cube --domain-mode drop --quiet --stats "$work/drop.csv" && ok || bad "drop run"
grep -q ",cube,.*,drop,,\"\"$" "$work/drop.csv" && ok || bad "drop mode named in the notes"
"$bin" --dim 3 --grid 8 --methods cnj --domain ball --quiet --stats "$work/ball.csv" && ok || bad "ball run"
awk -F, '$1 == 3 && $2 == 8 && $3 == "cnj" && $19 == "ball" && $25 == "0" && /,conformant,[a-z-]*,"/ { found = 1 } END { exit !found }' "$work/ball.csv" &&
  ok || bad "ball: $(tail -1 "$work/ball.csv")"
"$bin" --dim 4 --grid 6 --on sphere --quiet --no-timing --stats "$work/sphere.csv" && ok || bad "sphere run"
[[ $(grep -c ",fair,sphere,2.0," "$work/sphere.csv") -eq 2 ]] && ok || bad "sphere: cnj and random rows: $(cat "$work/sphere.csv")"
"$bin" --dim 4 --grid 6 --domain sphere --quiet --no-timing --stats "$work/sphere2.csv" && cmp -s "$work/sphere.csv" "$work/sphere2.csv" && ok ||
  bad "--domain sphere is --on sphere"
expect_error "sample domain" "" "" --dim 3 --grid 4 --domain klein
expect_error "torus drop" "" "torus has no boundary" --dim 3 --grid 4 --domain torus --domain-mode drop
expect_error "torus bound" "" "--bound applies to conformant CNJ" --dim 3 --grid 4 --domain torus --bound ramp
# Without --domain, options that need a boundary put CNJ in the cube.
"$bin" --dim 3 --grid 4 --methods cnj --domain-mode drop -q | grep -q ",cube,.*,drop,,\"\"$" &&
  "$bin" --dim 3 --grid 4 --methods cnj --bound ramp -q | grep -q ",cube,.*,conformant,,\"\"$" && ok ||
  bad "--domain-mode drop or --bound without --domain: the cube"
expect_error "drop boundary width" "" "--boundary-spacings applies" --dim 3 --grid 4 --domain cube --domain-mode drop --boundary-spacings 1
expect_error "torus simplex" "" "periodic noise basis" --dim 3 --grid 4 --noise simplex
expect_error "jitter-matched ball" "" "jitter-matched" --dim 3 --grid 4 --domain ball --methods cnj,jitter-matched
expect_error "field bound without a boundary" "" "--bound applies to --domain cube or ball" field --dim 3 --bound ramp
expect_error "field diagnose cube" "" "--diagnose measures" field --diagnose --domain cube
# stats --periodic: minimum-image distances; two points across a face are neighbours.
printf '0.01,0.5\n0.98,0.5\n0.5,0.1\n' >"$work/across.csv"
"$bin" stats --input "$work/across.csv" --periodic --no-timing -o "$work/across.stats" && awk -F, 'NR == 2 { exit !($5 + 0 > 0.0299 && $5 + 0 < 0.0301) }' "$work/across.stats" &&
  ok || bad "stats --periodic: $(cat "$work/across.stats")"
"$bin" field --diagnose --domain torus --dim 3 --diagnose-points 2000 >"$work/td.csv" && grep -q ",torus$" "$work/td.csv" &&
  ok || bad "field --diagnose --domain torus: $(cat "$work/td.csv")"
expect_error "sample domain mode" "" "" --dim 3 --grid 4 --domain-mode keep
expect_error "sphere in 2D" "" "" --dim 2 --grid 4 --on sphere
expect_message "sphere in 2D" "needs --dim 3..8"
expect_error "sphere methods" "" "" --dim 3 --grid 4 --on sphere --methods cnj,pds
# A huge lattice is refused at once, not counted site by site.
expect_error "ball memory" "" "" --dim 8 --grid 100 --domain ball --max-memory 1
expect_error "sphere memory" "" "" --dim 8 --grid 100 --on sphere --max-memory 1
# The ball's RDF, edge-corrected by the lens of two balls.
"$bin" --dim 3 --grid 8 --domain ball --methods cnj,random --rdf "$work/ballrdf.csv" -q -o /dev/null && ok || bad "ball rdf"
expect_finite "ball rdf" "$work/ballrdf.csv"

# RDF output
"$bin" --dim 3 --grid 6 --methods jitter,random --rdf "$work/rdf.csv" --rdf-bins 10 --quiet >/dev/null && ok || bad "rdf run"
head -1 "$work/rdf.csv" | grep -qx "dim,method,r,g" && [[ $(wc -l <"$work/rdf.csv") -eq 21 ]] && ok || bad "rdf csv shape"

# reproduce
expect_error "reproduce dims" "" "" reproduce table1 --dims 2-9 --out "$work/r1"
expect_message "reproduce dims" "Table 1 covers dimensions 3..7"
expect_error "reproduce dims text" "" "" reproduce table1 --dims x --out "$work/r1"
expect_error "reproduce width" "" "" reproduce table2 --width 1 --out "$work/r2"
expect_error "reproduce which" "" "" reproduce table3
expect_error "reproduce setting" "" "" reproduce table2 --setting paper --out "$work/r2"
expect_error "reproduce samples" "" "" reproduce table2 --samples 3 --out "$work/r2"
expect_error "reproduce second width" "" "" reproduce table2 --width 32 --height 18 --second-width 3 --out "$work/r2"
expect_message "reproduce second width" "second resolution is too small"
"$bin" reproduce table2 --width 32 --height 18 --second-width 16 --out "$work/r2" --quiet >"$work/t2.md" 2>"$work/err" && ok || bad "reproduce table2: $(cat "$work/err")"
for f in table2.csv table2.md timeline.csv source.png reference.png rk4-64-newton1.png euler-512.png time-0.5.png; do
  [[ -s $work/r2/$f ]] && ok || bad "reproduce table2 wrote no $f"
done
grep -q "paper Euler RMSE" "$work/t2.md" && ok || bad "table2.md on stdout"
grep -q "Setting \`shader\`" "$work/r2/table2.md" && ok || bad "table2 default is the shader's setting"
echo "0.1,0.2" | "$bin" field --dim 2 --noise quintic-gradient >"$work/qg.csv" 2>"$work/err" && ok || bad "field --noise quintic-gradient: $(cat "$work/err")"

finish "cli"
