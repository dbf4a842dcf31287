#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The README's pictures (docs/pictures/*.png): the last frame of one scene of each main family,
# rendered offscreen by `stroma render` at 640x400, colored by displacement. Needs a build
# (scripts/build.sh or scripts/run-default.sh). Usage: scripts/make-pictures.sh [BUILD_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
build="${1:-build}"
out=docs/pictures
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$out"

picture() {  # NAME SCENE [render options...]
  local name=$1 scene=$2
  shift 2
  "$build/bin/stroma" render "$scene" -n 100 --size 640x400 --color-map displacement \
    --out "$work/$name" "$@" > "$work/$name.log"
  cp "$(ls "$work/$name"/frame_*.png | tail -n 1)" "$out/$name.png"
  echo "$out/$name.png: $scene, $(tail -n 1 "$work/$name.log" | cut -d: -f1)"
}

picture organ scenes/organ/Organ.scn
picture truth-cube scenes/sparsegrid/TruthCube.scn --camera "0.13 0.1 0.16  0 0 -0.005"
picture sparse-grid-organ scenes/sparsegrid/SparseGridOrgan.scn
picture probe-on-organ scenes/contact/ProbeSlidingOnOrgan.scn \
  --show "showVisual showCollisionModels"
