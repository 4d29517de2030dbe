#!/usr/bin/env bash
# scripts/check_floors on small trees: it passes downward, rooted includes and fails an upward include
# and an include without the dfvn/ root, naming the file and line.
#   test_check_floors.sh SOURCE_DIR
set -euo pipefail
check=$1/scripts/check_floors
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

mkdir -p "$work/src/core" "$work/src/noise" "$work/tests/noise"
echo '#pragma once' >"$work/src/core/a.hpp"
printf '#pragma once\n#include "dfvn/core/a.hpp"\n' >"$work/src/noise/b.hpp"
printf '#include "dfvn/noise/b.hpp"\n' >"$work/tests/noise/test_b.cpp"
"$check" "$work" >"$work/out" 2>&1 || { cat "$work/out" >&2; fail "a tree of downward includes fails"; }

printf '#pragma once\n#include "dfvn/noise/b.hpp"\n' >"$work/src/core/a.hpp"
if "$check" "$work" >"$work/out" 2>&1; then fail "an upward include passes"; fi
grep -q 'src/core/a.hpp:2: upward include of noise/' "$work/out" || { cat "$work/out" >&2; fail "no upward message"; }

echo '#pragma once' >"$work/src/core/a.hpp"
printf '#include "noise/b.hpp"\n' >"$work/tests/noise/test_b.cpp"
if "$check" "$work" >"$work/out" 2>&1; then fail "an include without the dfvn/ root passes"; fi
grep -q 'tests/noise/test_b.cpp:1: include without the dfvn/ root' "$work/out" || { cat "$work/out" >&2; fail "no root message"; }
echo "ok: check_floors passes downward includes, fails upward and unrooted ones"
