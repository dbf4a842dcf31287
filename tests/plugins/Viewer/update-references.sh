#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Regenerates the reference pictures of SceneViewer_test (tests/plugins/Viewer/reference/) from
# this build's viewer under xvfb-run: run after a deliberate change of the drawing, look at the
# pictures, commit them. Usage: update-references.sh [BUILD_DIR] (default: build).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
build="${1:-$here/../../../build}"
ninja -C "$build" SceneViewer_test
cd "$here/../../.."
STROMA_UPDATE_VIEWER_REFERENCES=1 xvfb-run -a -s "-screen 0 1024x768x24 -noreset" \
  "$build/tests/SceneViewer_test" --gtest_filter='*ReferencePictures'
ls -l "$here/reference"
