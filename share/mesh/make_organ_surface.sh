#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Meshes the surface of organ.geo into organ_surface.stl (binary STL, 1282 triangles, 643
# points once merged), the surface that scenes/sparsegrid/SparseGridOrgan.scn embeds in sparse
# grids. Needs Debian's gmsh (`apt-get install gmsh`); the output is committed, so building
# Stroma does not need gmsh. Made with gmsh 4.8.4.
set -euo pipefail
cd "$(dirname "$0")"
gmsh -2 organ.geo -o organ_surface.stl -format stl -bin 2>&1 | tail -n 1
