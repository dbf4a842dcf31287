# SPDX-License-Identifier: MIT
# Reads a mesh file with meshio (an independent reader) and prints what it found, for the
# Export tests: "points N" then N lines "x y z"; per cell block "cells TYPE N" then N lines of
# point indices; per point field "point_data NAME COMPONENTS" then one line per point; per cell
# field "cell_data NAME COMPONENTS" then one line per cell (blocks concatenated). Numbers with
# repr(): they read back as the same doubles. Exit code 3 when meshio is missing.
import sys

try:
    import meshio
except ImportError:
    print("meshio is not installed")
    sys.exit(3)

mesh = meshio.read(sys.argv[1], file_format=sys.argv[2] if len(sys.argv) > 2 else None)
out = ["points %d" % len(mesh.points)]
for p in mesh.points:
    out.append(" ".join(repr(float(v)) for v in list(p) + [0.0] * (3 - len(p))))
for block in mesh.cells:
    out.append("cells %s %d" % (block.type, len(block.data)))
    for c in block.data:
        out.append(" ".join(str(int(i)) for i in c))


def rows(values):
    for v in values:
        flat = v.reshape(-1) if hasattr(v, "reshape") else [v]
        yield " ".join(repr(float(x)) for x in flat)


for name, values in mesh.point_data.items():
    components = 1 if values.ndim == 1 else values.shape[1]
    out.append("point_data %s %d" % (name, components))
    out.extend(rows(values))
for name, blocks in mesh.cell_data.items():
    components = 1 if blocks[0].ndim == 1 else blocks[0].shape[1]
    out.append("cell_data %s %d" % (name, components))
    for values in blocks:
        out.extend(rows(values))
print("\n".join(out))
