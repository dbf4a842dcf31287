#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Builds Stroma with its tests, then what the tooling tests run (the sanitizer sub-build, the
# install and the out-of-tree plugins: tests/tooling/prepare.sh), and runs the whole suite
# (unit, scene, install, leak and fuzz tests). Every build is a step here, none is a test: no
# test depends on how fast the machine compiles. CI runs exactly this (.ci/run).
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/build.sh -DSTROMA_BUILD_TESTS=ON
./tests/tooling/prepare.sh build
cd build
ctest --output-on-failure --parallel "$(nproc)" "$@"
