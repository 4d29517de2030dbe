#!/usr/bin/env bash
# The bash completion script completes subcommands, options and option values of the real binary.
# Environment: DFVN_SAMPLE (the binary), COMPLETION (the script).
set -uo pipefail
: "${DFVN_SAMPLE:?}" "${COMPLETION:?}"
fail() { echo "FAIL: $*" >&2; exit 1; }
completion_lib=/usr/share/bash-completion/bash_completion
[[ -r $completion_lib ]] || fail "$completion_lib is missing (apt-get install bash-completion)"
# bash_completion reads its own settings and expects an interactive-like shell; these are enough.
source "$completion_lib"
source "$COMPLETION"
complete -p dfvn-sample >/dev/null || fail "the script registers no completion for dfvn-sample"

# The completions offered for a command line whose last word is being typed.
complete_line() {
  local line="$DFVN_SAMPLE $1"
  COMP_LINE=$line
  COMP_POINT=${#line}
  read -r -a COMP_WORDS <<<"$line"
  [[ $line == *" " ]] && COMP_WORDS+=("")
  COMP_CWORD=$((${#COMP_WORDS[@]} - 1))
  COMPREPLY=()
  _dfvn_sample dfvn-sample "${COMP_WORDS[COMP_CWORD]}" "${COMP_WORDS[COMP_CWORD - 1]}"
  printf '%s\n' "${COMPREPLY[@]}" | sort | tr '\n' ' '
}

expect() {  # expect LINE WORD...: every WORD is offered
  local got
  got=" $(complete_line "$1")"
  shift
  for word in "$@"; do [[ $got == *" $word "* ]] || fail "completing '$line_shown' offered '$got', not '$word'"; done
}

line_shown="dfvn-sample re"; expect "re" reproduce
line_shown="dfvn-sample "; expect "" sample field stats reproduce animate
line_shown="dfvn-sample an"; expect "an" animate
line_shown="dfvn-sample animate --lattice "; expect "animate --lattice " cubic bcc
line_shown="dfvn-sample animate --domain-mode "; expect "animate --domain-mode " conformant drop
line_shown="dfvn-sample animate --ph"; expect "animate --ph" --phase --phase-step
line_shown="dfvn-sample reproduce f"; expect "reproduce f" figure8
line_shown="dfvn-sample reproduce figure8 --lattice-3d "; expect "reproduce figure8 --lattice-3d " cubic bcc
line_shown="dfvn-sample reproduce t"; expect "reproduce t" table1 table2
line_shown="dfvn-sample field --d"; expect "field --d" --dim --diagnose --diagnose-points
line_shown="dfvn-sample --noise "; expect "--noise " turning-bands simplex quintic-gradient simplex-separate
line_shown="dfvn-sample sample --protocol u"; expect "sample --protocol u" unit
line_shown="dfvn-sample --methods cnj,s"; expect "--methods cnj,s" cnj,sobol
line_shown="dfvn-sample sample --s"; expect "sample --s" --sets --seed
line_shown="dfvn-sample sample --re"; expect "sample --re" --realizations
line_shown="dfvn-sample sample -"; expect "sample -" -m --sets
line_shown="dfvn-sample sample --format "; expect "sample --format " csv npy dat bin
line_shown="dfvn-sample stats --format b"; expect "stats --format b" bin
line_shown="dfvn-sample stats --r"; expect "stats --r" --rdf --rdf-bins
got=$(complete_line "sample --sets ")
[[ -z ${got// /} ]] || fail "a number option (--sets) offered '$got'"
line_shown="dfvn-sample --methods cnj,j"; expect "--methods cnj,j" cnj,jitter cnj,jitter-matched
line_shown="dfvn-sample reproduce t"; expect "reproduce " table1 table2 cnj-study integration
line_shown="dfvn-sample reproduce cnj-study --r"; expect "reproduce cnj-study --r" --realizations
line_shown="dfvn-sample --c"; expect "--c" --count --cycles-per-spacing
# The main output's three names, each followed by a file name.
for name in -o --output --stats; do
  got=$(cd "$(dirname "$DFVN_SAMPLE")" && complete_line "$name dfvn-sam")
  [[ $got == *dfvn-sample* ]] || fail "$name offered '$got', not a file"
done
got=$(complete_line "field --dim ")
[[ -z ${got// /} ]] || fail "a number option (--dim) offered '$got'"
echo "ok: subcommands, options and their values complete"
