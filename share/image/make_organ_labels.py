#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Writes organ_labels.nrrd: a synthetic labelled volume image of an organ-like blob, for
scenes/sparsegrid/VolumeImage.scn.

48 x 32 x 24 voxels of 2.5 mm (the image covers [0, 0.12] x [0, 0.08] x [0, 0.06] m; voxel
(0, 0, 0) is centred at 1.25 mm). Labels: 0 outside; 1 soft tissue: the union of two overlapping
ellipsoids (a large lobe and a smaller one tilted upward, like a liver's); 2 a stiffer inner
core: an ellipsoid inside the large lobe. A voxel takes the label of its centre. Standard library
only; the output is deterministic (run: python3 make_organ_labels.py).
"""
import os
import struct

NX, NY, NZ = 48, 32, 24
H = 0.0025  # voxel size, m


def inside_ellipsoid(p, centre, semi_axes):
    return sum(((p[a] - centre[a]) / semi_axes[a]) ** 2 for a in range(3)) <= 1.0


def label(p):
    if inside_ellipsoid(p, (0.05, 0.036, 0.03), (0.016, 0.011, 0.009)):
        return 2
    if inside_ellipsoid(p, (0.05, 0.036, 0.03), (0.045, 0.026, 0.026)):
        return 1
    # The small lobe, its long axis tilted 30 degrees up from x (rotated into its frame).
    x, y, z = p[0] - 0.092, p[1] - 0.05, p[2] - 0.03
    c, s = 0.8660254037844386, 0.5
    if inside_ellipsoid((c * x + s * y, -s * x + c * y, z), (0, 0, 0), (0.024, 0.013, 0.018)):
        return 1
    return 0


def main():
    data = bytearray()
    for k in range(NZ):  # x fastest, then y, then z
        for j in range(NY):
            for i in range(NX):
                data.append(label(((i + 0.5) * H, (j + 0.5) * H, (k + 0.5) * H)))
    header = (
        "NRRD0004\n"
        "# A synthetic organ: 0 outside, 1 soft tissue, 2 stiffer core (make_organ_labels.py)\n"
        "type: uint8\n"
        "dimension: 3\n"
        "space dimension: 3\n"
        f"sizes: {NX} {NY} {NZ}\n"
        f"space directions: ({H},0,0) (0,{H},0) (0,0,{H})\n"
        f"space origin: ({H / 2},{H / 2},{H / 2})\n"
        "kinds: domain domain domain\n"
        "endian: little\n"
        "encoding: raw\n"
        "\n"
    )
    path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "organ_labels.nrrd")
    with open(path, "wb") as out:
        out.write(header.encode("ascii"))
        out.write(bytes(data))
    counts = [data.count(v) for v in (0, 1, 2)]
    print(f"{path}: {NX}x{NY}x{NZ} voxels; label 0: {counts[0]}, 1: {counts[1]}, 2: {counts[2]}")


if __name__ == "__main__":
    main()
