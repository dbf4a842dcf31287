#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Writes the meshes of the robots of scenes/robot into this folder (share/robot/):

  link.obj    a box along +x from 0 to 1, 1 x 1 in y and z, centered on the x axis: a link
              of length L and thickness t is this box scaled by "L t t" in its URDF.
  base.obj    a box 1 x 1 x 1 centered at the origin (a robot's base plate, scaled likewise).

Run: /usr/bin/python3 share/robot/make_robot_meshes.py
"""
import os

HERE = os.path.dirname(os.path.abspath(__file__))


def box(x0, x1, y0, y1, z0, z1):
    """Vertices and outward triangles (counter-clockwise seen from outside) of a box."""
    v = [(x, y, z) for x in (x0, x1) for y in (y0, y1) for z in (z0, z1)]
    # vertex index = 4 ix + 2 iy + iz
    quads = [(0, 1, 3, 2), (4, 6, 7, 5),  # x = x0 (normal -x), x = x1 (+x)
             (0, 4, 5, 1), (2, 3, 7, 6),  # y = y0 (-y), y = y1 (+y)
             (0, 2, 6, 4), (1, 5, 7, 3)]  # z = z0 (-z), z = z1 (+z)
    tris = []
    for a, b, c, d in quads:
        tris += [(a, b, c), (a, c, d)]
    return v, tris


def write_obj(name, comment, vertices, triangles):
    with open(os.path.join(HERE, name), "w") as f:
        f.write("# %s\n# written by share/robot/make_robot_meshes.py\n" % comment)
        for x, y, z in vertices:
            f.write("v %g %g %g\n" % (x, y, z))
        for a, b, c in triangles:
            f.write("f %d %d %d\n" % (a + 1, b + 1, c + 1))


write_obj("link.obj", "a link: the box [0, 1] x [-0.5, 0.5] x [-0.5, 0.5]",
          *box(0, 1, -0.5, 0.5, -0.5, 0.5))
write_obj("base.obj", "a base plate: the unit box centered at the origin",
          *box(-0.5, 0.5, -0.5, 0.5, -0.5, 0.5))
