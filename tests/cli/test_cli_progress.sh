#!/usr/bin/env bash
# Issue 24: progress in every long-running subcommand. With --progress always (stderr is no terminal
# here) every line counts "[k/n]" stages, the count ends at n/n and agrees with the closing "done: n
# stages", no line reads "ETA 0.0 s"; -q (and --progress never) print nothing on stderr for a successful
# run, and progress changes neither stdout nor an output file.
set -u
source "$(dirname "${BASH_SOURCE[0]}")/harness.sh"

"$bin" -d 2 --grid 12 --methods jitter --points "$work/pts" --no-stats --format dat -q -s 4 2>"$work/err" &&
  [[ ! -s $work/err ]] && ok || bad "sample -q wrote on stderr: $(cat "$work/err")"

# check_log NAME LOG: the checks on a --progress always log.
check_log() {
  local name=$1 log=$2 n last done_n
  # Besides the progress lines, sample's verdict and notes (of its own count) close its log.
  if grep -v "^dfvn-sample: \[[0-9]*/[0-9]*\] .*(stage [^;]*; elapsed [^)]*)$" "$log" | grep -v "^dfvn-sample: done: " |
    grep -v "^dfvn-sample: verdict by " | grep -qv "^dfvn-sample: note: "; then
    bad "$name: a progress line without [k/n]: $(grep -v '\[[0-9]*/[0-9]*\]' "$log" | head -2)"
  else ok; fi
  n=$(grep -o "\[[0-9]*/[0-9]*\]" "$log" | head -1 | sed 's/.*\/\([0-9]*\)\]/\1/')
  last=$(grep -o "\[[0-9]*/[0-9]*\]" "$log" | tail -1)
  done_n=$(sed -n 's/^dfvn-sample: done: \([0-9]*\) stages\{0,1\} in .*/\1/p' "$log")
  [[ -n $n && $last == "[$n/$n]" && $done_n == "$n" ]] && ok || bad "$name: counter ends at $last of $n, done says '$done_n'"
  grep -q "ETA 0\.0 s" "$log" && bad "$name: ETA 0.0 s: $(grep -m1 'ETA 0\.0 s' "$log")" || ok
}

# run_both NAME ARGS...: the command with --progress always, then with -q; both succeed, -q writes
# nothing on stderr and the same stdout (run with --no-timing or a stdout free of times).
run_both() {
  local name=$1
  shift
  "$bin" "$@" --progress always >"$work/$name.out1" 2>"$work/$name.log" && ok || bad "$name: $(tail -2 "$work/$name.log")"
  check_log "$name" "$work/$name.log"
  "$bin" "$@" -q >"$work/$name.out2" 2>"$work/$name.err" && [[ ! -s $work/$name.err ]] && ok ||
    bad "$name -q: $(head -2 "$work/$name.err")"
  "$bin" "$@" --progress never >/dev/null 2>"$work/$name.err" &&
    [[ -z $(grep -v "^dfvn-sample: verdict by \|^dfvn-sample: note: " "$work/$name.err") ]] && ok || bad "$name --progress never"
}

run_both sample -d 3 --grid 6 --methods cnj,pds,sobol --realizations 2 --no-timing -o -
cmp -s "$work/sample.out1" "$work/sample.out2" && ok || bad "sample: progress changed stdout"
run_both sample_rdf -d 3 --grid 6 --methods cnj,jitter --rdf "$work/rdf.csv" --no-timing -o -
rm -f "$work"/spec*
run_both stats stats --input "$work/pts/jitter.dat" --discrepancy --no-timing -o -
cmp -s "$work/stats.out1" "$work/stats.out2" && ok || bad "stats: progress changed stdout"
"$bin" stats --input "$work/pts/jitter.dat" --spectrum "$work/specA" --spectrum-frequency 8 --progress always -o /dev/null \
  2>"$work/spec.log" && ok || bad "stats --spectrum: $(cat "$work/spec.log")"
check_log "stats --spectrum" "$work/spec.log"
grep -q "\[2/2\] spectrum" "$work/spec.log" && ok || bad "no spectrum stage: $(cat "$work/spec.log")"
"$bin" stats --input "$work/pts/jitter.dat" --spectrum "$work/specB" --spectrum-frequency 8 -q -o /dev/null 2>"$work/err" &&
  [[ ! -s $work/err ]] && cmp -s "$work/specA.csv" "$work/specB.csv" && cmp -s "$work/specA_radial.csv" "$work/specB_radial.csv" &&
  ok || bad "stats --spectrum -q: $(cat "$work/err")"

run_both field field --input "$(dirname "${BASH_SOURCE[0]}")/../../data/points_3d_example.csv" -o -
cmp -s "$work/field.out1" "$work/field.out2" && ok || bad "field: progress changed stdout"
run_both field_diagnose field --diagnose --diagnose-points 2000 -o "$work/diagnosis.csv"

# The reproductions, small. Their stdout holds measured times, so only stderr is compared.
run_both table2 reproduce table2 --width 16 --height 9 --second-width 8 --out "$work/t2"
grep -q "^dfvn-sample: \[1/29\] reference" "$work/table2.log" && ok || bad "table2: $(head -1 "$work/table2.log")"
run_both table1 reproduce table1 --dims 3 --realizations 2 --out "$work/t1"
run_both cnj_study reproduce cnj-study --dims 3 --noises simplex --cycles-per-spacing 0.5 --step-scales 0.5 --steps 1 --realizations 2 --out "$work/cs"
grep -q "\[3/3\] 3D jitter curve" "$work/cnj_study.log" && ok || bad "cnj-study stages: $(cat "$work/cnj_study.log")"
run_both integration reproduce integration --dims 3 --realizations 2 --max-points 512 --methods jitter,random --out "$work/int"

finish "cli_progress"
