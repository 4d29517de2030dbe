#!/usr/bin/env bash
# Command-line tests: run the real binary ($DFVN_SAMPLE) and check exit codes, messages and files.
set -u
bin=${DFVN_SAMPLE:?set DFVN_SAMPLE to the dfvn-sample binary}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
passed=0
failed=0

ok() { passed=$((passed + 1)); }
bad() { failed=$((failed + 1)); echo "FAIL: $*" >&2; }

# expect_error NAME STDIN ARGS...: non-zero exit, exactly one line on stderr, nothing on stdout.
expect_error() {
  local name=$1 input=$2
  shift 2
  printf '%b' "$input" | "$bin" "$@" >"$work/out" 2>"$work/err"
  local rc=$?
  local lines
  lines=$(wc -l <"$work/err")
  if [[ $rc -ne 0 && $lines -eq 1 && ! -s $work/out ]] && grep -q "^dfvn-sample: error: " "$work/err"; then
    ok
  else
    bad "$name: rc=$rc, $lines stderr lines: $(cat "$work/err")"
  fi
}

# expect_message NAME PATTERN: the last error message matches PATTERN.
expect_message() {
  grep -q -- "$2" "$work/err" && ok || bad "$1: '$(cat "$work/err")' does not match '$2'"
}

# --help and --version
"$bin" --version >"$work/out" 2>&1 && grep -q "^dfvn-sample [0-9]" "$work/out" && ok || bad "--version"
"$bin" field --help >"$work/out" 2>&1 && grep -q -- "--frequency" "$work/out" && ok || bad "field --help"

# field: header, columns, precision
printf 'x0,x1,x2\n0.1,0.2,0.3\n' | "$bin" field --dim 3 --seed 5 >"$work/f.csv" 2>"$work/err" && ok || bad "field run"
head -1 "$work/f.csv" | grep -qx "x0,x1,x2,c0,c1,c2,f1,f2" && ok || bad "field header: $(head -1 "$work/f.csv")"
[[ $(sed -n 2p "$work/f.csv" | awk -F, '{print NF}') -eq 8 ]] && ok || bad "field column count"
sed -n 2p "$work/f.csv" | cut -d, -f1 | grep -qx "0.10000000000000001" && ok || bad "17 significant digits"

# field: bad input names the line and the problem
expect_error "wrong column count" "1,2,3\n0.5,0.5\n" field --dim 3
expect_message "wrong column count" "line 2: expected 3 comma-separated columns"
expect_error "non-numeric" "1,2,3\n1,zz,3\n" field --dim 3
expect_message "non-numeric" "line 2, column 2: 'zz' is not a number"
expect_error "nan" "1,2,nan\n" field --dim 3
expect_message "nan" "line 1, column 3: 'nan' is not a finite number"
expect_error "inf" "1,2,3\n4,inf,6\n" field --dim 3
expect_message "inf" "line 2, column 2"
expect_error "dim too large" "" field --dim 9
expect_message "dim too large" "dim"
expect_error "dim too small" "" field --dim 1
expect_error "negative frequency" "" field --dim 3 --frequency -2
expect_message "negative frequency" "must be a finite number > 0"
expect_error "nan frequency" "" field --dim 3 --frequency nan
expect_error "missing input file" "" field --dim 3 --input "$work/does-not-exist.csv"
expect_error "unknown option" "" field --dim 3 --bogus
expect_error "unwritable output" "0,0,0\n" field --dim 3 --output "$work/no/such/dir/out.csv"

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

echo "cli: $passed passed, $failed failed"
[[ $failed -eq 0 ]]
