#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Writes share/robot/arm6.urdf, a 6-axis arm holding a rigid instrument (a 12 cm rod), and
prints where the instrument's tip is at the joint values of scenes/robot/ArmOnOrgan.scn, with
the base pose that puts the tip above the organ's right lobe.

The arm, z up in its base frame, links along their +x:
  base_yaw    about z, 5 cm above the base      column  10 cm (up)
  shoulder    about y, at the column's top      upper arm 25 cm
  elbow       about y                           forearm  20 cm
  wrist_roll  about x                           4 cm
  wrist_pitch about y                           4 cm
  tool_roll   about x                           flange 2 cm
  tool_mount  fixed                             instrument 12 cm, its tip at x = 0.12 m
A rotation q about y turns +x toward -z, so shoulder + elbow + wrist_pitch = pi/2 points the
instrument straight down. Masses are solid boxes of 1000 kg/m^3 x their section, inertias those
of the boxes about their centers. Meshes: share/robot/link.obj and base.obj, scaled.

Run: /usr/bin/python3 share/robot/make_arm6.py
"""
import math
import os

HERE = os.path.dirname(os.path.abspath(__file__))

# name, parent joint axis, joint origin in the parent link (x, y, z), link length, section
LINKS = [
    ("column", (0, 0, 1), (0, 0, 0.05), 0.10, 0.06),
    ("upper_arm", (0, 1, 0), (0, 0, 0.10), 0.25, 0.05),
    ("forearm", (0, 1, 0), (0.25, 0, 0), 0.20, 0.04),
    ("wrist1", (1, 0, 0), (0.20, 0, 0), 0.04, 0.04),
    ("wrist2", (0, 1, 0), (0.04, 0, 0), 0.04, 0.035),
    ("flange", (1, 0, 0), (0.04, 0, 0), 0.02, 0.03),
]
JOINTS = ["base_yaw", "shoulder", "elbow", "wrist_roll", "wrist_pitch", "tool_roll"]
INSTRUMENT = ("instrument", (0.02, 0, 0), 0.12, 0.008)
DENSITY = 1000.0


def box_inertial(length, section):
    m = DENSITY * length * section * section
    ixx = m * (2 * section * section) / 12
    iyy = izz = m * (length * length + section * section) / 12
    return m, ixx, iyy, izz


def link_xml(name, length, section, color, column=False):
    m, ixx, iyy, izz = box_inertial(length, section)
    # The column stands up: its box (along +x) is turned by -pi/2 about y, so +x becomes +z.
    rpy = "0 %.17g 0" % (-math.pi / 2) if column else "0 0 0"
    com = "0 0 %g" % (length / 2) if column else "%g 0 0" % (length / 2)
    if column:
        ixx, izz = izz, ixx
    return ("  <link name=\"%s\">\n"
            "    <inertial><origin xyz=\"%s\"/><mass value=\"%.6g\"/>\n"
            "      <inertia ixx=\"%.6g\" ixy=\"0\" ixz=\"0\" iyy=\"%.6g\" iyz=\"0\" izz=\"%.6g\"/></inertial>\n"
            "    <visual><origin xyz=\"0 0 0\" rpy=\"%s\"/><geometry><mesh filename=\"package://robot/link.obj\" "
            "scale=\"%g %g %g\"/></geometry>\n"
            "      <material name=\"%s\"><color rgba=\"%s\"/></material></visual>\n"
            "  </link>\n") % (name, com, m, ixx, iyy, izz, rpy, length, section, section,
                             name + "_color", color)


def write_urdf():
    out = ["<?xml version=\"1.0\"?>\n",
           "<!-- A 6-axis arm holding a rigid instrument; written by share/robot/make_arm6.py -->\n",
           "<robot name=\"arm6\">\n",
           "  <link name=\"base_link\">\n"
           "    <inertial><mass value=\"2\"/><inertia ixx=\"0.01\" ixy=\"0\" ixz=\"0\" iyy=\"0.01\" "
           "iyz=\"0\" izz=\"0.01\"/></inertial>\n"
           "    <visual><origin xyz=\"0 0 0.025\"/><geometry><mesh filename=\"package://robot/base.obj\" "
           "scale=\"0.12 0.12 0.05\"/></geometry>\n"
           "      <material name=\"base_color\"><color rgba=\"0.3 0.3 0.3 1\"/></material></visual>\n"
           "  </link>\n"]
    parent = "base_link"
    colors = ["0.85 0.85 0.9 1", "0.2 0.4 0.8 1", "0.85 0.85 0.9 1", "0.2 0.4 0.8 1",
              "0.85 0.85 0.9 1", "0.3 0.3 0.3 1"]
    for (name, axis, origin, length, section), joint, color in zip(LINKS, JOINTS, colors):
        out.append(link_xml(name, length, section, color, column=(name == "column")))
        out.append("  <joint name=\"%s\" type=\"revolute\"><parent link=\"%s\"/><child link=\"%s\"/>"
                   "<origin xyz=\"%g %g %g\"/><axis xyz=\"%g %g %g\"/>"
                   "<limit lower=\"-3.1\" upper=\"3.1\" effort=\"100\" velocity=\"3\"/>"
                   "<dynamics damping=\"0.5\"/></joint>\n"
                   % ((joint, parent, name) + origin + axis))
        parent = name
    name, origin, length, section = INSTRUMENT
    out.append(link_xml(name, length, section, "0.75 0.75 0.7 1"))
    out.append("  <joint name=\"tool_mount\" type=\"fixed\"><parent link=\"%s\"/><child link=\"%s\"/>"
               "<origin xyz=\"%g %g %g\"/></joint>\n" % ((parent, name) + origin))
    out.append("</robot>\n")
    with open(os.path.join(HERE, "arm6.urdf"), "w") as f:
        f.write("".join(out))


def rot(axis, q):
    x, y, z = axis
    c, s = math.cos(q), math.sin(q)
    t = 1 - c
    return [[t * x * x + c, t * x * y - s * z, t * x * z + s * y],
            [t * x * y + s * z, t * y * y + c, t * y * z - s * x],
            [t * x * z - s * y, t * y * z + s * x, t * z * z + c]]


def mul(a, b):
    return [[sum(a[i][k] * b[k][j] for k in range(3)) for j in range(3)] for i in range(3)]


def apply(r, v):
    return [sum(r[i][k] * v[k] for k in range(3)) for i in range(3)]


def tip(q):
    """The instrument tip in the base frame at joint values q (6)."""
    R = [[1, 0, 0], [0, 1, 0], [0, 0, 1]]
    p = [0, 0, 0]
    for (name, axis, origin, length, section), value in zip(LINKS, q):
        p = [a + b for a, b in zip(p, apply(R, origin))]
        R = mul(R, rot(axis, value))
    p = [a + b for a, b in zip(p, apply(R, INSTRUMENT[1]))]
    return [a + b for a, b in zip(p, apply(R, (INSTRUMENT[2], 0, 0)))]


def pose(shoulder, elbow):
    return [0, shoulder, elbow, 0, math.pi / 2 - shoulder - elbow, 0]


def solve_down(start, depth):
    """Shoulder and elbow values (the instrument kept vertical) that put the tip `depth` m
    straight below its place at `start`, by Newton's method on central differences."""
    goal = tip(start)
    goal = (goal[0], goal[1], goal[2] - depth)
    s, e = start[1], start[2]
    for _ in range(20):
        t = tip(pose(s, e))
        r = (t[0] - goal[0], t[2] - goal[2])
        h = 1e-7
        ds = [(a - b) / (2 * h) for a, b in zip(tip(pose(s + h, e)), tip(pose(s - h, e)))]
        de = [(a - b) / (2 * h) for a, b in zip(tip(pose(s, e + h)), tip(pose(s, e - h)))]
        a11, a12, a21, a22 = ds[0], de[0], ds[2], de[2]
        det = a11 * a22 - a12 * a21
        s -= (a22 * r[0] - a12 * r[1]) / det
        e -= (-a21 * r[0] + a11 * r[1]) / det
    return pose(s, e)


if __name__ == "__main__":
    write_urdf()
    approach = pose(0.35, 0.9)
    press = solve_down(approach, 0.025)
    a, b = tip(approach), tip(press)
    print("tip at approach", " ".join("%.5f" % v for v in a), "joints",
          " ".join("%.6f" % v for v in approach))
    print("tip at press   ", " ".join("%.5f" % v for v in b), "joints",
          " ".join("%.6f" % v for v in press))
    # The base turned by -90 degrees about x (robot z up -> world y up); the tip at approach
    # 2.5 cm above the point (0.03, 0.045, 0) of the organ's right lobe.
    # world = (x, z, -y) for a robot vector (x, y, z).
    target = (0.03, 0.045 + 0.025, 0.0)
    base = (target[0] - a[0], target[1] - a[2], target[2] + a[1])
    print("basePose %.6f %.6f %.6f  -0.70710678118654752 0 0 0.70710678118654752" % base)
    print("press moves the tip by (world) %.4f %.4f %.4f" % (b[0] - a[0], b[2] - a[2], -(b[1] - a[1])))
