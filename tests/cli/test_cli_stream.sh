#!/usr/bin/env bash
# Issue 28 item 1, streaming: `sample --stream` makes and measures cnj, jitter, random and sobol in slabs
# and must give the in-memory run's point files and statistics byte for byte (cmp, --no-timing), for
# 2D-7D lattices, the torus and the cube (conformant and drop), several slab counts down to slabs of one
# layer, every point format, --periodic and --rdf (the RDF CSV too); and refuse what it cannot stream with
# one line and no file. Runs the real
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
same_as_in_memory "4D cube" npy 7 --dim 4 --grid 7 --methods $all --domain cube
same_as_in_memory "5D cube" npy 2 --dim 5 --grid 4 --methods $all --domain cube
same_as_in_memory "7D cube" npy 3 --dim 7 --grid 3 --methods cnj,jitter --domain cube
same_as_in_memory "2D drop" npy 5 --dim 2 --grid 30 --methods cnj --domain-mode drop --step-scale 2
same_as_in_memory "3D drop" bin 4 --dim 3 --grid 8 --methods cnj --domain-mode drop --step-scale 2
same_as_in_memory "4D drop" dat 3 --dim 4 --grid 6 --methods cnj --domain-mode drop --step-scale 2
same_as_in_memory "5D drop" npy 5 --dim 5 --grid 5 --methods cnj --domain-mode drop --step-scale 2
# Drop mode must really drop points for the test above to mean anything.
"$bin" sample --dim 2 --grid 30 --methods cnj --domain-mode drop --step-scale 2 --no-timing --stream --slabs 5 \
  -o "$work/drop.csv" 2>/dev/null
dropped=$(awk -F, 'NR == 2 { print $25 }' "$work/drop.csv")
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

# --periodic and --rdf (issue 28 item 1, finished): minimum-image distances on the torus with a halo that
# wraps (the first and last slabs are neighbours; one slab, and two whose both neighbours are the same
# slab), and the RDF from per-slab pair counts with its query subset chosen by index: the stats CSV, the
# RDF CSV, the JSON and the point files are the in-memory run's.
same_with_rdf() {
  local name=$1 slabs=$2
  shift 2
  rm -rf "$work/mem" "$work/str"
  mkdir -p "$work/mem" "$work/str"
  local common=(--no-timing --points pts --format npy -o stats.csv --json run.json --rdf rdf.csv)
  if ! (cd "$work/mem" && "$bin" sample "$@" "${common[@]}") 2>"$work/err"; then
    bad "$name: in memory: $(head -c 300 "$work/err")"
    return
  fi
  if ! (cd "$work/str" && "$bin" sample "$@" "${common[@]}" --stream --slabs "$slabs") 2>"$work/err"; then
    bad "$name: streamed (--slabs $slabs): $(head -c 300 "$work/err")"
    return
  fi
  local differ=()
  for f in stats.csv run.json rdf.csv pts/*; do
    [[ -e $work/mem/$f ]] || continue
    cmp -s "$work/mem/$f" "$work/str/$f" || differ+=("$f")
  done
  # The RDF must hold a curve per method with pairs in it (g > 0 somewhere), else the cmp means little.
  local curves
  curves=$(awk -F, 'NR > 1 && $4 + 0 > 0 { print $2 }' "$work/mem/rdf.csv" | sort -u | wc -l)
  [[ ${#differ[@]} -eq 0 && $curves -ge 1 ]] && ok || bad "$name (--slabs $slabs): ${differ[*]} differ (curves with pairs: $curves)"
}
# The torus' nearest neighbours alone (rdf.csv then holds only the header), one slab to one layer each.
for slabs in 1 2 3 24; do
  same_as_in_memory "2D periodic" npy $slabs --dim 2 --grid 24 --methods $all --seed 5 --periodic
done
same_as_in_memory "5D periodic" npy 5 --dim 5 --grid 5 --methods $all --periodic
# With the RDF: torus and cube, --periodic or not, 2D-7D, --rdf-queries 0 (every point) and a subset.
for slabs in 1 2 24; do
  same_with_rdf "2D periodic rdf" $slabs --dim 2 --grid 24 --methods $all --seed 5 --periodic
done
same_with_rdf "2D cube rdf" 24 --dim 2 --grid 24 --methods $all --seed 5 --domain cube
same_with_rdf "3D periodic rdf, all queries" 5 --dim 3 --grid 10 --methods $all --periodic --rdf-queries 0
same_with_rdf "3D cube rdf, 50 queries" 10 --dim 3 --grid 10 --methods $all --rdf-queries 50 --domain cube
same_with_rdf "4D cube rdf" 6 --dim 4 --grid 6 --methods $all --domain cube --rdf-queries 200
same_with_rdf "5D periodic rdf, 100 queries" 5 --dim 5 --grid 5 --methods $all --periodic --rdf-queries 100
same_with_rdf "6D periodic rdf" 2 --dim 6 --grid 4 --methods cnj,jitter,sobol --periodic --rdf-bins 20
same_with_rdf "6D count periodic rdf" 4 --dim 6 --methods random,sobol -n 3000 --periodic --rdf-queries 300
same_with_rdf "7D periodic rdf" 3 --dim 7 --grid 3 --methods $all --periodic
same_with_rdf "7D cube rdf" 3 --dim 7 --grid 3 --methods cnj,jitter --domain cube
same_with_rdf "3D drop rdf" 4 --dim 3 --grid 8 --methods cnj --domain-mode drop --step-scale 2
# --rdf-max wider than a slab: the halo reaches over several slabs each way (7 of 24 here; on the torus
# 11 each way, and with 2 slabs each one's halo is the whole set), and beyond every slab in 3D.
same_with_rdf "2D cube rdf-max over 7 slabs" 24 --dim 2 --grid 24 --methods cnj,random --rdf-max 0.3 --domain cube
same_with_rdf "2D periodic rdf-max over 11 slabs" 24 --dim 2 --grid 24 --methods cnj,random --periodic --rdf-max 0.45
same_with_rdf "2D periodic rdf-max, 2 slabs" 2 --dim 2 --grid 24 --methods cnj,random --periodic --rdf-max 0.45
same_with_rdf "3D rdf-max beyond every slab" 6 --dim 3 --grid 6 --methods jitter --rdf-max 0.9 --rdf-bins 30 --domain cube
# A first halo too thin for some nearest neighbour (40 random points in 40 slabs: the halo starts at the
# mean spacing): the slab is measured again, exactly (test_streamed_statistics checks that it is).
same_with_rdf "2D thin halo" 40 --dim 2 --methods random -n 40 --seed 3
same_with_rdf "2D thin halo periodic" 40 --dim 2 --methods random -n 40 --seed 3 --periodic

# Past the memory limit the run streams by itself, with a note, and gives the same statistics.
"$bin" sample --dim 3 --grid 20 --methods cnj,sobol --no-timing -o "$work/mem.csv" 2>/dev/null
"$bin" sample --dim 3 --grid 20 --methods cnj,sobol --no-timing -o "$work/auto.csv" --max-memory 0.0005 2>"$work/err" &&
  ok || bad "automatic streaming failed: $(head -c 300 "$work/err")"
grep -q "note: .*streaming them in slabs (--stream)" "$work/err" && ok || bad "no note on automatic streaming: $(cat "$work/err")"
cmp -s "$work/mem.csv" "$work/auto.csv" && ok || bad "automatic streaming: statistics differ"
# ... with --periodic and --rdf too.
"$bin" sample --dim 3 --grid 20 --methods cnj,sobol --no-timing -o "$work/mem.csv" --periodic --rdf "$work/mem_rdf.csv" \
  --rdf-queries 500 2>/dev/null
"$bin" sample --dim 3 --grid 20 --methods cnj,sobol --no-timing -o "$work/auto.csv" --periodic --rdf "$work/auto_rdf.csv" \
  --rdf-queries 500 --max-memory 0.0005 2>"$work/err" && grep -q "streaming them in slabs" "$work/err" &&
  cmp -s "$work/mem.csv" "$work/auto.csv" && cmp -s "$work/mem_rdf.csv" "$work/auto_rdf.csv" &&
  ok || bad "automatic streaming with --periodic --rdf: $(head -c 300 "$work/err")"
# ... but not when the run cannot stream: the memory refusal stands.
expect_error "pds past the limit" "" "need about .* of memory" sample --dim 3 --grid 20 --methods pds --max-memory 0.0005

# Bad input: one line, non-zero exit, no file.
expect_error "slabs not dividing K" "" "--slabs 4 does not divide --grid 10" \
  sample --dim 3 --grid 10 --methods cnj --stream --slabs 4 -o "$work/bad.csv"
expect_error "pds" "" "not pds" sample --dim 3 --grid 6 --methods cnj,pds --stream -o "$work/bad.csv"
expect_error "jitter-matched" "" "not jitter-matched" sample --dim 3 --grid 6 --stream -o "$work/bad.csv"
expect_error "ball" "" "of a torus or cube into slabs, not --domain ball" sample --dim 3 --grid 6 --methods cnj --domain ball --stream -o "$work/bad.csv"
expect_error "periodic rdf-max" "" "--rdf-max 0.5 with --periodic must be below half" \
  sample --dim 3 --grid 6 --methods cnj --periodic --rdf "$work/rdf.csv" --rdf-max 0.5 --stream -o "$work/bad.csv"
expect_error "sets" "" "drop --sets 2" sample --dim 3 --grid 6 --methods cnj --sets 2 --stream -o "$work/bad.csv"
expect_error "slabs without stream" "" "--slabs applies to --stream" sample --dim 3 --grid 6 --methods cnj --slabs 2 -o "$work/bad.csv"
expect_error "more slabs than points" "" "more slabs than points" sample --dim 2 --methods sobol -n 4 --stream --slabs 8 -o "$work/bad.csv"
# A slab that does not fit says what helps (3D 20^3 jitter: 96 bytes a point, 400 points a layer, a halo
# of two layers): more slabs when a larger divisor of K fits, a smaller --rdf-max when the RDF's
# halo is what does not fit, else only more memory.
expect_error "more slabs help" "" "raise --slabs or --max-memory GIB$" \
  sample --dim 3 --grid 20 --methods jitter --stream --slabs 2 --max-memory 0.0002 -o "$work/bad.csv"
expect_error "the RDF halo does not fit" "" "; lower --rdf-max or raise --max-memory GIB$" \
  sample --dim 3 --grid 20 --methods jitter --stream --slabs 2 --max-memory 0.0002 --rdf "$work/rdf.csv" --rdf-max 0.4 \
  -o "$work/bad.csv"
expect_error "no slabs help" "" "; raise --max-memory GIB \\(a slab is one layer of the lattice already\\)$" \
  sample --dim 3 --grid 20 --methods jitter --stream --slabs 20 --max-memory 0.00005 -o "$work/bad.csv"
expect_error "automatic slabs" "" "; raise --max-memory GIB \\(a slab is one layer" \
  sample --dim 3 --grid 20 --methods jitter --stream --max-memory 0.00005 -o "$work/bad.csv"
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
