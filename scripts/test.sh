#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Builds Stroma with its tests and runs the whole suite (unit, scene, install, leak and fuzz
# tests). CI runs exactly this (.ci/run).
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/build.sh -DSTROMA_BUILD_TESTS=ON
cd build
ctest --output-on-failure --parallel "$(nproc)" "$@"
