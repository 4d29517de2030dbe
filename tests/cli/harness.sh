# Shared harness of the command-line tests (tests/cli/test_cli*.sh); not a test itself. Each script,
# after `set -u`, does
#   source "$(dirname "${BASH_SOURCE[0]}")/harness.sh"
# which sets bin (the binary under test, from $DFVN_SAMPLE; the script stops if it is unset), work (a
# fresh temporary folder, removed on exit) and the counters passed and failed, and defines:
#
# ok: one check passed.
# bad MESSAGE...: one check failed; prints "FAIL: MESSAGE" on stderr.
# expect_error NAME STDIN PATTERN ARGS...: one check, of "$bin" ARGS... run with STDIN on its standard
#   input (expanded by printf '%b', so \n, \0, \033 and \xHH are bytes; an empty STDIN means no input,
#   </dev/null). It passes when the exit status is non-zero, nothing is on stdout, and stderr is exactly
#   one line that starts with "dfvn-sample: error: ", is at most 400 bytes, holds no control byte but
#   its newline, and matches the extended regular expression (grep -E) PATTERN after that prefix
#   (an empty PATTERN: any message). stdout and stderr are left in $work/out and $work/err.
# expect_message NAME PATTERN: one check, that the last expect_error's stderr ($work/err) matches the
#   extended regular expression (grep -E) PATTERN anywhere. Escape ( ) { } | + ? ^ $ [ ] . \ to mean
#   them literally.
# same_as_recorded NAME FILE REFERENCE: one check, that FILE with its times blanked as for REFERENCE's
#   name (normalise_times.py goes by the name) is byte for byte $recorded/REFERENCE, the files
#   test_cli_reference.sh records. normalise_times FILE prints FILE so blanked.
# finish NAME: prints "NAME: P passed, F failed" and exits 0 if no check failed, 1 otherwise.

bin=${DFVN_SAMPLE:?set DFVN_SAMPLE to the dfvn-sample binary}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
passed=0
failed=0

ok() { passed=$((passed + 1)); }
bad() { failed=$((failed + 1)); echo "FAIL: $*" >&2; }

expect_error() {
  local name=$1 input=$2 pattern=$3
  shift 3
  if [[ -n $input ]]; then
    printf '%b' "$input" | "$bin" "$@" >"$work/out" 2>"$work/err"
  else
    "$bin" "$@" </dev/null >"$work/out" 2>"$work/err"
  fi
  local rc=$?
  local lines bytes regex="^dfvn-sample: error: "
  [[ -n $pattern ]] && regex+=".*($pattern)"
  lines=$(wc -l <"$work/err")
  bytes=$(wc -c <"$work/err")
  if [[ $rc -ne 0 && $lines -eq 1 && $bytes -le 400 && ! -s $work/out ]] && grep -Eq -- "$regex" "$work/err" &&
    ! LC_ALL=C grep -q '[[:cntrl:]]' <(tr -d '\n' <"$work/err"); then
    ok
  else
    bad "$name: rc=$rc, $(wc -c <"$work/out") stdout bytes, $lines stderr lines, $bytes bytes${pattern:+ (pattern '$pattern')}:" \
      "$(head -c 300 "$work/err" | cat -v)"
  fi
}

expect_message() {
  grep -Eq -- "$2" "$work/err" && ok || bad "$1: '$(head -c 300 "$work/err" | cat -v)' does not match '$2'"
}

# expect_finite NAME FILE...: the files exist and hold no NaN or Inf.
expect_finite() {
  local name=$1
  shift
  for f in "$@"; do
    if [[ ! -s $f ]]; then
      bad "$name: $f is missing or empty"
    elif grep -Eiq '(^|[^a-z])(nan|-?inf(inity)?)([^a-z]|$)' "$f"; then
      bad "$name: $f holds NaN or Inf: $(grep -Eim1 'nan|inf' "$f" | head -c 200)"
    else
      ok
    fi
  done
}

recorded="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)/reference"
normalise_times() { /usr/bin/python3 "$recorded/../normalise_times.py" "$1"; }
same_as_recorded() {
  mkdir -p "$work/named" && cp "$2" "$work/named/$(basename "$3")"
  if cmp -s <(normalise_times "$work/named/$(basename "$3")") "$recorded/$3"; then ok; else bad "$1: $2 differs from $3"; fi
}

finish() {
  echo "$1: $passed passed, $failed failed"
  [[ $failed -eq 0 ]] && exit 0
  exit 1
}
