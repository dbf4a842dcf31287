#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The main job: install what is missing, build, and run the bundled default scene, the organ
# hanging from its left lobe under gravity (scenes/organ/Organ.scn, 100 steps unless -n N).
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/build.sh -DSTROMA_BUILD_TESTS=OFF
exec build/bin/stroma run scenes/organ/Organ.scn "$@"
