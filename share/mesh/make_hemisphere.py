#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Quarter hemispheres of hexahedra for the Hertz contact study (bench/studies/Hertz.xml).

Writes share/mesh/hemisphere-N.msh (Gmsh 2.2 ASCII, hexahedra only) for each N given: the
quarter x >= 0, y >= 0 of the lower half of a ball of radius 1 centred at (0, 0, 1), so that
its lowest point (the pole, where it touches a plane z = 0) is the origin and its flat face is
the plane z = 1. Scenes scale it with the loader's `scale`.

Construction (coordinates about the ball's centre, the pole at (0, 0, -1)):
1. an O-grid of the octant cube [0, 1] x [0, 1] x [-1, 0]: an inner cube [0, C]^2 x [-C, 0] of
   N^3 cells and, around it, a shell block per outer face (x = 1, y = 1, z = -1), each N x N
   cells across and N / 2 cells from the inner cube to the face. Unlike a single grid of the
   octant, no cell then has two faces on the sphere (those cells are flat at the cube's edges);
2. the shells mapped onto the ball along the rays from the centre: a point s d (d on the
   unit cube's surface, C <= s <= 1) goes to distance (1 - l) C |d| + l, l = (s - C) / (1 - C),
   on the ray d / |d|: the inner cube stays, the outer faces become the sphere;
3. refined towards the pole: a point's angle theta from the pole's axis (seen from the centre)
   becomes pi/2 g_a(2 theta / pi), and near the pole its distance r from the centre becomes
   1 - g_b(1 - r), with g_k(t) = k t + (1 - k) t^2, a = POLE_REFINEMENT and b = a + (1 - a) 2
   theta / pi (no radial refinement at the flat face's rim). Cells at the pole shrink about a
   times in every direction; the sphere, the flat face and the symmetry planes x = 0, y = 0
   stay in place.
The hexahedra list their vertices in SOFA's order, right-handed (x, y, z as the reference axes).
A check prints the smallest scaled corner Jacobian (1 for a cube, 0 for a flat corner).

Usage: python3 share/mesh/make_hemisphere.py [N ...]   (default 4 6 8 10; N even; standard
library only)
"""
import math
import os
import sys

POLE_REFINEMENT = 0.1  # a
INNER = 0.5  # C: half size of the inner cube, in units of the radius

HERE = os.path.dirname(os.path.abspath(__file__))


def onto_ball(p):
    """Point of the octant cube onto the ball: the shells bent onto the sphere."""
    s = max(abs(c) for c in p)
    if s <= INNER:
        return p
    d = [c / s for c in p]
    length = math.sqrt(sum(c * c for c in d))
    blend = (s - INNER) / (1 - INNER)
    radius = (1 - blend) * INNER * length + blend  # from the inner cube's face to the sphere
    return tuple(radius * c / length for c in d)


def towards_pole(q):
    """Point of the ball refined towards the pole (step 3 of the construction)."""
    r = math.sqrt(sum(c * c for c in q))
    if r == 0:
        return q
    theta = math.acos(max(-1.0, min(1.0, -q[2] / r)))
    phi = math.atan2(q[1], q[0])
    a = POLE_REFINEMENT
    b = a + (1 - a) * theta / (math.pi / 2)
    r = 1 - (b * (1 - r) + (1 - b) * (1 - r) ** 2)
    t = theta / (math.pi / 2)
    theta = math.pi / 2 * (a * t + (1 - a) * t * t)
    # The symmetry planes exactly (cos(pi / 2) is not 0).
    x = 0.0 if q[0] == 0 else r * math.sin(theta) * math.cos(phi)
    y = 0.0 if q[1] == 0 else r * math.sin(theta) * math.sin(phi)
    return (x, y, -r * math.cos(theta))


def blocks(n):
    """The four blocks: cell counts (along their three parameters) and the cube point of
    parameters (u, v, w) in [0, 1]^3."""
    layers = n // 2

    def shell(u, v, w):
        return INNER + (1 - INNER) * w  # s, from the inner cube (w = 0) out

    return [
        ((n, n, n), lambda u, v, w: (INNER * u, INNER * v, -INNER * w)),
        ((n, n, layers), lambda u, v, w: tuple(shell(u, v, w) * c for c in (1, u, -v))),
        ((n, n, layers), lambda u, v, w: tuple(shell(u, v, w) * c for c in (u, 1, -v))),
        ((n, n, layers), lambda u, v, w: tuple(shell(u, v, w) * c for c in (u, v, -1))),
    ]


def corner_jacobian(points, h):
    """Smallest over the 8 corners of det(e1, e2, e3) / (|e1| |e2| |e3|)."""
    neighbours = ((1, 3, 4), (2, 0, 5), (3, 1, 6), (0, 2, 7), (7, 5, 0), (4, 6, 1), (5, 7, 2),
                  (6, 4, 3))
    worst = 1.0
    for corner, (a, b, c) in enumerate(neighbours):
        p = points[h[corner]]
        e = [[points[h[k]][i] - p[i] for i in range(3)] for k in (a, b, c)]
        det = (e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1])
               - e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0])
               + e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]))
        norms = math.prod(math.sqrt(sum(x * x for x in v)) for v in e)
        worst = min(worst, det / norms)
    return worst


def make_mesh(n):
    points, index, hexahedra = [], {}, []

    def point(p):
        key = tuple(round(c, 12) + 0.0 for c in p)  # shared faces: the same cube point
        if key not in index:
            index[key] = len(points)
            q = towards_pole(onto_ball(p))
            points.append((q[0], q[1], q[2] + 1))  # pole at the origin
        return index[key]

    for (cu, cv, cw), cube in blocks(n):
        ids = {}
        for k in range(cw + 1):
            for j in range(cv + 1):
                for i in range(cu + 1):
                    ids[i, j, k] = point(cube(i / cu, j / cv, k / cw))
        cells = []
        for k in range(cw):
            for j in range(cv):
                for i in range(cu):
                    cells.append([ids[i, j, k], ids[i + 1, j, k], ids[i + 1, j + 1, k],
                                  ids[i, j + 1, k], ids[i, j, k + 1], ids[i + 1, j, k + 1],
                                  ids[i + 1, j + 1, k + 1], ids[i, j + 1, k + 1]])
        # A block whose parameters are left-handed in x, y, z: its cells mirrored.
        if corner_jacobian(points, cells[0]) < 0:
            cells = [[h[0], h[3], h[2], h[1], h[4], h[7], h[6], h[5]] for h in cells]
        hexahedra += cells
    return points, hexahedra


def write_msh(path, points, hexahedra):
    with open(path, "w") as out:
        out.write("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n%d\n" % len(points))
        for n, p in enumerate(points):
            out.write("%d %.10g %.10g %.10g\n" % (n + 1, p[0], p[1], p[2]))
        out.write("$EndNodes\n$Elements\n%d\n" % len(hexahedra))
        for n, h in enumerate(hexahedra):
            out.write("%d 5 0 %s\n" % (n + 1, " ".join(str(v + 1) for v in h)))
        out.write("$EndElements\n")


def main():
    sizes = [int(a) for a in sys.argv[1:]] or [4, 6, 8, 10]
    for n in sizes:
        if n < 2 or n % 2:
            sys.exit("make_hemisphere: N must be even and at least 2, got %d" % n)
        points, hexahedra = make_mesh(n)
        worst = min(corner_jacobian(points, h) for h in hexahedra)
        pole = sorted(math.dist((0, 0, 0), p) for p in points)[1]  # the pole is a point
        path = os.path.join(HERE, "hemisphere-%d.msh" % n)
        write_msh(path, points, hexahedra)
        print("%s: %d points, %d hexahedra, nearest point to the pole at %.4g radius, smallest "
              "scaled corner Jacobian %.3f" % (os.path.relpath(path), len(points),
                                                len(hexahedra), pole, worst))


if __name__ == "__main__":
    main()
