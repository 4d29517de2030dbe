#!/usr/bin/env bash
# Issue 28 item 1, streaming: `sample --stream` makes and measures cnj, jitter, random and sobol in slabs
# and must give the in-memory run's point files and statistics byte for byte (cmp, --no-timing), for
# 2D-7D lattices, the torus and the cube (conformant and drop), several slab counts down to slabs of one
# layer, every point format; and refuse what it cannot stream with one line and no file. Runs the real
# binary ($DFVN_SAMPLE).
set -u
source "$(dirname "${BASH_SOURCE[0]}")/harness.sh"

# same_as_in_memory NAME FORMAT SLABS ARGS...: the in-memory run and the streamed run with --slabs SLABS
# (0: the automatic count) write the same stats CSV, JSON and point files.
same_as_in_memory() {
  local name=$1 format=$2 slabs=$3
  shift 3
  rm -rf "$work/mem" "$work/str"
  mkdir -p "$work/mem" "$work/str"
  local slab_option=()
  [[ $slabs != 0 ]] && slab_option=(--slabs "$slabs")
  # Each run in a folder of its own, with the same relative names (the JSON records the paths).
  if ! (cd "$work/mem" && "$bin" sample "$@" --no-timing --points pts --format "$format" -o stats.csv --json run.json) \
    2>"$work/err"; then
    bad "$name: in memory: $(head -c 300 "$work/err")"
    return
  fi
  if ! (cd "$work/str" && "$bin" sample "$@" --no-timing --points pts --format "$format" -o stats.csv --json run.json \
    --stream "${slab_option[@]}") 2>"$work/err"; then
    bad "$name: streamed (--slabs $slabs): $(head -c 300 "$work/err")"
    return
  fi
  local differ=()
  for f in stats.csv run.json pts/*; do
    [[ -e $work/mem/$f ]] || continue
    cmp -s "$work/mem/$f" "$work/str/$f" || differ+=("$f")
  done
  [[ ${#differ[@]} -eq 0 && -n $(ls "$work/mem/pts") ]] && ok || bad "$name ($format, --slabs $slabs): ${differ[*]} differ"
}

all=cnj,jitter,random,sobol
# 2D-7D on the torus (the default domain), with slab counts from one to slabs of one layer.
same_as_in_memory "2D torus" npy 1 --dim 2 --grid 24 --methods $all --seed 5
same_as_in_memory "2D torus" npy 24 --dim 2 --grid 24 --methods $all --seed 5
same_as_in_memory "2D torus" csv 4 --dim 2 --grid 24 --methods $all --seed 5
same_as_in_memory "3D torus" npy 5 --dim 3 --grid 10 --methods $all --seed 2
same_as_in_memory "3D torus" dat 10 --dim 3 --grid 10 --methods $all --seed 2
same_as_in_memory "4D torus" npy 3 --dim 4 --grid 6 --methods $all
same_as_in_memory "4D torus" bin 6 --dim 4 --grid 6 --methods $all
same_as_in_memory "5D torus" npy 5 --dim 5 --grid 5 --methods $all
same_as_in_memory "6D torus" npy 2 --dim 6 --grid 4 --methods $all
same_as_in_memory "6D count" npy 4 --dim 6 --methods $all -n 3000
same_as_in_memory "7D torus" npy 3 --dim 7 --grid 3 --methods $all
same_as_in_memory "7D torus" npy 0 --dim 7 --grid 3 --methods $all
# The cube, conformant (no point leaves) and drop (the count is known only at the end: npy's and bin's
# shape are written last).
same_as_in_memory "2D cube" npy 6 --dim 2 --grid 30 --methods $all --domain cube
same_as_in_memory "3D cube" csv 3 --dim 3 --grid 9 --methods $all --domain cube --seed 7
same_as_in_memory "4D cube" npy 7 --dim 4 --grid 7 --methods $all --domain cube --protocol unit
same_as_in_memory "5D cube" npy 2 --dim 5 --grid 4 --methods $all --domain cube
same_as_in_memory "7D cube" npy 3 --dim 7 --grid 3 --methods cnj,jitter --domain cube
same_as_in_memory "2D drop" npy 5 --dim 2 --grid 30 --methods cnj --domain-mode drop --step-scale 2
same_as_in_memory "3D drop" bin 4 --dim 3 --grid 8 --methods cnj --domain-mode drop --step-scale 2
same_as_in_memory "4D drop" dat 3 --dim 4 --grid 6 --methods cnj --domain-mode drop --step-scale 2
same_as_in_memory "5D drop" npy 5 --dim 5 --grid 5 --methods cnj --domain-mode drop --step-scale 2
# Drop mode must really drop points for the test above to mean anything.
"$bin" sample --dim 2 --grid 30 --methods cnj --domain-mode drop --step-scale 2 --no-timing --stream --slabs 5 \
  -o "$work/drop.csv" 2>/dev/null
dropped=$(awk -F, 'NR == 2 { print $24 }' "$work/drop.csv")
[[ $dropped =~ ^[0-9]+$ && $dropped -gt 0 ]] && ok || bad "2D drop: dropped column '$dropped'"
# Other CNJ options and the paper protocol's Sobol box.
same_as_in_memory "3D curl field" npy 4 --dim 3 --grid 8 --methods cnj --field curl
same_as_in_memory "4D euler" npy 2 --dim 4 --grid 6 --methods cnj --integrator euler --steps 3 --knn flann
same_as_in_memory "3D unscrambled" npy 3 --dim 3 --grid 12 --methods sobol,random --scramble none
# --no-stats: the point files alone.
rm -rf "$work/mem" "$work/str"
"$bin" sample --dim 3 --grid 8 --methods cnj,sobol --no-stats --points "$work/mem" --format npy 2>/dev/null &&
  "$bin" sample --dim 3 --grid 8 --methods cnj,sobol --no-stats --points "$work/str" --format npy --stream --slabs 8 \
    2>/dev/null && cmp -s "$work/mem/cnj.npy" "$work/str/cnj.npy" && cmp -s "$work/mem/sobol.npy" "$work/str/sobol.npy" &&
  ok || bad "--no-stats point files differ"
# Standard output: one method's points.
cmp -s <("$bin" sample --dim 2 --grid 16 --methods jitter --no-stats --points - --format dat 2>/dev/null) \
  <("$bin" sample --dim 2 --grid 16 --methods jitter --no-stats --points - --format dat --stream --slabs 4 2>/dev/null) &&
  ok || bad "--points - differs"

# Past the memory limit the run streams by itself, with a note, and gives the same statistics.
"$bin" sample --dim 3 --grid 20 --methods cnj,sobol --no-timing -o "$work/mem.csv" 2>/dev/null
"$bin" sample --dim 3 --grid 20 --methods cnj,sobol --no-timing -o "$work/auto.csv" --max-memory 0.0005 2>"$work/err" &&
  ok || bad "automatic streaming failed: $(head -c 300 "$work/err")"
grep -q "note: .*streaming them in slabs (--stream)" "$work/err" && ok || bad "no note on automatic streaming: $(cat "$work/err")"
cmp -s "$work/mem.csv" "$work/auto.csv" && ok || bad "automatic streaming: statistics differ"
# ... but not when the run cannot stream: the memory refusal stands.
expect_error "pds past the limit" "" "need about .* of memory" sample --dim 3 --grid 20 --methods pds --max-memory 0.0005

# Bad input: one line, non-zero exit, no file.
expect_error "slabs not dividing K" "" "--slabs 4 does not divide --grid 10" \
  sample --dim 3 --grid 10 --methods cnj --stream --slabs 4 -o "$work/bad.csv"
expect_error "pds" "" "not pds" sample --dim 3 --grid 6 --methods cnj,pds --stream -o "$work/bad.csv"
expect_error "jitter-matched" "" "not jitter-matched" sample --dim 3 --grid 6 --stream -o "$work/bad.csv"
expect_error "ball" "" "--domain torus or cube" sample --dim 3 --grid 6 --methods cnj --domain ball --stream -o "$work/bad.csv"
expect_error "periodic" "" "not --periodic" sample --dim 3 --grid 6 --methods cnj --periodic --stream -o "$work/bad.csv"
expect_error "rdf" "" "drop --rdf" sample --dim 3 --grid 6 --methods cnj --rdf "$work/rdf.csv" --stream -o "$work/bad.csv"
expect_error "sets" "" "drop --sets 2" sample --dim 3 --grid 6 --methods cnj --sets 2 --stream -o "$work/bad.csv"
expect_error "slabs without stream" "" "--slabs applies to --stream" sample --dim 3 --grid 6 --methods cnj --slabs 2 -o "$work/bad.csv"
expect_error "more slabs than points" "" "more slabs than points" sample --dim 2 --methods sobol -n 4 --stream --slabs 8 -o "$work/bad.csv"
[[ ! -e $work/bad.csv && ! -e $work/rdf.csv ]] && ok || bad "a refused run left a file"
mkdir -p "$work/ro" && chmod a-w "$work/ro"
if [[ -w $work/ro ]]; then ok; else  # root writes anywhere: nothing to check
  expect_error "unwritable points" "" "" sample --dim 3 --grid 6 --methods cnj --stream --points "$work/ro/pts" -o "$work/s.csv"
  expect_error "unwritable stats" "" "" sample --dim 3 --grid 6 --methods cnj --stream -o "$work/ro/s.csv"
  [[ ! -e $work/s.csv && -z $(ls -A "$work/ro") ]] && ok || bad "an unwritable run left a file"
fi
# A set too small to measure: the error comes before its point file is written, as in memory.
expect_error "all dropped" "" "statistics need at least 2" sample --dim 2 --grid 4 --methods cnj --domain-mode drop \
  --step-scale 1000 --stream --points "$work/dropped" -o "$work/dropped.csv"
[[ ! -e $work/dropped/cnj.csv && ! -e $work/dropped.csv ]] && ok || bad "all dropped: a file was left"
# Drop mode's npy count is written last: standard output cannot take it, and nothing is written.
expect_error "drop npy to stdout" "" "needs a regular file" \
  sample --dim 2 --grid 10 --methods cnj --domain-mode drop --stream --points - --format npy --no-stats
# No temporaries are left behind in $TMPDIR.
export TMPDIR="$work/tmp"
mkdir -p "$TMPDIR"
"$bin" sample --dim 3 --grid 8 --methods cnj,random --stream --slabs 4 -o "$work/t.csv" 2>/dev/null
[[ -z $(ls -A "$TMPDIR") ]] && ok || bad "temporaries left: $(ls "$TMPDIR")"

finish cli_stream
