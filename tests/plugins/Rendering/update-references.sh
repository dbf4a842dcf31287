#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Regenerates the reference pictures of RenderCommand_test (tests/plugins/Rendering/reference/)
# from this build's `stroma render`: run after a deliberate change of the drawing, look at the
# pictures, commit them. Usage: update-references.sh [BUILD_DIR] (default: build).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
build="${1:-$here/../../../build}"
ninja -C "$build" RenderCommand_test
STROMA_UPDATE_RENDER_REFERENCES=1 "$build/tests/RenderCommand_test" \
  --gtest_filter=RenderCommand.BundledScenesMatchTheirReferencePictures
ls -l "$here/reference"
