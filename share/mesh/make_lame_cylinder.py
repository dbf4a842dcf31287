#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Lame's thick cylinder for the volumetric-locking scenes (issue 7, item 6).

Writes share/mesh/lame_cylinder.msh (Gmsh 2.2 ASCII, hexahedra): a quarter of the cross-section
a = 1 < r < b = 2 m, one layer 0.25 m thick along z, RADIAL x ANGULAR cells, vertex order of
SOFA's hexahedra (the radial, angular and axial directions as the reference x, y, z). The
tetrahedral force fields split each hexahedron into 6 tetrahedra around its 0-6 diagonal.

Writes scenes/locking/LameCylinderTetrahedra.scn and LameCylinderHexahedra.scn: the plain and
the locking-free element side by side (translated along x), nu = 0.499, E = 1e6 Pa, internal
pressure p = 1e3 Pa as nodal forces (each inner face, a flat quadrilateral of chord c and
height h, gives p c h / 4 to each of its corners along its normal), plane strain (every point
fixed along z), symmetry on the planes x = 0 and y = 0, a static Newton solve, and a
ReferenceComparison against the closed form at the inner points.

Usage: python3 share/mesh/make_lame_cylinder.py (no arguments; standard library only).
"""
import math
import os

RADIAL, ANGULAR = 6, 12
INNER, OUTER, THICKNESS = 1.0, 2.0, 0.25
YOUNG, POISSON, PRESSURE = 1e6, 0.499, 1e3
YOUNG_TEXT = "1e6"
OFFSET = 3.0  # distance between the two bodies of a scene, along x (m)

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))


def point_index(i, j, k):
    return i + (RADIAL + 1) * (j + (ANGULAR + 1) * k)


def make_mesh():
    points = []
    for k in range(2):
        for j in range(ANGULAR + 1):
            for i in range(RADIAL + 1):
                r = INNER + (OUTER - INNER) * i / RADIAL
                theta = math.pi / 2 * j / ANGULAR
                points.append((r * math.cos(theta), r * math.sin(theta), THICKNESS * k))
    hexahedra = []
    for j in range(ANGULAR):
        for i in range(RADIAL):
            hexahedra.append([point_index(i, j, 0), point_index(i + 1, j, 0),
                              point_index(i + 1, j + 1, 0), point_index(i, j + 1, 0),
                              point_index(i, j, 1), point_index(i + 1, j, 1),
                              point_index(i + 1, j + 1, 1), point_index(i, j + 1, 1)])
    return points, hexahedra


def pressure_forces(points, hexahedra):
    """Nodal forces of the internal pressure: {point: (fx, fy, fz)}."""
    forces = {}
    for h in hexahedra:
        p0, p3, p4 = points[h[0]], points[h[3]], points[h[4]]
        if abs(math.hypot(p0[0], p0[1]) - INNER) > 1e-9:
            continue
        chord = [p3[a] - p0[a] for a in range(3)]
        height = [p4[a] - p0[a] for a in range(3)]
        # chord x height: |chord| |height|, pointing to +r.
        normal = (chord[1] * height[2] - chord[2] * height[1],
                  chord[2] * height[0] - chord[0] * height[2],
                  chord[0] * height[1] - chord[1] * height[0])
        for v in (h[0], h[3], h[4], h[7]):
            f = forces.setdefault(v, [0.0, 0.0, 0.0])
            for a in range(3):
                f[a] += PRESSURE / 4 * normal[a]
    return forces


def write_msh(path, points, hexahedra):
    with open(path, "w") as out:
        out.write("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n%d\n" % len(points))
        for n, p in enumerate(points):
            out.write("%d %.17g %.17g %.17g\n" % (n + 1, p[0], p[1], p[2]))
        out.write("$EndNodes\n$Elements\n%d\n" % len(hexahedra))
        for n, h in enumerate(hexahedra):
            out.write("%d 5 2 1 1 %s\n" % (n + 1, " ".join(str(v + 1) for v in h)))
        out.write("$EndElements\n")


def body(name, x, field, description, inner, forces):
    lame = (1 + POISSON) / YOUNG * PRESSURE * INNER ** 2 / (OUTER ** 2 - INNER ** 2) * (
        (1 - 2 * POISSON) * INNER + OUTER ** 2 / INNER)
    force_text = "  ".join("%.10g %.10g %.10g" % tuple(forces[v]) for v in inner)
    return f"""
  <!-- {description} -->
  <Node name="{name}">
    <StaticSolver newton_iterations="10" />
    <SparseLDLSolver />
    <MeshGmshLoader name="loader" filename="mesh/lame_cylinder.msh" translation="{x:g} 0 0" />
    <MeshTopology name="mesh" src="@loader" />
    <MechanicalObject name="dofs" src="@loader" />
    {field}
    <PartialFixedProjectiveConstraint name="planeStrain" fixAll="true" fixedDirections="0 0 1" />
    <BoxROI name="onPlaneX" box="{x - 1e-6:.9g} -1 -1  {x + 1e-6:.9g} 3 1" position="@dofs.rest_position" />
    <PartialFixedProjectiveConstraint name="symmetryX" indices="@onPlaneX.indices" fixedDirections="1 0 0" />
    <BoxROI name="onPlaneY" box="{x - 1:g} -1e-6 -1  {x + 3:g} 1e-6 1" position="@dofs.rest_position" />
    <PartialFixedProjectiveConstraint name="symmetryY" indices="@onPlaneY.indices" fixedDirections="0 1 0" />
    <ConstantForceField name="pressure" indices="{" ".join(str(v) for v in inner)}"
                        forces="{force_text}" />
    <!-- Error at the inner points, relative to u_r(a) = {lame:.6g} m. -->
    <ReferenceComparison name="error" analytic="lame" innerRadius="{INNER:g}" outerRadius="{OUTER:g}"
                         pressure="{PRESSURE:g}" youngModulus="{YOUNG_TEXT}" poissonRatio="{POISSON:g}"
                         origin="{x:g} 0 0" axis="0 0 1" referenceLength="{lame:.6g}"
                         indices="{" ".join(str(v) for v in inner)}" />
  </Node>"""


def write_scene(path, title, bodies):
    with open(path, "w") as out:
        out.write(f"""<?xml version="1.0"?>
<!-- {title}
     Lame's thick cylinder (REFERENCES.md, "Volumetric locking"): a quarter of the cross-section
     a = {INNER:g} < r < b = {OUTER:g} m ({RADIAL} x {ANGULAR} cells, share/mesh/lame_cylinder.msh), plane strain,
     nu = {POISSON:g}, E = {YOUNG_TEXT} Pa, internal pressure {PRESSURE:g} Pa. Each body's ReferenceComparison
     prints the error against the closed form at the end of `stroma run` (maxError: relative to
     the inner displacement u_r(a)). Generated by share/mesh/make_lame_cylinder.py: edit that. -->
<Node name="root" dt="1" gravity="0 0 0">""")
        for b in bodies:
            out.write(b)
        out.write("\n</Node>\n")


def main():
    points, hexahedra = make_mesh()
    write_msh(os.path.join(HERE, "lame_cylinder.msh"), points, hexahedra)
    forces = pressure_forces(points, hexahedra)
    inner = sorted(forces)
    material = f'youngModulus="{YOUNG_TEXT}" poissonRatio="{POISSON:g}" method="polar"'
    scenes = os.path.join(ROOT, "scenes", "locking")
    os.makedirs(scenes, exist_ok=True)
    write_scene(
        os.path.join(scenes, "LameCylinderTetrahedra.scn"),
        "Volumetric locking of linear tetrahedra, and the averaged nodal pressure that cures it.",
        [body("PlainTetrahedra", 0.0,
              f'<TetrahedronFEMForceField name="FEM" {material} />',
              "Plain linear tetrahedra (6 per cell): lock, u_r(a) about 22 % short.",
              inner, forces),
         body("NodalPressureTetrahedra", OFFSET,
              f'<TetrahedronFEMForceField name="FEM" {material} volumetricIntegration="nodal" />',
              "The same tetrahedra with one volumetric strain per vertex: about 1.4 % short.",
              inner, forces)])
    write_scene(
        os.path.join(scenes, "LameCylinderHexahedra.scn"),
        "Volumetric locking of trilinear hexahedra, and selective reduced integration.",
        [body("FullHexahedra", 0.0,
              f'<HexahedronFEMForceField name="FEM" {material} />',
              "2 x 2 x 2 Gauss points: lock, u_r(a) about 42 % short.", inner, forces),
         body("ReducedHexahedra", OFFSET,
              f'<HexahedronFEMForceField name="FEM" {material} volumetricIntegration="reduced" />',
              "Volumetric part on the mean dilatation (B-bar): about 0.3 % short.",
              inner, forces)])


if __name__ == "__main__":
    main()
