#!/usr/bin/env bash
# Issue 28 item 2, MPI: dfvn-sample-mpi under `mpirun -np 1`, `-np 2` and `-np 3` (oversubscribed on a
# 2-core machine) must write the point files and statistics CSV of one process's
# `dfvn-sample sample --stream` byte for byte (cmp, --no-timing), for 4D-7D lattices, the torus and the
# cube (conformant and drop), every point format, fewer slabs than ranks, any thread count; with
# --periodic (statistics on the torus: the halo wraps), --rdf and --json the same three files as
# sample --stream and in-memory sample; and refuse bad input with one line, a non-zero exit and no file
# (a rank that dies included: DFVN_MPI_FAIL_RANK).
# Registered by ctest only with -DDFVN_MPI=ON. $DFVN_SAMPLE: the one-process binary; $DFVN_SAMPLE_MPI:
# the MPI binary; $MPIEXEC: mpirun.
set -u
source "$(dirname "${BASH_SOURCE[0]}")/harness.sh"
mpi=${DFVN_SAMPLE_MPI:?set DFVN_SAMPLE_MPI to the dfvn-sample-mpi binary}
mpiexec=${MPIEXEC:-mpirun}
# CI runs as root in a fresh container: Open MPI refuses root without these; shared memory and self only
# (no network), without the cross-memory attach that containers forbid.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_btl=self,vader OMPI_MCA_btl_vader_single_copy_mechanism=none OMPI_MCA_rmaps_base_oversubscribe=1
# -q: mpirun's own banners off, so that a failed run's stderr is the program's line.
run_mpi() {
  local np=$1
  shift
  timeout 300 "$mpiexec" -q --oversubscribe -np "$np" "$mpi" "$@"
}

# same_as_stream NAME FORMAT ARGS...: `sample --stream` in one process, then dfvn-sample-mpi with 1, 2
# and 3 ranks (and the extra options of $MPI_EXTRA), the same stats CSV and point files.
same_as_stream() {
  local name=$1 format=$2
  shift 2
  rm -rf "$work/one" && mkdir -p "$work/one"
  if ! (cd "$work/one" && "$bin" sample "$@" --stream --no-timing --points pts --format "$format" -o stats.csv) \
    2>"$work/err"; then
    bad "$name: one process: $(head -c 300 "$work/err")"
    return
  fi
  [[ -n $(ls "$work/one/pts") ]] || { bad "$name: no point files"; return; }
  for np in 1 2 3; do
    rm -rf "$work/mpi" && mkdir -p "$work/mpi"
    if ! (cd "$work/mpi" && run_mpi "$np" "$@" ${MPI_EXTRA:-} --no-timing --points pts --format "$format" -o stats.csv) \
      2>"$work/err"; then
      bad "$name: -np $np: $(head -c 300 "$work/err")"
      continue
    fi
    local differ=()
    for f in "$work/one"/stats.csv "$work/one"/pts/*; do
      f=${f#"$work/one/"}
      cmp -s "$work/one/$f" "$work/mpi/$f" || differ+=("$f")
    done
    [[ ${#differ[@]} -eq 0 ]] && ok || bad "$name ($format, -np $np): ${differ[*]} differ"
    [[ -z $(ls -A "$work/mpi/pts" | grep -v "\.$format\$" | grep -v "\.$format\.json\$") ]] && ok ||
      bad "$name -np $np: stray files $(ls -A "$work/mpi/pts")"
  done
}

all=cnj,jitter,random,sobol
same_as_stream "4D torus" npy --dim 4 --grid 6 --methods $all
same_as_stream "4D cube" dat --dim 4 --grid 6 --methods $all --domain cube --seed 3
same_as_stream "5D torus" csv --dim 5 --grid 5 --methods $all --seed 9
same_as_stream "5D cube" bin --dim 5 --grid 5 --methods $all --domain cube
same_as_stream "6D torus" npy --dim 6 --grid 4 --methods $all --seed 2
same_as_stream "6D count" npy --dim 6 -n 3000 --methods random,sobol
same_as_stream "7D torus" npy --dim 7 --grid 4 --methods $all
same_as_stream "7D cube" bin --dim 7 --grid 4 --methods cnj,jitter --domain cube
# Drop mode: the count is known only after generation (npy's shape from the ranks' counts).
same_as_stream "4D drop" npy --dim 4 --grid 6 --methods cnj --domain-mode drop --step-scale 2
same_as_stream "3D drop" dat --dim 3 --grid 8 --methods cnj --domain-mode drop --step-scale 2
# Fewer slabs than ranks (ranks without a slab make no points and only take part in the exchanges), one
# slab, and one thread against the default.
MPI_EXTRA="--slabs 2" same_as_stream "4D two slabs" npy --dim 4 --grid 6 --methods $all
MPI_EXTRA="--slabs 1 --threads 1" same_as_stream "5D one slab, one thread" npy --dim 5 --grid 4 --methods $all
# Drop mode must really drop points for the test above to mean anything.
dropped=$(awk -F, 'NR == 2 { print $25 }' "$work/one/stats.csv" 2>/dev/null)
run_mpi 2 --dim 4 --grid 6 --methods cnj --domain-mode drop --step-scale 2 --no-timing -o "$work/drop.csv" 2>/dev/null
dropped=$(awk -F, 'NR == 2 { print $25 }' "$work/drop.csv")
[[ $dropped =~ ^[0-9]+$ && $dropped -gt 0 ]] && ok || bad "4D drop: dropped column '$dropped'"
# --no-stats: the point files alone.
rm -rf "$work/a" "$work/b"
"$bin" sample --dim 4 --grid 6 --methods cnj,sobol --no-stats --points "$work/a" --format npy --stream 2>/dev/null &&
  run_mpi 3 --dim 4 --grid 6 --methods cnj,sobol --no-stats --points "$work/b" 2>/dev/null &&
  cmp -s "$work/a/cnj.npy" "$work/b/cnj.npy" && cmp -s "$work/a/sobol.npy" "$work/b/sobol.npy" &&
  ok || bad "--no-stats point files differ"

# same_as_memory NAME ARGS...: in-memory `sample`, `sample --stream` and dfvn-sample-mpi with 1, 2 and 3
# ranks (and $MPI_EXTRA), each writing the stats CSV, --rdf CSV, --json and npy point files: all the same
# bytes (issue 28: --periodic and --rdf over MPI).
same_as_memory() {
  local name=$1
  shift
  local outputs=(--no-timing --points pts --format npy -o stats.csv --rdf rdf.csv --json run.json)
  rm -rf "$work/mem" "$work/one" && mkdir -p "$work/mem" "$work/one"
  if ! (cd "$work/mem" && "$bin" sample "$@" "${outputs[@]}" -q) 2>"$work/err" ||
    ! (cd "$work/one" && "$bin" sample "$@" --stream "${outputs[@]}" -q) 2>"$work/err"; then
    bad "$name: one process: $(head -c 300 "$work/err")"
    return
  fi
  local files=(stats.csv rdf.csv run.json)
  for f in "$work/one"/pts/*; do files+=("pts/${f##*/}"); done
  [[ ${#files[@]} -gt 3 && $(wc -l <"$work/one/rdf.csv") -gt 1 ]] || { bad "$name: no point files or RDF rows"; return; }
  local differ=()
  for f in "${files[@]}"; do cmp -s "$work/mem/$f" "$work/one/$f" || differ+=("$f"); done
  [[ ${#differ[@]} -eq 0 ]] && ok || bad "$name: sample --stream and in memory: ${differ[*]} differ"
  for np in 1 2 3; do
    rm -rf "$work/mpi" && mkdir -p "$work/mpi"
    # shellcheck disable=SC2086
    if ! (cd "$work/mpi" && run_mpi "$np" "$@" ${MPI_EXTRA:-} "${outputs[@]}") 2>"$work/err"; then
      bad "$name: -np $np: $(head -c 300 "$work/err")"
      continue
    fi
    differ=()
    for f in "${files[@]}"; do cmp -s "$work/one/$f" "$work/mpi/$f" || differ+=("$f"); done
    [[ ${#differ[@]} -eq 0 ]] && ok || bad "$name (-np $np): ${differ[*]} differ"
  done
}
# The torus (the default; --periodic says so again) and the cube, with and without --rdf's query subset,
# 4D-7D; the paper protocol's boxes.
same_as_memory "4D torus, periodic" --dim 4 --grid 6 --methods $all --periodic
same_as_memory "4D cube" --dim 4 --grid 6 --methods cnj,jitter --domain cube --seed 5
same_as_memory "5D box" --dim 5 --grid 5 --methods $all --rdf-queries 400 --rdf-bins 30 --domain cube
same_as_memory "5D torus" --dim 5 --grid 5 --methods cnj,sobol --rdf-max 0.2
same_as_memory "4D paper" --dim 4 --grid 6 --methods cnj,jitter,sobol --protocol paper
same_as_memory "6D count, periodic" --dim 6 -n 3000 --methods random,sobol --periodic --rdf-queries 500
same_as_memory "7D torus, periodic" --dim 7 --grid 4 --methods cnj,jitter --periodic --rdf-queries 1000 --rdf-bins 20
# The halo wrapping over several ranks and the whole torus: one slab (ranks 1 and 2 have none), two slabs
# on three ranks, and one thread.
MPI_EXTRA="--slabs 1" same_as_memory "4D periodic, one slab" --dim 4 --grid 6 --methods cnj,random --periodic
MPI_EXTRA="--slabs 2 --threads 1" same_as_memory "5D periodic, two slabs" --dim 5 --grid 4 --methods jitter,sobol --periodic
MPI_EXTRA="--slabs 3" same_as_memory "4D box, three slabs" --dim 4 --grid 6 --methods jitter --rdf-max 0.4 --domain cube
# The torus must change the statistics for the tests above to mean anything; --periodic is the torus.
run_mpi 2 --dim 4 --grid 6 --methods jitter --no-timing --domain cube -o "$work/box.csv" 2>/dev/null
run_mpi 2 --dim 4 --grid 6 --methods jitter --no-timing -o "$work/torus.csv" 2>/dev/null
run_mpi 2 --dim 4 --grid 6 --methods jitter --no-timing --periodic -o "$work/torus2.csv" 2>/dev/null
[[ -s $work/box.csv && -s $work/torus.csv ]] && ! cmp -s "$work/box.csv" "$work/torus.csv" &&
  cmp -s "$work/torus.csv" "$work/torus2.csv" && ok || bad "the torus gave the box's statistics"
# The JSON names the experiment's program, as sample's does (so that the files compare equal).
grep -q '"program": *"dfvn-sample"' "$work/mpi/run.json" && ok || bad "run.json: $(head -c 200 "$work/mpi/run.json")"
# --progress always: rank 0's plain lines, prefixed with dfvn-sample-mpi; -q: none.
run_mpi 2 --dim 4 --grid 6 --methods jitter --rdf "$work/p.rdf" --progress always -o "$work/p.csv" 2>"$work/err"
grep -q "^dfvn-sample-mpi: \[1/3\] jitter" "$work/err" && grep -q "^dfvn-sample-mpi: \[3/3\] jitter rdf" "$work/err" && ok ||
  bad "--progress always: $(head -c 300 "$work/err")"
run_mpi 2 --dim 4 --grid 6 --methods jitter --rdf "$work/p.rdf" --progress always -q -o "$work/p.csv" 2>"$work/err"
[[ ! -s $work/err ]] && ok || bad "-q: $(head -c 300 "$work/err")"

# Bad input: one line "dfvn-sample-mpi: error: ...", a non-zero exit, nothing on stdout, no file.
expect_mpi_error() {
  local name=$1 np=$2 pattern=$3
  shift 3
  run_mpi "$np" "$@" </dev/null >"$work/out" 2>"$work/err"
  local rc=$?
  if [[ $rc -ne 0 && $(wc -l <"$work/err") -eq 1 && ! -s $work/out ]] &&
    grep -Eq -- "^dfvn-sample-mpi: error: .*($pattern)" "$work/err"; then
    ok
  else
    bad "$name: rc=$rc, $(wc -l <"$work/err") stderr lines: $(head -c 400 "$work/err" | cat -v)"
  fi
}
mkdir -p "$work/bad"
expect_mpi_error "slabs not dividing K" 2 "--slabs 4 does not divide --grid 6" \
  --dim 4 --grid 6 --methods cnj --slabs 4 -o "$work/bad/s.csv" --points "$work/bad/p"
expect_mpi_error "pds" 3 "not pds" --dim 4 --grid 6 --methods cnj,pds -o "$work/bad/s.csv"
expect_mpi_error "halton" 2 "not halton" --dim 4 --grid 6 --methods halton -o "$work/bad/s.csv"
expect_mpi_error "cube periodic" 2 "--periodic measures on the torus" --dim 4 --grid 6 --methods jitter --domain cube --periodic -o "$work/bad/s.csv"
expect_mpi_error "ball" 2 "of a torus or cube into slabs, not --domain ball" --dim 4 --grid 6 --methods cnj --domain ball -o "$work/bad/s.csv"
expect_mpi_error "points to stdout" 2 "needs a directory" --dim 4 --grid 6 --methods cnj --points - --no-stats
expect_mpi_error "more slabs than points" 2 "more slabs than points" --dim 2 -n 4 --methods sobol --slabs 8 -o "$work/bad/s.csv"
# A rank's share past the memory limit (the one-process slab of one layer fits: 7D K = 8, 8 slabs).
expect_mpi_error "a rank's share past --max-memory" 2 "run on more ranks" \
  --dim 7 --grid 8 --methods jitter --slabs 8 --max-memory 0.2 -o "$work/bad/s.csv"
touch "$work/bad/file"
expect_mpi_error "unwritable points" 3 "" --dim 4 --grid 6 --methods cnj --points "$work/bad/file/pts" -o "$work/bad/s.csv"
expect_mpi_error "unwritable stats" 2 "" --dim 4 --grid 6 --methods cnj -o "$work/bad/file/s.csv"
expect_mpi_error "--rdf with --no-stats" 2 "--no-stats computes no statistics" \
  --dim 4 --grid 6 --methods cnj --no-stats --points "$work/bad/p" --rdf "$work/bad/r.csv"
expect_mpi_error "periodic r_max past half the side" 3 "--rdf-max 0.5 with --periodic must be below half" \
  --dim 4 --grid 6 --methods jitter --periodic --rdf "$work/bad/r.csv" --rdf-max 0.5 -o "$work/bad/s.csv" --json "$work/bad/j.json"
expect_mpi_error "RDF bins too narrow" 2 "too narrow" --dim 4 --grid 6 --methods jitter --rdf "$work/bad/r.csv" \
  --rdf-max 1e-300 -o "$work/bad/s.csv"
expect_mpi_error "unwritable --rdf" 2 "" --dim 4 --grid 6 --methods cnj -o "$work/bad/s.csv" --rdf "$work/bad/file/r.csv" \
  --json "$work/bad/j.json"
expect_mpi_error "unwritable --json" 3 "" --dim 4 --grid 6 --methods cnj --periodic -o "$work/bad/s.csv" \
  --rdf "$work/bad/r.csv" --json "$work/bad/file/j.json" --points "$work/bad/p"
expect_mpi_error "--rdf and --json both on stdout" 2 "" --dim 4 --grid 6 --methods cnj -o "$work/bad/s.csv" --rdf - --json -
[[ $(ls -A "$work/bad") == file ]] && ok || bad "a refused run left a file: $(ls -A "$work/bad")"
# A rank that dies: after writing its share of the points (rank 1 of 3, and rank 0, whose survivors
# remove the temporary when mpirun stops them), and before the statistics (rank 2, no --points).
for r in 1 0; do
  rm -rf "$work/dies" && mkdir -p "$work/dies"
  DFVN_MPI_FAIL_RANK=$r expect_mpi_error "rank $r dies" 3 "rank $r stops after writing its share" \
    --dim 4 --grid 6 --methods cnj,jitter --points "$work/dies/pts" -o "$work/dies/s.csv"
  [[ -z $(ls -A "$work/dies/pts" 2>/dev/null) && ! -e $work/dies/s.csv ]] && ok ||
    bad "rank $r died: files left: $(ls -A "$work/dies" "$work/dies/pts")"
done
DFVN_MPI_FAIL_RANK=2 expect_mpi_error "rank 2 dies" 3 "rank 2 stops before the statistics" \
  --dim 4 --grid 6 --methods jitter -o "$work/dies/s.csv"
[[ ! -e $work/dies/s.csv ]] && ok || bad "rank 2 died: the stats file was written"
# --help names every option with its default.
run_mpi 1 --help >"$work/help" 2>&1
for option in --dim --grid --count --methods --slabs --points --format --no-timing --seed --threads --domain \
  --periodic --rdf --rdf-max --rdf-bins --rdf-queries --json --progress --quiet; do
  grep -q -- "$option" "$work/help" && ok || bad "--help does not name $option"
done
# The bash completion (scripts/dfvn-sample-completion.bash) reads dfvn-sample-mpi's own --help.
if [[ -n ${COMPLETION:-} && -r /usr/share/bash-completion/bash_completion ]]; then
  complete_mpi() {
    (
      source /usr/share/bash-completion/bash_completion
      source "$COMPLETION"
      local line="$mpi $1"
      COMP_LINE=$line
      COMP_POINT=${#line}
      read -r -a COMP_WORDS <<<"$line"
      [[ $line == *" " ]] && COMP_WORDS+=("")
      COMP_CWORD=$((${#COMP_WORDS[@]} - 1))
      COMPREPLY=()
      _dfvn_sample dfvn-sample-mpi "${COMP_WORDS[COMP_CWORD]}" "${COMP_WORDS[COMP_CWORD - 1]}"
      printf ' %s ' "${COMPREPLY[@]}"
    )
  }
  [[ $(complete_mpi "--sl") == *" --slabs "* ]] && ok || bad "completion of --sl: '$(complete_mpi "--sl")'"
  [[ $(complete_mpi "--format ") == *" npy "*" "* && $(complete_mpi "--format ") == *" bin "* ]] && ok ||
    bad "completion of --format: '$(complete_mpi "--format ")'"
  [[ $(complete_mpi "") != *" sample "* ]] && ok || bad "completion offers subcommands to dfvn-sample-mpi"
else
  bad "no COMPLETION script or no bash-completion"
fi

finish cli_mpi
