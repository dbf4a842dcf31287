#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Frames per second of `stroma render` on the default organ scene at 1280x720: a frame after
# every step, 100 steps, with the scene's own look (its FEM mesh) and with the displacement
# color map and legend. Each line of `stroma render`'s summary splits the time into drawing
# (OpenGL in OSMesa, and reading the pixels back), writing (PNG files) and stepping.
# Usage: bench-render.sh [BUILD_DIR] [STEPS]   (default: build, 100)
set -euo pipefail
root="$(cd "$(dirname "$0")/../../.." && pwd)"
build="${1:-$root/build}"
steps="${2:-100}"
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
for options in "" "--color-map displacement"; do
  echo "== stroma render scenes/organ/Organ.scn -n $steps --every 1 --size 1280x720 $options"
  # shellcheck disable=SC2086
  "$build/bin/stroma" render "$root/scenes/organ/Organ.scn" -n "$steps" --every 1 \
    --size 1280x720 --out "$out" $options 2>/dev/null | tail -1
done
