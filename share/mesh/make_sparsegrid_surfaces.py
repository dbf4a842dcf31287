#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Writes the closed surfaces of scenes/sparsegrid/{CantileverGrids,CylinderCompression}.scn:

- sparsegrid_beam.obj: the box [-2, 40] x [-2, 2] x [-1, 1] m, seed 001's 40 x 4 x 2 m
  cantilever (section 6.2.1) with 2 m more reaching into the wall (x < 0);
- sparsegrid_cylinder.obj: a cylinder of radius 0.5 m from z = 0 to z = 1 m (seed 001, section
  6.3.2.2), 64 points per circle, 9 circles (one at mid-height), each end closed by a fan.

Run from share/mesh: python3 make_sparsegrid_surfaces.py
"""
import math


def box(lo, hi):
    points = [(hi[0] if i & 1 else lo[0], hi[1] if i & 2 else lo[1], hi[2] if i & 4 else lo[2])
              for i in range(8)]
    # Each face as two triangles, outward normals.
    quads = [(0, 4, 6, 2), (1, 3, 7, 5), (0, 1, 5, 4), (2, 6, 7, 3), (0, 2, 3, 1), (4, 5, 7, 6)]
    triangles = []
    for a, b, c, d in quads:
        triangles += [(a, b, c), (a, c, d)]
    return points, triangles


def cylinder(radius, height, segments, rings):
    points = [(radius * math.cos(2 * math.pi * i / segments),
               radius * math.sin(2 * math.pi * i / segments), height * k / rings)
              for k in range(rings + 1) for i in range(segments)]
    ident = lambda k, i: k * segments + i % segments
    triangles = []
    for k in range(rings):
        for i in range(segments):
            triangles += [(ident(k, i), ident(k, i + 1), ident(k + 1, i + 1)),
                          (ident(k, i), ident(k + 1, i + 1), ident(k + 1, i))]
    bottom = len(points)
    points += [(0.0, 0.0, 0.0), (0.0, 0.0, height)]
    for i in range(segments):
        triangles += [(bottom, ident(0, i + 1), ident(0, i)),
                      (bottom + 1, ident(rings, i), ident(rings, i + 1))]
    return points, triangles


def write_obj(name, points, triangles, comment):
    with open(name, "w") as out:
        out.write("# %s\n# written by make_sparsegrid_surfaces.py\n" % comment)
        for p in points:
            out.write("v %.9g %.9g %.9g\n" % p)
        for t in triangles:
            out.write("f %d %d %d\n" % tuple(i + 1 for i in t))


if __name__ == "__main__":
    points, triangles = box((-2.0, -2.0, -1.0), (40.0, 2.0, 1.0))
    write_obj("sparsegrid_beam.obj", points, triangles,
              "cantilever 40 x 4 x 2 m, 2 m in the wall (x < 0)")
    points, triangles = cylinder(0.5, 1.0, 64, 8)
    write_obj("sparsegrid_cylinder.obj", points, triangles, "cylinder r = 0.5 m, h = 1 m")
