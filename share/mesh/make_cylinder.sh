#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Meshes cylinder.geo into cylinder.msh (Gmsh 2.2 ASCII: points, lines, surface triangles and
# tetrahedra; the loaders take what a scene asks for). Needs Debian's gmsh
# (`apt-get install gmsh`). The output is committed, so building Stroma does not need gmsh.
# Made with gmsh 4.8.4: 780 nodes, 3054 tetrahedra, 1032 boundary triangles.
set -euo pipefail
cd "$(dirname "$0")"
gmsh -3 cylinder.geo -o cylinder.msh -format msh22 -save_all 2>&1 | tail -n 1
