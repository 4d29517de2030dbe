#!/usr/bin/env bash
# Issue 24, tidy outputs: every CSV that every subcommand writes has columns of one type each (all
# integers, all reals with a decimal point or an exponent, or all words; empty cells allowed), across
# its rows and across runs of the same output (check_csv_types.py says how a cell's type is read).
# Each command runs in a quick setting chosen to reach the rows where a type could slip: several
# methods and --realizations (with --summary), a dat file of several sets (with --summary), an RDF with
# empty bins (g = 0), a field frequency of 1, every reproduce subcommand.
set -u
source "$(dirname "${BASH_SOURCE[0]}")/harness.sh"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
check() { /usr/bin/python3 "$here/check_csv_types.py" "$@"; }
bin="$(cd "$(dirname "$bin")" && pwd)/$(basename "$bin")"  # the commands below run in $work
cd "$work" || exit 1

# The checker itself: a real column written "1" beside "0.5", or a word in a column of integers, fails.
# (Every table also holds data rows only: no row of a CSV is a summary of its other rows.)
printf 'seed,g\n1,0.5\n2,1\n' >bad_real.csv
printf 'seed,g\n1,0.5\nmean,0.5\n' >bad_word.csv
printf 'method,g,n\ncnj,0.5,\nsobol,1e-07,3\n,nan,\n' >good.csv
check bad_real.csv >/dev/null && bad "the checker accepts a real written as 1" || ok
check bad_word.csv >/dev/null && bad "the checker accepts 'mean' among integers" || ok
check good.csv >/dev/null && ok || bad "the checker refuses a tidy file: $(check good.csv)"
rm bad_real.csv bad_word.csv good.csv

# run NAME ARGS...: a command that must succeed; its standard output kept in NAME.stdout.
run() {
  local name=$1
  shift
  "$bin" "$@" >"$name.stdout" 2>"$name.stderr" && ok || bad "$name: exit $?: $(head -c 300 "$name.stderr")"
}

# sample: every method (2D, with the RDF and the point files), a point count, realizations (the
# statistics on standard output), the sphere, the bounded ball; the statistics with times.
run all -d 2 --grid 8 --methods cnj,jitter-matched,jitter,pds,sobol,random,halton,lhs --scramble none \
  -o all.csv --rdf all_rdf.csv --rdf-bins 40 --points pts -q
run count -d 3 -n 100 --methods pds,sobol,halton,lhs,random --domain cube --no-timing -o count.csv -q
run realizations -d 3 --grid 5 --methods cnj,jitter,pds,sobol --realizations 3 --summary realizations_summary.csv -q
run sphere --dim 3 --grid 6 --on sphere --no-timing -o sphere.csv -q
run ball --dim 3 --grid 6 --domain ball --bound ramp --methods cnj,jitter --no-timing -o ball.csv -q
run torus --dim 2 --grid 6 --domain torus --methods cnj,jitter --periodic --no-timing -o torus.csv -q
# stats: a CSV with discrepancies, a dat file of three sets (their summary), another side, the spectrum.
run stats stats --input pts/cnj.csv --discrepancy -o stats.csv -q
"$bin" -d 2 --grid 6 --methods jitter --no-stats --points - --format dat -q -s 1 >sets.dat
for s in 2 3; do echo "#" >>sets.dat && "$bin" -d 2 --grid 6 --methods jitter --no-stats --points - --format dat -q -s $s >>sets.dat; done
run stats_sets stats --input sets.dat --discrepancy --no-timing -o stats_sets.csv --summary stats_sets_summary.csv -q
awk '!/^#/ {print 2 * $1, 2 * $2; next} {print}' sets.dat >sets2.dat
run stats_side stats --input sets2.dat --format dat --domain-side 2 --periodic -o stats_side.csv -q
run stats_spectrum stats --input pts/sobol.csv --spectrum spectrum --spectrum-frequency 5 -o stats_spectrum.csv -q
# field: points from a file (lattice coordinates), the diagnosis at frequency 1 and 0.5, the cube.
run field field --input pts/jitter.csv -o field.csv
run field_cube field --input pts/cnj.csv --domain cube --frequency 2 -o field_cube.csv
run diagnose1 field --diagnose --diagnose-points 2000 --dim 3 -o diagnose1.csv
run diagnose2 field --diagnose --diagnose-points 2000 --dim 4 --frequency 0.5 --domain torus -o diagnose2.csv
# reproduce: every subcommand, small.
run table1 reproduce table1 --dims 3 --realizations 2 --out r1 -q
run table2 reproduce table2 --width 32 --height 18 --second-width 16 --out r2 -q
run cnj_study reproduce cnj-study --dims 3 --realizations 2 --cycles-per-spacing 0.5,1 --step-scales 0.5 --steps 1 --out r3 -q
run integration reproduce integration --dims 3 --realizations 2 --max-points 512 --methods jitter,random,pds --out r4 -q
run figure8 reproduce figure8 --frames 20 --grid-2d 6 --grid-3d 3 --drop-margin 1 --out r5 -q
run constructions reproduce constructions --divergence-points 1000 --speed-points 200 --trace-starts 4 --escape-starts 20 --out rc -q
run figure6 reproduce figure6 --width 16 --out r6 -q
run figure7 reproduce figure7 --width 24 --rk4-steps 8 --width-3d 12 --out r7 -q
run figure10 reproduce figure10 --grid 4 --rk4-steps 8 --segments 4 --image 32 --out r10 -q
run bridson reproduce bridson --grid 3 --trace-steps 8 --image 32 --check-points 200 --out rb -q
# animate: frames.csv and trails.csv, conformant and drop.
run animate animate --dim 2 --grid 6 --frames 30 --out a1 -q
run animate_drop animate --dim 3 --grid 3 --lattice bcc --frames 30 --domain-mode drop --drop-margin 1 --out a2 -q

mv realizations.stdout realizations.csv  # the statistics went to standard output
# Every CSV written must have been found: each command above writes at least the files named here.
for f in all.csv all_rdf.csv pts/cnj.csv pts/lhs.csv count.csv realizations.csv realizations_summary.csv sphere.csv \
  ball.csv torus.csv stats.csv stats_sets.csv stats_sets_summary.csv stats_side.csv stats_spectrum.csv spectrum.csv spectrum_radial.csv field.csv \
  field_cube.csv diagnose1.csv diagnose2.csv r1/table1.csv r1/table1_summary.csv r1/rdf.csv r2/table2.csv r2/timeline.csv \
  r3/cnj_study.csv r3/cnj_study_jitter.csv r4/integration.csv r4/integration_slopes.csv r5/figure8_frames.csv \
  r5/figure8_tracks.csv rc/constructions.csv rc/curl_obstacle.csv r6/figure6.csv r7/figure7.csv r7/figure7_profile.csv r7/figure7_constructions_3d.csv r10/figure10.csv r10/figure10_traces.csv \
  rb/bridson_checks.csv rb/bridson_octaves.csv rb/wake_traces.csv rb/ring_traces.csv \
  a1/frames.csv a1/trails.csv a2/frames.csv a2/trails.csv; do
  [[ -s $f ]] && ok || bad "$f not written"
done
mapfile -t csvs < <(find . -name '*.csv' | sort)
if out=$(check "${csvs[@]}"); then
  ok
  echo "$out"
else
  bad "columns of more than one type:"
  echo "$out" >&2
fi
finish cli_csv_types
