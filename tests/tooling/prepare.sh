#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The builds that the tooling tests need, as a step of the test command (scripts/test.sh runs it
# after the main build and before ctest), so that no test's outcome depends on how fast the
# machine compiles:
#   1. the sanitizer sub-build of asan/ (clang; ASan, LSan, UBSan, libFuzzer) with the plugins
#      the fuzzers and the leak test load, into BUILD_DIR/tests/tooling/asan (incremental);
#   2. the install of the main build and the out-of-tree plugins built against it, into
#      BUILD_DIR/tests/tooling/install_test (install_test.sh prepare).
# The tests tooling_fuzz, tooling_fuzz_mesh, tooling_leak and tooling_install then only run
# what was built here, and fail with a message naming this script when it was not run.
# Usage: prepare.sh BUILD_DIR
set -euo pipefail

here=$(cd "$(dirname "$0")" && pwd)
build=$(cd "$1" && pwd)
tooling=$build/tests/tooling
mkdir -p "$tooling"

start=$SECONDS
"$here/asan_build.sh" "$tooling/asan"
echo "tooling: sanitizer sub-build ready ($((SECONDS - start)) s)"
start=$SECONDS
"$here/install_test.sh" prepare "$build" "$tooling/install_test"
echo "tooling: install and out-of-tree plugins ready ($((SECONDS - start)) s)"
