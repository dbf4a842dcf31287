#!/bin/bash
# SPDX-License-Identifier: MIT
# Writes tests/scenes/liver-sofa-positions.txt: the liver's positions after 100 steps of SOFA's
# Demos/liver.scn, as SOFA's own WriteState prints them (6 significant digits), for
# SofaCollisionScenes.LiverFollowsSofasTrajectory. Needs runSofa (../shared/sofa-runtime/README.md;
# RUNSOFA=path overrides) and ../shared/sofa. A copy of the scene gets a WriteState next to the
# liver's MechanicalObject; the scene itself is not changed.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
shared=${STROMA_SHARED_DIR:-$root/../shared}
runsofa=${RUNSOFA:-$(command -v runSofa || echo /tmp/sofa/sofa/bin/runSofa)}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
sed -e 's#<FixedProjectiveConstraint  name="FixedProjectiveConstraint" indices="3 39 64" />#&\n<WriteState filename="'"$work"'/liver.state" period="0.02" writeX="1"/>#' \
    -e 's#<RequiredPlugin pluginName="Sofa.Component.Mass"/>#&\n<RequiredPlugin pluginName="Sofa.Component.Playback"/>#' \
    "$shared/sofa/examples/Demos/liver.scn" > "$work/liver.scn"
grep -q WriteState "$work/liver.scn" || { echo "liver.scn changed: WriteState not inserted" >&2; exit 1; }
# SOFA writes the state at the start of each step: -n 101 gives t = 2 s, after 100 steps.
SOFA_DATA_PATH="$shared/sofa/share:$shared/sofa/examples" OMP_NUM_THREADS=1 \
  "$runsofa" -g batch -n 101 "$work/liver.scn" > "$work/log" 2>&1
out=$root/tests/scenes/liver-sofa-positions.txt
{
  echo "# /lroot/Liver/dofs positions (x y z per point) of SOFA's examples/Demos/liver.scn after 100"
  echo "# steps (t = 2 s), SOFA's WriteState output (runSofa of ../shared/sofa-runtime, one thread)."
  echo "# Made by scripts/make-sofa-liver-reference.sh."
  awk '/^T= 2$/ { found = 1; next } found && /X=/ { sub(/^ *X= */, ""); n = split($0, v, " ");
       for (i = 1; i <= n; i += 3) print v[i], v[i + 1], v[i + 2]; exit }' "$work/liver.state"
} > "$out"
echo "wrote $out ($(grep -vc '^#' "$out") points)"
