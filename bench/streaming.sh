#!/usr/bin/env bash
# Streamed against in-memory `sample` runs (issue 28 item 3's streamed half): wall time, peak RSS
# (/usr/bin/time -v) and byte identity (cmp) of the point file and the statistics CSV (and with RDF=1 in the
# environment, of --rdf's CSV too). Results: bench/streaming.md, bench/results.md.
# Usage: [RDF=1] bench/streaming.sh BINARY WORKDIR CASE... where CASE is "NAME|ARGS" (ARGS as for `sample`;
# --stream and --slabs S there apply to the streamed run only: "NAME|ARGS|S" gives it --slabs S).
set -u
bin=$1 work=$2
shift 2
mkdir -p "$work"
for case in "$@"; do
  name=${case%%|*} args=${case#*|} slabs=0
  if [[ $args == *\|* ]]; then slabs=${args##*|} args=${args%|*}; fi
  for mode in memory stream; do
    extra=()
    [[ $mode == stream ]] && extra=(--stream)
    [[ $mode == stream && $slabs != 0 ]] && extra+=(--slabs "$slabs")
    [[ ${RDF:-0} == 1 ]] && extra+=(--rdf "$work/$mode.rdf.csv")
    rm -rf "$work/$mode"
    if [[ $args == *--no-stats* ]]; then stats=(); else stats=(-o "$work/$mode.csv"); fi
    # shellcheck disable=SC2086
    /usr/bin/time -v "$bin" sample $args --no-timing -q --points "$work/$mode" --format npy "${stats[@]}" \
      "${extra[@]}" 2>"$work/$mode.time"
    wall=$(sed -n 's/.*Elapsed (wall clock) time.*: //p' "$work/$mode.time")
    rss=$(sed -n 's/.*Maximum resident set size (kbytes): //p' "$work/$mode.time")
    user=$(sed -n 's/.*User time (seconds): //p' "$work/$mode.time")
    points=$(awk -F, 'NR == 2 { print $4 }' "$work/$mode.csv" 2>/dev/null)
    echo "$name | $mode | $args | points ${points:-?} | wall $wall | user $user s | peak RSS $((rss / 1024)) MiB"
  done
  same=yes
  [[ $args == *--no-stats* ]] || cmp -s "$work/memory.csv" "$work/stream.csv" || same="no (stats)"
  [[ ${RDF:-0} == 1 ]] && { cmp -s "$work/memory.rdf.csv" "$work/stream.rdf.csv" || same="no (rdf)"; }
  for f in "$work"/memory/*; do cmp -s "$f" "$work/stream/$(basename "$f")" || same="no ($(basename "$f"))"; done
  echo "$name | identical: $same"
  rm -rf "$work/memory" "$work/stream"
done
