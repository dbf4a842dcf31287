#!/bin/bash
# SPDX-License-Identifier: MIT
# Writes sofa-beam-writestate.txt: SOFA's own WriteState output (positions and velocities,
# t = 0 to 0.1 s) of its example Component/Playback/WriteState.scn (a 3 x 3 x 7 grid beam under
# gravity), for ReadState_test's reading of a file written by SOFA. Needs runSofa
# (../shared/sofa-runtime/README.md; RUNSOFA=path overrides) and ../shared/sofa. A copy of the
# scene writes uncompressed velocities too; the scene itself is not changed.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
shared=${STROMA_SHARED_DIR:-$here/../../../../../shared}
runsofa=${RUNSOFA:-$(command -v runSofa || echo /tmp/sofa-runtime/sofa/bin/runSofa)}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
sed -e 's#filename="beamGravity.txt.gz" period="0.01" writeX="1" writeV="0"#filename="'"$work"'/beam.state" period="0.01" writeX="1" writeV="1"#' \
    "$shared/sofa/examples/Component/Playback/WriteState.scn" > "$work/beam.scn"
grep -q "$work/beam.state" "$work/beam.scn" || { echo "WriteState.scn changed: WriteState not edited" >&2; exit 1; }
# SOFA writes the state at the start of each step: -n 11 gives t = 0 to 0.1 s.
SOFA_DATA_PATH="$shared/sofa/share:$shared/sofa/examples" OMP_NUM_THREADS=1 \
  "$runsofa" -g batch -n 11 "$work/beam.scn" > "$work/log" 2>&1
cp "$work/beam.state" "$here/sofa-beam-writestate.txt"
echo "wrote $here/sofa-beam-writestate.txt ($(grep -c '^T=' "$here/sofa-beam-writestate.txt") records)"
