#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The main job: install what is missing, build, run the bundled default scene, the organ
# hanging from its left lobe under gravity (scenes/organ/Organ.scn, 100 steps unless -n N),
# then take a picture of its last frame colored by displacement (build/pictures/organ.png).
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/build.sh -DSTROMA_BUILD_TESTS=OFF
build/bin/stroma run scenes/organ/Organ.scn "$@"

# The picture: the same scene and steps again, offscreen (stroma render, OSMesa).
steps=100
args=("$@")
for ((i = 0; i < ${#args[@]}; ++i)); do
  if [[ "${args[i]}" == "-n" && $((i + 1)) -lt ${#args[@]} ]]; then steps="${args[i + 1]}"; fi
done
frames=build/pictures/organ-frames
rm -rf "$frames"
build/bin/stroma render scenes/organ/Organ.scn -n "$steps" --size 1280x720 \
  --color-map displacement --out "$frames" > build/pictures-render.log
last=$(ls "$frames"/frame_*.png | tail -n 1)
cp "$last" build/pictures/organ.png
echo "Picture of the last frame (step $steps, colored by displacement): build/pictures/organ.png"
