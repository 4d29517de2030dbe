#!/usr/bin/env bash
# A bounded libFuzzer run, as ctest runs it (tests/CMakeLists.txt, with -DDFVN_FUZZ=ON):
#   run_fuzzer.sh FUZZER SEED_CORPUS SECONDS ARTIFACT_DIR [DICTIONARY]
# The seed corpus (tests/fuzz/corpus/<reader>) is replayed first, so every input that once crashed a
# reader is a regression test; then FUZZER mutates for SECONDS into a scratch corpus (the source tree is
# never written). libFuzzer's seed is DFVN_FUZZ_SEED (default 1), printed, so a run can be repeated. A
# crash, a broken reader promise (tests/fuzz/fuzz_contract.hpp) or a sanitizer report fails the test and
# leaves the input in ARTIFACT_DIR as crash-<sha1>; add it to the corpus and a GoogleTest case.
set -euo pipefail
fuzzer=$1 seeds=$2 seconds=$3 artifacts=$4 dictionary=${5:-}
scratch=$(mktemp -d)
log=$(mktemp)
trap 'rm -rf "$scratch" "$log"' EXIT
mkdir -p "$artifacts"
seed=${DFVN_FUZZ_SEED:-1}
echo "$(basename "$fuzzer"): ${seconds} s from $(find "$seeds" -type f | wc -l) seed inputs, libFuzzer -seed=$seed"
options=(-seed="$seed" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=4096
         -artifact_prefix="$artifacts/" -print_final_stats=1)
[[ -n $dictionary ]] && options+=(-dict="$dictionary")
status=0
"$fuzzer" "${options[@]}" "$scratch" "$seeds" >"$log" 2>&1 || status=$?
# libFuzzer's progress lines (NEW, REDUCE, pulse) are many; the rest says what ran and what failed.
grep -v -E '^#[0-9]+[[:space:]]+(NEW|REDUCE|pulse)' "$log" || true
[[ $status -eq 0 ]] || echo "$(basename "$fuzzer") FAILED (status $status); inputs in $artifacts" >&2
exit "$status"
