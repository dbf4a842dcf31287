#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Configures and builds the sanitizer sub-build of asan/ (ASan + LSan + UBSan, libFuzzer
# coverage) with clang and ccache. prepare.sh runs it before ctest (scripts/test.sh); later runs
# are incremental (a few seconds). Ninja's progress goes to BUILD_DIR/build.log, the errors to
# stderr.
# The CHOLMOD plugin is left out: libcholmod (with its BLAS/OpenMP) leaks a few bytes when it is
# loaded, which LeakSanitizer reports against a library Stroma does not control.
# Usage: asan_build.sh BUILD_DIR
set -euo pipefail

here=$(cd "$(dirname "$0")" && pwd)
build=$1
cmake=${CMAKE_COMMAND:-cmake}

cxx=${STROMA_TOOLING_CXX:-$(command -v clang++ || command -v clang++-14 || true)}
if [ -z "$cxx" ]; then
  echo "asan_build: clang++ not found (scripts/install-deps.sh installs clang and" \
    "libclang-rt-14-dev)" >&2
  exit 1
fi
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)

mkdir -p "$build"
"$cmake" -S "$here/asan" -B "$build" -G Ninja -DCMAKE_CXX_COMPILER="$cxx" \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSTROMA_SANITIZE=address,undefined,fuzzer-no-link \
  -DSTROMA_BUILD_TESTS=OFF -DSTROMA_WITH_CHOLMOD=OFF "${launcher[@]}" >"$build/configure.log" 2>&1 || {
  cat "$build/configure.log" >&2
  exit 1
}
# The plugin-index step of each plugin runs the sanitized stroma, leak check included.
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1}
"$cmake" --build "$build" >"$build/build.log" 2>&1 || {
  grep -v '^\[[0-9]*/[0-9]*\] ' "$build/build.log" | tail -n 60 >&2
  echo "asan_build: the sanitizer sub-build failed; full log: $build/build.log" >&2
  exit 1
}
