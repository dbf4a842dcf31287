#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Writes bowl.obj: the inside of a hemispherical bowl of radius 0.15 m, centred at the origin,
open upwards (y > 0 is open; the bottom at y = -0.15), as a triangulated surface whose normals
(right-hand rule) point into the bowl, towards its centre: the side spheres poured into it touch
(scenes/collision/SpheresInBowl.scn). `rings` latitude bands from the bottom pole to the rim, each
with `segments` points around."""
import math

RADIUS = 0.15
RINGS = 8
SEGMENTS = 24


def main():
    points = [(0.0, -RADIUS, 0.0)]  # the bottom pole
    for ring in range(1, RINGS + 1):
        polar = (math.pi / 2) * ring / RINGS  # 0 at the bottom, pi/2 at the rim
        y = -RADIUS * math.cos(polar)
        r = RADIUS * math.sin(polar)
        for s in range(SEGMENTS):
            a = 2 * math.pi * s / SEGMENTS
            points.append((r * math.cos(a), y, r * math.sin(a)))

    def index(ring, s):  # ring >= 1
        return 1 + (ring - 1) * SEGMENTS + s % SEGMENTS

    triangles = []
    for s in range(SEGMENTS):  # the cap around the pole
        triangles.append((0, index(1, s), index(1, s + 1)))
    for ring in range(1, RINGS):
        for s in range(SEGMENTS):
            a, b = index(ring, s), index(ring, s + 1)
            c, d = index(ring + 1, s), index(ring + 1, s + 1)
            triangles.append((a, c, d))
            triangles.append((a, d, b))
    # Orient every triangle so that its normal points towards the centre (inside the bowl).
    oriented = []
    for t in triangles:
        p = [points[i] for i in t]
        u = [p[1][k] - p[0][k] for k in range(3)]
        v = [p[2][k] - p[0][k] for k in range(3)]
        n = (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])
        centroid = [sum(q[k] for q in p) / 3 for k in range(3)]
        inwards = sum(n[k] * -centroid[k] for k in range(3)) > 0
        oriented.append(t if inwards else (t[0], t[2], t[1]))
    with open("bowl.obj", "w") as out:
        out.write("# Inside of a hemispherical bowl, radius %g m: share/mesh/make_bowl.py\n" % RADIUS)
        for p in points:
            out.write("v %.9g %.9g %.9g\n" % p)
        for t in oriented:
            out.write("f %d %d %d\n" % (t[0] + 1, t[1] + 1, t[2] + 1))


if __name__ == "__main__":
    main()
