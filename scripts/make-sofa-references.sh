#!/bin/bash
# SPDX-License-Identifier: MIT
# Writes the SOFA reference positions that the tests compare with (tests/scenes/SofaReference.h):
# the positions of one state after N steps of a SOFA example scene, as SOFA's own WriteState
# prints them (6 significant digits):
#   tests/plugins/Constraint/sofa-fixed-plane-liver-positions.txt
#     FixedPlaneProjectiveConstraint.scn, /root/Liver/dofs, 100 steps
#   tests/plugins/MechanicalLoad/sofa-triangle-pressure-positions.txt
#     TrianglePressureForceField.scn, /root/TT/Volume, 100 steps
#   tests/plugins/SolidMechanics/sofa-triangle-fem-m{1,2,3}-positions.txt
#     TriangleFEMForceField.scn, /root/M1..M3/mechanicalObject, 100 steps
# Needs runSofa (../shared/sofa-runtime/README.md; RUNSOFA=path overrides) and ../shared/sofa.
# A copy of each scene gets a WriteState next to the state; the scenes are not changed.
# (The liver of SofaCollisionScenes has its own script, make-sofa-liver-reference.sh.)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
shared=${STROMA_SHARED_DIR:-$root/../shared}
runsofa=${RUNSOFA:-$(command -v runSofa || echo /tmp/sofa/sofa/bin/runSofa)}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# reference SCENE STATE DT STEPS OUT DESCRIPTION. STATE: the MechanicalObject's name, or #K for
# the K-th MechanicalObject of the file (from 0) when they have no names.
reference() {
  local scene=$1 state=$2 dt=$3 steps=$4 out=$5 what=$6
  python3 - "$shared/sofa/examples/$scene" "$state" "$dt" "$work/copy.scn" "$work/out.state" <<'PY'
import re, sys
src, state, dt, out, written = sys.argv[1:6]
s = open(src).read()
if state.startswith('#'):
    found = list(re.finditer(r'<MechanicalObject\b[^>]*/>', s))
    k = int(state[1:])
    m = found[k] if k < len(found) else None
else:
    m = re.search(r'<MechanicalObject[^>]*name="%s"[^>]*/>' % re.escape(state), s)
if not m: sys.exit("no MechanicalObject %s in %s" % (state, src))
s = s[:m.end()] + '\n<WriteState filename="%s" period="%s" writeX="1"/>' % (written, dt) + s[m.end():]
s = re.sub(r'(<Node[^>]*>)', r'\1\n<RequiredPlugin pluginName="Sofa.Component.Playback"/>', s, count=1)
open(out, 'w').write(s)
PY
  # SOFA writes the state at the start of each step: -n STEPS+1 gives the state after STEPS.
  (cd "$(dirname "$shared/sofa/examples/$scene")" &&
    SOFA_DATA_PATH="$shared/sofa/share:$shared/sofa/examples" OMP_NUM_THREADS=1 \
      "$runsofa" -g batch -n $((steps + 1)) "$work/copy.scn" > "$work/log" 2>&1)
  local t
  t=$(python3 -c "print(round($dt * $steps, 10))")
  {
    echo "# $what positions (x y z per point) of SOFA's examples/$scene"
    echo "# after $steps steps (t = $t s), SOFA's WriteState output (runSofa of ../shared/sofa-runtime,"
    echo "# one thread). Made by scripts/make-sofa-references.sh."
    python3 - "$work/out.state" "$t" <<'PY'
import sys
path, t = sys.argv[1], float(sys.argv[2])
found = False
for line in open(path):
    if line.startswith('T='):
        found = abs(float(line.split()[1]) - t) < 1e-9
    elif found and line.strip().startswith('X='):
        v = line.split()[1:]
        for i in range(0, len(v), 3): print(v[i], v[i + 1], v[i + 2])
        sys.exit(0)
sys.exit("no state at t = %g" % t)
PY
  } > "$root/$out"
  echo "wrote $out ($(grep -vc '^#' "$root/$out") points)"
}

reference Component/Constraint/Projective/FixedPlaneProjectiveConstraint.scn dofs 0.02 100 \
  tests/plugins/Constraint/sofa-fixed-plane-liver-positions.txt "/root/Liver/dofs"
reference Component/MechanicalLoad/TrianglePressureForceField.scn Volume 0.05 100 \
  tests/plugins/MechanicalLoad/sofa-triangle-pressure-positions.txt "/root/TT/Volume"
for k in 1 2 3; do
  reference Component/SolidMechanics/FEM/TriangleFEMForceField.scn "#$((k - 1))" 0.05 100 \
    tests/plugins/SolidMechanics/sofa-triangle-fem-m$k-positions.txt "/root/M$k/mechanicalObject"
done
