#!/usr/bin/env bash
# Behaviour unchanged (issue 21): a fixed set of commands of the real binary ($DFVN_SAMPLE), small
# sizes, --no-timing where the command has it, and every file they write (standard output and error
# included) compared with cmp against tests/cli/reference/, recorded from main 7b10613 before the
# refactor of issue 21 (re-recorded for issue 24's tidy outputs: the `stat` column, summary rows without
# a word in `seed`, every real with a decimal point; and for its vocabulary: cycles_per_spacing, the
# help of every subcommand, and -n's unit protocol). Files whose bytes hold a time are compared with the time blanked (normalise
# below says which). Run from a fixed folder with relative paths, so the paths written into the
# outputs are the same on every machine.
#
#   DFVN_SAMPLE=build/dfvn-sample tests/cli/test_cli_reference.sh            compare
#   DFVN_SAMPLE=build/dfvn-sample tests/cli/test_cli_reference.sh --record   rewrite the reference
set -u
# The reference holds gnuplot's figures (PNG, byte for byte): without gnuplot the test is skipped.
command -v gnuplot >/dev/null || { echo "gnuplot not found: skipped"; exit 77; }
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
reference="$here/reference"
bin="$(cd "$(dirname "$DFVN_SAMPLE")" && pwd)/$(basename "$DFVN_SAMPLE")"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
mkdir "$work/out"
cp "$here/../../data/points_3d_example.csv" "$work/out/points_3d.csv"
cd "$work/out" || exit 1

# run NAME ARGS...: the command's standard output and error land in NAME.stdout and NAME.stderr.
run() {
  local name=$1
  shift
  "$bin" "$@" >"$name.stdout" 2>"$name.stderr"
  echo "$?" >"$name.status"
}

# The help texts and the usage.
run usage
run help --help
run help_all --help-all
run version --version
# The main job: the default methods, realizations, a point count, the sphere, the torus.
run main --dim 3 --grid 8 --no-timing -q -o main_stats.csv --rdf main_rdf.csv --json main.json --points main_points
run main_2d --dim 2 --grid 8 --realizations 3 --no-timing -q -o main_2d.csv --json main_2d.json
run main_count -d 2 -n 200 --methods pds,sobol,halton,lhs,random --domain cube --no-timing -q -o main_count.csv \
  --points count_points --format npy
run main_sphere sample --dim 3 --grid 6 --on sphere --no-timing -q
run main_torus --dim 3 --grid 6 --domain torus --methods cnj,jitter --no-timing -q --periodic
run main_ball --dim 3 --grid 6 --domain ball --bound ramp --methods cnj --noise simplex --no-timing -q
run main_stdout --dim 2 --grid 5 --methods cnj --no-stats --points - -q
# field: points from a file and standard input, a bounded domain, the torus, the diagnosis.
run field field --input points_3d.csv -o field.csv
run field_stdin field --frequency 2 --noise simplex <points_3d.csv
run field_cube field --input points_3d.csv --domain cube --bound eq13 --boundary-width 0.2
run field_torus field --input points_3d.csv --domain torus --frequency 3
run field_torus_refused field --input points_3d.csv --domain torus --noise quintic-gradient
run field_diagnose field --diagnose --diagnose-points 2000 --dim 4
# stats: each input format, discrepancies, the torus, the spectrum.
run stats stats --input main_points/cnj.csv --discrepancy --no-timing -o stats.csv --json stats.json
run stats_npy stats --input count_points/pds.npy --periodic --no-timing
run stats_spectrum stats --input count_points/sobol.npy --spectrum spectrum --spectrum-frequency 6 --no-timing -q
# reproduce: every subcommand, small.
run table1 reproduce table1 --dims 3 --realizations 2 --out r1 -q
run table2 reproduce table2 --width 32 --height 18 --second-width 16 --out r2 -q
run cnj_study reproduce cnj-study --dims 3 --realizations 1 --cycles-per-spacing 0.5 --step-scales 0.5 --steps 1 --out r3 -q
run integration reproduce integration --dims 3 --realizations 2 --max-points 512 --methods jitter,random --out r4 -q

# Times are the only bytes allowed to differ: blanked (normalise_times.py says how), in the recording
# as in the comparison.
normalise() { /usr/bin/python3 "$here/normalise_times.py" "$1"; }

status=0
if [[ ${1:-} == --record ]]; then
  rm -rf "$reference"
  mkdir -p "$reference"
  find . -type f | sort | while read -r f; do
    mkdir -p "$reference/$(dirname "$f")"
    normalise "$f" >"$reference/$f"
  done
  echo "recorded $(find "$reference" -type f | wc -l) files in $reference"
  exit 0
fi
checked=0
while read -r f; do
  checked=$((checked + 1))
  if [[ ! -e $f ]]; then
    echo "FAIL: $f not written"
    status=1
  elif ! cmp -s <(normalise "$f") "$reference/$f"; then
    echo "FAIL: $f differs from the reference"
    diff <(normalise "$f") "$reference/$f" | head -10
    status=1
  fi
done < <(cd "$reference" && find . -type f | sort)
while read -r f; do
  [[ -e $reference/$f ]] || { echo "FAIL: $f written, not in the reference"; status=1; }
done < <(find . -type f | sort)

# Another host: the files that name this machine's CPU (as core/machine.cpp reads it from /proc/cpuinfo),
# with another CPU's name put in its place, must still equal the reference once normalised. Written to fail
# when the normaliser keeps any part of the host's name, or when the CPU's name is not where it should be.
model=$(sed -n 's/^model name[[:space:]]*:[[:space:]]*//p' /proc/cpuinfo 2>/dev/null | head -n 1)
model=${model:-unknown CPU}
injected=0
for f in r1/table1.md table1.stdout r2/table2.md table2.stdout; do
  for other in "Intel(R) Xeon(R) Gold 6248 CPU @ 2.50GHz" "AMD EPYC 9654 96-Core Processor" "unknown CPU" "ARMv8 (rev 1), v8.2"; do
    mkdir -p "$work/other/$(dirname "$f")"
    MODEL=$model OTHER=$other /usr/bin/python3 - "$f" "$work/other/$f" <<'PY' || { echo "FAIL: $f does not name the CPU ('$model')"; status=1; continue; }
import os, sys
text = open(sys.argv[1], encoding="utf-8").read()
if os.environ["MODEL"] + " (" not in text:
    sys.exit(1)
open(sys.argv[2], "w", encoding="utf-8").write(text.replace(os.environ["MODEL"] + " (", os.environ["OTHER"] + " ("))
PY
    (cd "$work/other" && normalise "$f") >"$work/other.normalised"
    if ! cmp -s "$work/other.normalised" "$reference/$f"; then
      echo "FAIL: $f with the CPU named '$other' differs from the reference"
      diff "$work/other.normalised" "$reference/$f" | head -6
      status=1
    fi
    injected=$((injected + 1))
  done
done
echo "$checked reference files compared; $injected with another CPU's name"
exit $status
