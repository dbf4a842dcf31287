#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""The cantilever of ../CantileverSmallHexa.scn solved by CalculiX (ccx, Debian calculix-ccx),
an independent finite-element code, written as a Stroma state file (docs/state-format.md).

Box [0, 1] x [0, 0.1] x [0, 0.1] m, E = 1e8 Pa, nu = 0.3, face x = 0 fixed, 100 N along -z
(or --load) spread evenly on the nodes of the face x = 1 (the same nodal loads as
ConstantForceField's totalForce); --nlgeom solves the large-deflection problem of
../CantileverLargeHexa.scn (1666.67 N, geometric nonlinearity, the dead load in increments).
Nodes are numbered as RegularGridTopology's points (x fastest, then y, then z). Elements: C3D8I (8-node bricks with incompatible modes, which bend without
shear locking), nx x ny x nz of them. The state file holds two snapshots, the rest positions
(step 0, so that ReferenceComparison can locate the nodes in another mesh) and rest +
displacement (step 1), of a state named /root/Beam/dofs. ccx's .frd file prints displacements
with 6 significant digits: the reference is good to about 1e-6 relative.

    share/reference/calculix/cantilever_ccx.py [--cells 80 8 8] [--load 100] [--nlgeom] [--output FILE]

The files of this folder:
    cantilever_ccx.py                                    -> CantileverSmallCalculix.state
    cantilever_ccx.py --cells 60 6 6 --load 1666.6667 --nlgeom \
        --output share/reference/calculix/CantileverLargeCalculix.state
"""
import argparse
import os
import shutil
import subprocess
import sys
import tempfile


def write_inp(path, cells, load, nlgeom):
    nx, ny, nz = cells
    size = (1.0, 0.1, 0.1)
    def node_id(i, j, k):
        return 1 + i + (nx + 1) * (j + (ny + 1) * k)
    nodes = []
    with open(path, "w") as f:
        f.write("*HEADING\nStroma cantilever reference (share/reference/calculix/cantilever_ccx.py)\n")
        f.write("*NODE, NSET=NALL\n")
        for k in range(nz + 1):
            for j in range(ny + 1):
                for i in range(nx + 1):
                    x = (size[0] * i / nx, size[1] * j / ny, size[2] * k / nz)
                    nodes.append(x)
                    f.write("%d, %.17g, %.17g, %.17g\n" % (node_id(i, j, k), *x))
        f.write("*ELEMENT, TYPE=C3D8I, ELSET=EALL\n")
        e = 1
        for k in range(nz):
            for j in range(ny):
                for i in range(nx):
                    # Abaqus/CalculiX brick order: face z = k counter-clockwise, then z = k + 1.
                    ids = [node_id(i, j, k), node_id(i + 1, j, k), node_id(i + 1, j + 1, k),
                           node_id(i, j + 1, k), node_id(i, j, k + 1), node_id(i + 1, j, k + 1),
                           node_id(i + 1, j + 1, k + 1), node_id(i, j + 1, k + 1)]
                    f.write("%d, %s\n" % (e, ", ".join(map(str, ids))))
                    e += 1
        clamped = [node_id(0, j, k) for k in range(nz + 1) for j in range(ny + 1)]
        tip = [node_id(nx, j, k) for k in range(nz + 1) for j in range(ny + 1)]
        f.write("*NSET, NSET=CLAMPED\n")
        for n in clamped:
            f.write("%d,\n" % n)
        f.write("*MATERIAL, NAME=BEAM\n*ELASTIC\n1e8, 0.3\n")
        f.write("*SOLID SECTION, ELSET=EALL, MATERIAL=BEAM\n")
        f.write("*BOUNDARY\nCLAMPED, 1, 3\n")
        # Large deflection: geometric nonlinearity, the dead load applied in increments.
        f.write("*STEP, NLGEOM, INC=1000\n*STATIC\n0.05, 1.0, 1e-6, 0.1\n" if nlgeom
                else "*STEP\n*STATIC\n")
        f.write("*CLOAD\n")
        for n in tip:
            f.write("%d, 3, %.17g\n" % (n, -load / len(tip)))
        f.write("*NODE FILE\nU\n*END STEP\n")
    return nodes


def read_frd_displacements(path, count):
    """The last DISP block of a .frd file (the end of the step): node id -> (ux, uy, uz)."""
    u, block = {}, None
    with open(path) as f:
        for line in f:
            if line.startswith(" -4  DISP"):
                block = {}
            elif block is not None and line.startswith(" -3"):
                u, block = block, None
            elif block is not None and line.startswith(" -1"):
                node = int(line[3:13])
                block[node] = tuple(float(line[13 + 12 * c:25 + 12 * c]) for c in range(3))
    if len(u) != count:
        sys.exit("cantilever_ccx.py: %s holds %d displacements, expected %d" % (path, len(u), count))
    return u


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--cells", type=int, nargs=3, default=[80, 8, 8])
    parser.add_argument("--load", type=float, default=100.0, help="total tip load (N), along -z")
    parser.add_argument("--nlgeom", action="store_true",
                        help="geometrically nonlinear (large deflection), dead load")
    parser.add_argument("--output", default=os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                                         "CantileverSmallCalculix.state"))
    args = parser.parse_args()
    ccx = shutil.which("ccx")
    if not ccx:
        sys.exit("cantilever_ccx.py: no ccx (Debian package calculix-ccx)")
    work = tempfile.mkdtemp(prefix="stroma_ccx_")
    nodes = write_inp(os.path.join(work, "cantilever.inp"), args.cells, args.load, args.nlgeom)
    run = subprocess.run([ccx, "-i", "cantilever"], cwd=work, capture_output=True, text=True)
    if run.returncode != 0 or not os.path.exists(os.path.join(work, "cantilever.frd")):
        sys.exit("cantilever_ccx.py: ccx failed:\n" + run.stdout[-2000:] + run.stderr[-2000:])
    u = read_frd_displacements(os.path.join(work, "cantilever.frd"), len(nodes))
    version = run.stdout.split("Version")[1].split()[0].rstrip(",") if "Version" in run.stdout else "?"
    with open(args.output, "w") as f:
        f.write("# stroma-state 1\n")
        f.write("# made by: share/reference/calculix/cantilever_ccx.py --cells %d %d %d --load %s%s\n"
                % (*args.cells, repr(args.load), " --nlgeom" if args.nlgeom else ""))
        f.write("# with: CalculiX ccx %s, C3D8I elements, %s\n" % (
            version, "geometrically nonlinear static (NLGEOM), dead load in increments"
            if args.nlgeom else "linear static"))
        for step, moved in ((0, False), (1, True)):
            f.write("snapshot time %d step %d\n" % (step, step))
            f.write("state /root/Beam/dofs Vec3d %d 3 3\n" % len(nodes))
            for n, x in enumerate(nodes, start=1):
                d = u[n] if moved else (0.0, 0.0, 0.0)
                f.write("%.17g %.17g %.17g 0 0 0\n" % (x[0] + d[0], x[1] + d[1], x[2] + d[2]))
            f.write("end\n")
    shutil.rmtree(work)
    print("wrote %s (%d nodes)" % (args.output, len(nodes)))


if __name__ == "__main__":
    main()
