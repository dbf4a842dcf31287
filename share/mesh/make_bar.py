#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Writes bar.msh, the bar of seed 000 (figure 5.1: 192 nodes, 820 tetrahedra there) for the
hybrid model's scenes (scenes/hybrid) and tests: a regular grid of 4 x 4 x 12 = 192 nodes,
spacing 0.01 m, so the bar spans [0, 0.03] x [0, 0.03] x [0, 0.11] m; each of its 3 x 3 x 11
cubes is split into the 6 tetrahedra around its main diagonal (Kuhn's split, conforming between
cubes), 594 tetrahedra. Every tetrahedron is positive ((b-a).((c-a)x(d-a)) > 0). Gmsh 2.2
ASCII; the physical group of each tetrahedron is 1 + the index (0 to 10) of its layer of cubes
along z (Gmsh numbers groups from 1), so that a partition into zones by layers can be read from
it (MeshGmshLoader's tetrahedraPhysicalGroups; HybridDomainDecompositionSolver partition="groups").

Run from share/mesh: python3 make_bar.py
"""
import itertools

NX, NY, NZ = 4, 4, 12
H = 0.01


def node(i, j, k):
    return i + NX * (j + NY * k)


def volume6(a, b, c, d):
    u = [b[t] - a[t] for t in range(3)]
    v = [c[t] - a[t] for t in range(3)]
    w = [d[t] - a[t] for t in range(3)]
    return (u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) +
            u[2] * (v[0] * w[1] - v[1] * w[0]))


def main():
    points = [(i * H, j * H, k * H) for k in range(NZ) for j in range(NY) for i in range(NX)]
    tetrahedra = []
    for k, j, i in itertools.product(range(NZ - 1), range(NY - 1), range(NX - 1)):
        for order in itertools.permutations(range(3)):
            corner = [0, 0, 0]
            path = [node(i, j, k)]
            for axis in order:
                corner[axis] += 1
                path.append(node(i + corner[0], j + corner[1], k + corner[2]))
            a, b, c, d = path
            if volume6(points[a], points[b], points[c], points[d]) < 0:
                b, c = c, b
            tetrahedra.append((k, (a, b, c, d)))
    with open("bar.msh", "w") as out:
        out.write("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n%d\n" % len(points))
        for n, p in enumerate(points):
            out.write("%d %.6g %.6g %.6g\n" % (n + 1, p[0], p[1], p[2]))
        out.write("$EndNodes\n$Elements\n%d\n" % len(tetrahedra))
        for e, (layer, t) in enumerate(tetrahedra):
            out.write("%d 4 2 %d %d %d %d %d %d\n" % (e + 1, layer + 1, layer + 1, *(v + 1 for v in t)))
        out.write("$EndElements\n")


if __name__ == "__main__":
    main()
