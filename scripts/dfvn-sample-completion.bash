# bash completion for dfvn-sample (installed as share/bash-completion/completions/dfvn-sample) and
# dfvn-sample-mpi (-DDFVN_MPI=ON; installed as .../completions/dfvn-sample-mpi, the same file), which has
# no subcommands.
# Options and their allowed values are read from the program's own --help, so they always match the
# installed version: `--noise <TAB>` offers what `--noise {a,b,c} (default a)` lists.

# The --help text of the subcommand path given so far ("sample" when none is named: it is the default).
_dfvn_sample_help() {
  local program=$1
  shift
  if [[ ${program##*/} == dfvn-sample-mpi ]]; then
    "$program" --help 2>/dev/null
    return
  fi
  (($#)) || set -- sample
  "$program" "$@" --help 2>/dev/null
}

_dfvn_sample() {
  local cur prev words cword
  _init_completion || return

  local program=${words[0]}
  # Subcommands: the first word may name one of the top level's, the next one of its own, and so on.
  local -a path=()
  # The top level's subcommands as its --help lists them (one source with the usage and the man page).
  local i subcommands=""
  [[ ${program##*/} == dfvn-sample-mpi ]] ||
    subcommands=$("$program" --help 2>/dev/null | sed -n '/^Subcommands:$/,/^$/s/^  \([a-z][a-z0-9-]*\) .*/\1/p' | tr '\n' ' ')
  for ((i = 1; i < cword; i++)); do
    [[ " $subcommands " == *" ${words[i]} "* ]] || break
    path+=("${words[i]}")
    subcommands=$(_dfvn_sample_help "$program" "${path[@]}" |
      sed -n '/^Subcommands:$/,/^$/s/^  \([a-z][a-z0-9-]*\) .*/\1/p' | tr '\n' ' ')
  done
  local at_subcommand=$((i == cword))
  local help
  help=$(_dfvn_sample_help "$program" "${path[@]}")

  # The value of an option that takes one: its {choices}, a directory, a file, or nothing to offer.
  # An option's line in --help: two spaces, its names ("-o, --output, --stats"), then its value's
  # label when it takes one ("FILE (default -)", "{csv,npy,dat,bin} (default csv)", "N (2..8, default 7)").
  if [[ $prev == -* ]]; then
    local line value
    line=$(grep -E -- "^  (-[-a-zA-Z0-9]+, )*$prev(, -[-a-zA-Z0-9]+)*( |$)" <<<"$help" | head -n 1)
    value=$(sed -E 's/^  (-[-a-zA-Z0-9]+)(, -[-a-zA-Z0-9]+)*//; s/^ //' <<<"$line")
    if [[ -n $line && -n $value ]]; then
      if [[ $value =~ ^\{([^}]*)\} ]]; then
        COMPREPLY=($(compgen -W "${BASH_REMATCH[1]//,/ }" -- "$cur"))
      elif [[ $line == *--methods* ]]; then  # a comma list: complete the name after the last comma
        # The methods as the usage lists them (from the library's list of every method).
        local methods
        methods=$("$program" 2>/dev/null | sed -n 's/^  methods (--methods): //p' | tr -d ',')
        COMPREPLY=($(compgen -P "${cur%"${cur##*,}"}" -W "$methods" -- "${cur##*,}"))
        compopt -o nospace
      elif [[ $value == DIR* ]]; then
        _filedir -d
      elif [[ $value =~ ^(FILE|PATH|PREFIX|SPEC) ]]; then
        _filedir
      fi
      return
    fi
  fi

  if [[ $cur != -* && $at_subcommand == 1 && -n ${subcommands// /} ]]; then
    COMPREPLY=($(compgen -W "$subcommands" -- "$cur"))
  else
    COMPREPLY=($(compgen -W "$(grep -oE -- '^  (-[a-zA-Z], )?--[a-z][a-z0-9-]*(, --[a-z][a-z0-9-]*)*' <<<"$help" | sed 's/^ *//; s/,//g')" -- "$cur"))
  fi
} && complete -F _dfvn_sample dfvn-sample dfvn-sample-mpi
