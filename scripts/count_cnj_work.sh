#!/usr/bin/env bash
# Instructions per CNJ point in 7D under callgrind (repeatable, unlike seconds), against the
# arithmetic floor printed by count_cnj_work. Usage: scripts/count_cnj_work.sh [build dir] [noise basis, default turning-bands]
# [mode: free (default; the free field), torus (the main job's default domain) or cube (conformant, the bounded field)]
set -euo pipefail
build=${1:-build}
basis=${2:-turning-bands}
mode=${3:-free}
tool=$build/scripts/count_cnj_work
command -v valgrind >/dev/null || { echo "count_cnj_work.sh: valgrind not found (apt-get install valgrind)" >&2; exit 1; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
small=2000
large=6000
instructions() {
  valgrind --tool=callgrind --callgrind-out-file="$tmp/cg.$1" "$tool" "$1" "$basis" "$mode" >"$tmp/out.$1" 2>"$tmp/err.$1"
  grep -E "Collected : " "$tmp/err.$1" | awk '{ print $4 }'
}
a=$(instructions $small)
b=$(instructions $large)
per_point=$(( (b - a) / (large - small) ))
floor=$(awk '/floor_ops_per_point/ { print $2 }' "$tmp/out.$large")
cat "$tmp/out.$large"
echo "instructions_per_point $per_point"
awk -v i="$per_point" -v f="$floor" 'BEGIN { printf "instructions / floor operations: %.2f\n", i / f }'
