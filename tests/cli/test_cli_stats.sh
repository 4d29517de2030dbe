#!/usr/bin/env bash
# Command-line tests of `dfvn-sample stats --input` and `--realizations`: run the real binary
# ($DFVN_SAMPLE) on each input format and on bad files.
set -u
source "$(dirname "${BASH_SOURCE[0]}")/harness.sh"

# The sampling stats' nearest-neighbour columns; a file's points have no lattice, so no displacement columns.
header="input,set,dim,points,nn_min,nn_q01,nn_median,nn_mean,nn_median_scaled,seconds_stats,domain,domain_side,cd,wd,md,l2_star"

# The same Sobol set as CSV and NPY gives the same statistics.
"$bin" --dim 3 --grid 5 --methods sobol,jitter --domain cube --points "$work/p" --format npy --quiet >/dev/null || bad "sample npy"
"$bin" --dim 3 --grid 5 --methods sobol,jitter --domain cube --points "$work/p" --format csv --quiet >/dev/null || bad "sample csv"
for f in sobol.npy sobol.csv; do
  "$bin" stats --input "$work/p/$f" --discrepancy >"$work/$f.stats" 2>"$work/err" && ok || bad "stats $f: $(cat "$work/err")"
  head -1 "$work/$f.stats" | grep -qx "$header" && ok || bad "stats $f header: $(head -1 "$work/$f.stats")"
  [[ $(wc -l <"$work/$f.stats") -eq 2 ]] && ok || bad "stats $f: one row"
done
cut -d, -f3-9,11-16 "$work/sobol.npy.stats" >"$work/a"
cut -d, -f3-9,11-16 "$work/sobol.csv.stats" >"$work/b"
cmp -s "$work/a" "$work/b" && ok || bad "csv and npy statistics differ"
# Without --discrepancy the columns are empty.
"$bin" stats --input "$work/p/jitter.csv" | tail -1 | grep -q ",1.0,,,,$" && ok || bad "discrepancy columns not empty"
# nn_q01 is filled, the displacement columns are empty (a file's points have no lattice sites).
"$bin" stats --input "$work/p/jitter.csv" | tail -1 | awk -F, '{ exit !($6 != "" && NF == 16) }' && ok ||
  bad "stats --input nn_q01 / 16 columns"
# A headerless CSV in 1D and a dat file of two 2D sets (a row a set; --summary: mean, sd, standard error).
printf '0.1\n0.4\n0.9\n' >"$work/one.csv"
"$bin" stats --input "$work/one.csv" | tail -1 | cut -d, -f3-5 | grep -qx "1,3,0.3" && ok || bad "1D csv"
printf '# set 0\n0.1 0.2\n0.3 0.4\n0.8 0.1\n#\n0.5 0.5\n0.2 0.9\n' >"$work/two.dat"
"$bin" stats --input "$work/two.dat" --discrepancy --summary "$work/dat.summary" >"$work/dat.stats" 2>"$work/err" && ok ||
  bad "stats dat: $(cat "$work/err")"
[[ $(cut -d, -f2 "$work/dat.stats" | tr '\n' ' ') == "set 0 1 " ]] && ok || bad "dat rows: $(cat "$work/dat.stats")"
head -1 "$work/dat.summary" | grep -qx "input,dim,statistic,realizations,mean,sd,standard_error" &&
  grep -q '^"[^"]*two.dat",2,nn_min,2,' "$work/dat.summary" && grep -q ',cd,2,' "$work/dat.summary" && ok ||
  bad "dat summary: $(cat "$work/dat.summary")"
# Output does not depend on --threads (apart from the timing column).
"$bin" stats --input "$work/p/sobol.npy" --discrepancy --threads 1 | cut -d, -f1-9,11- >"$work/t1"
"$bin" stats --input "$work/p/sobol.npy" --discrepancy --threads 2 | cut -d, -f1-9,11- >"$work/t2"
cmp -s "$work/t1" "$work/t2" && ok || bad "stats depend on --threads"

# Bad files: one line naming the line, dtype or shape; no output file.
printf '0.1,0.2\n0.3\n' >"$work/ragged.csv"
expect_error "ragged csv" "" "ragged.csv, line 2: expected 2 comma-separated columns" stats --input "$work/ragged.csv" --output "$work/o.csv"
[[ ! -e $work/o.csv ]] && ok || bad "partial output after a bad file"
printf '0.1 0.2\n0.3 zz\n' >"$work/text.dat"
expect_error "text in dat" "" "line 2, column 2: 'zz' is not a number" stats --input "$work/text.dat"
printf '1,2,3,4,5,6,7,8,9\n' >"$work/wide.csv"
expect_error "9 columns" "" "9 coordinates per point; allowed 1..8" stats --input "$work/wide.csv"
printf '\x93NUMPY\x01\x00\x76\x00{'"'"'descr'"'"': '"'"'<i8'"'"', '"'"'fortran_order'"'"': False, '"'"'shape'"'"': (1, 2), }' >"$work/int.npy"
printf '%*s\n' $((118 - 59)) '' >>"$work/int.npy"
printf '\x01\x00\x00\x00\x00\x00\x00\x00\x02\x00\x00\x00\x00\x00\x00\x00' >>"$work/int.npy"
expect_error "int npy" "" "dtype '<i8' is not supported" stats --input "$work/int.npy"
expect_error "outside the domain" "" "outside the domain \[0, 0.5\]\^2; give the side with --domain-side" stats --input "$work/two.dat" --domain-side 0.5
expect_error "unknown format" "" "--format: xyz not in" stats --input "$work/two.dat" --format xyz
cp "$work/two.dat" "$work/two.pts"
expect_error "no format" "" "give --format" stats --input "$work/two.pts"
cp "$work/two.dat" "$work/two.bin"
expect_error "text named .bin" "" "two.bin, bin: .* not UTK .bin records" stats --input "$work/two.bin"
expect_error "missing file" "" "" stats --input "$work/none.csv"
expect_error "no input" "" "input" stats

# sample --realizations: R data rows per method and nothing else; --summary has their mean, sd and
# standard error, a row per method and statistic that varies (not the constant settings).
"$bin" --dim 3 --grid 4 --methods jitter,sobol --realizations 3 --seed 5 --quiet --summary "$work/r_summary.csv" \
  >"$work/r.csv" 2>"$work/err" && ok || bad "realizations: $(cat "$work/err")"
seed_column=$(head -1 "$work/r.csv" | tr ',' '\n' | grep -nx seed | cut -d: -f1)
rows=$(awk -F, -v s="$seed_column" 'NR > 1 { print $3 "," $s }' "$work/r.csv" | tr '\n' ' ')
[[ $rows == "jitter,5 sobol,5 jitter,6 sobol,6 jitter,7 sobol,7 " ]] && ok || bad "realization rows: $rows"
grep -q "^3,4,jitter,nn_min,3," "$work/r_summary.csv" && grep -q "^3,4,sobol,nn_median_scaled,3," "$work/r_summary.csv" &&
  ! grep -Eq ",(domain_side|half_width|requested|points)," "$work/r_summary.csv" && ok ||
  bad "realization summary: $(head -5 "$work/r_summary.csv")"
expect_error "summary of one" "" "--summary summarises the sets of --realizations R: give R >= 2" \
  --dim 3 --grid 4 --summary "$work/one_summary.csv"
expect_error "sets in csv" "" "--points writes the 2 sets of --sets into one file: --format dat, npy or bin" \
  --dim 3 --grid 4 --realizations 2 --points "$work/rp"
expect_error "realizations and rdf" "" "--rdf takes one realization" --dim 3 --grid 4 -m 2 --rdf "$work/rp.csv"

# stats --spectrum: 2D sets (the file's sets are averaged); not for 4D.
"$bin" --dim 2 --grid 16 --methods jitter --domain cube --points "$work/s2" --quiet >/dev/null || bad "sample 2D"
"$bin" stats --input "$work/s2/jitter.csv" --spectrum "$work/spec" --spectrum-frequency 20 >/dev/null 2>"$work/err" && ok || bad "spectrum: $(cat "$work/err")"
[[ $(wc -l <"$work/spec.csv") -eq $((41 * 41 + 1)) && $(wc -l <"$work/spec_radial.csv") -eq 21 ]] && ok || bad "spectrum files"
"$bin" --dim 4 --grid 3 --methods jitter --domain cube --points "$work/s4" --quiet >/dev/null || bad "sample 4D"
expect_error "spectrum 4D" "" "needs 2D or 3D points" stats --input "$work/s4/jitter.csv" --spectrum "$work/spec4"

# reproduce integration, small: every file and a reading.
"$bin" reproduce integration --dims 3 --realizations 2 --max-points 512 --methods cnj,jitter,random --out "$work/int" --quiet \
  >"$work/int.md" 2>"$work/err" && ok || bad "reproduce integration: $(cat "$work/err")"
for f in integration.csv integration_slopes.csv integration.md; do [[ -s $work/int/$f ]] && ok || bad "integration wrote no $f"; done
[[ $(tail -n +2 "$work/int/integration.csv" | wc -l) -eq $((6 * 3 * $(cut -d, -f4 "$work/int/integration.csv" | tail -n +2 | sort -u | wc -l))) ]] && ok || bad "integration rows"
grep -q "CNJ against the jittering" "$work/int.md" && ok || bad "integration reading"
expect_error "integration dims" "" "Table 1 covers dimensions 3..7" reproduce integration --dims 9 --out "$work/int2"
expect_error "integration realizations" "" "realizations" reproduce integration --realizations 1 --out "$work/int2"

finish "cli_stats"
