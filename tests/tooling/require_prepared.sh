#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Runs a tooling test's command once the sanitizer sub-build it needs exists; otherwise fails
# saying which step builds it (no test builds anything itself: see CMakeLists.txt).
# Usage: require_prepared.sh ASAN_BUILD_DIR COMMAND [ARGS...]
set -euo pipefail
asan=$1
shift
if [ ! -f "$asan/build.ninja" ] || [ ! -x "$asan/bin/SceneLoaderFuzzer" ]; then
  echo "the sanitizer sub-build is missing in $asan: tests/tooling/prepare.sh BUILD_DIR builds" \
    "it (scripts/test.sh runs it between the main build and ctest)" >&2
  exit 1
fi
exec "$@"
