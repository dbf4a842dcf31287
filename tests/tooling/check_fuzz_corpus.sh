#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The scene fuzzer's seed corpus under the sanitizer sub-build's stroma: every valid_* seed
# loads and runs 2 steps (exit 0), so the sub-build has the plugins its components come from
# (asan/CMakeLists.txt, STROMA_PLUGINS) and the fuzzer starts from scenes that get past the
# loader; every other seed is refused as bad input (exit 2), never a crash or a sanitizer
# report.
# Usage: check_fuzz_corpus.sh SANITIZED_STROMA PLUGIN_DIR CORPUS_DIR
set -euo pipefail
stroma=$1
export STROMA_PLUGIN_PATH=$2
corpus=$3
export ASAN_OPTIONS=detect_leaks=1
export UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1
unset STROMA_DATA_PATH

failed=0
for seed in "$corpus"/*; do
  name=$(basename "$seed")
  expected=2
  case "$name" in valid_*) expected=0 ;; esac
  rc=0
  output=$("$stroma" run "$seed" -n 2 2>&1) || rc=$?
  if [ "$rc" -ne "$expected" ]; then
    echo "$name: exit code $rc, expected $expected" >&2
    echo "$output" | tail -n 30 >&2
    failed=1
  else
    echo "$name: exit code $rc as expected"
  fi
done
exit "$failed"
