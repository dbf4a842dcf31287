#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Runs a fuzzer (the scene loader's by default) for a bounded time. Fails on any crash, leak, timeout, excess
# memory or sanitizer report; the input that triggered it is saved in WORK_DIR/artifacts/ and
# reproduces with `SceneLoaderFuzzer FILE` (same STROMA_PLUGIN_PATH).
# New interesting inputs go to WORK_DIR/corpus, kept between runs; the seed corpus in fuzz/corpus
# is only read.
# Usage: run_fuzzer.sh FUZZER PLUGIN_DIR WORK_DIR [SECONDS [SEED_CORPUS [DICTIONARY]]]
#   SEED_CORPUS: default fuzz/corpus; DICTIONARY: default fuzz/scene.dict, "none" for none
#   STROMA_FUZZ_SEED: libFuzzer's -seed (default 1, so that CI runs are alike; 0 is random)
set -euo pipefail

fuzzer=$(realpath "$1")
plugins=$(realpath "$2")
work=$3
seconds=${4:-30}
here=$(cd "$(dirname "$0")" && pwd)
seeds=${5:-$here/fuzz/corpus}
dictionary=${6:-$here/fuzz/scene.dict}
dict_option=()
[ "$dictionary" != none ] && dict_option=(-dict="$dictionary")

mkdir -p "$work/corpus" "$work/artifacts" "$work/cwd"
rm -f "$work"/artifacts/*
export STROMA_PLUGIN_PATH=$plugins
unset STROMA_DATA_PATH
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=0:allocator_may_return_null=0
export UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1
log=$work/fuzz.log

# From a scratch directory: relative <include> names then resolve nowhere interesting.
rc=0
(cd "$work/cwd" && "$fuzzer" "$work/corpus" "$seeds" "${dict_option[@]}" \
  -max_total_time="$seconds" -rss_limit_mb=2048 -timeout=10 -max_len=4096 \
  -seed="${STROMA_FUZZ_SEED:-1}" -artifact_prefix="$work/artifacts/" -print_final_stats=1) \
  >"$log" 2>&1 || rc=$?

if [ "$rc" -ne 0 ] || grep -Eq '^(==[0-9]+==ERROR|SUMMARY: |.*runtime error: )' "$log"; then
  # The report: from the first sanitizer or libFuzzer error line on.
  grep -n -m1 -E '^(==[0-9]+==|.*runtime error: |ALARM: |.*ERROR: libFuzzer)' "$log" |
    cut -d: -f1 | xargs -r -I{} tail -n +{} "$log" | head -n 120 >&2
  echo "run_fuzzer: FAIL (exit code $rc); full log: $log" >&2
  for artifact in "$work"/artifacts/*; do
    [ -e "$artifact" ] && echo "run_fuzzer: reproducer: STROMA_PLUGIN_PATH=$plugins $fuzzer $artifact" >&2
  done
  exit 1
fi
tail -n 8 "$log"
echo "run_fuzzer: OK, no crash, leak or sanitizer report in ${seconds} s"
