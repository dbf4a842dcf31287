// SPDX-License-Identifier: MIT
// A cylinder of radius 0.02 m and height 0.1 m standing on the plane y = 0, axis along y:
// the bending test of seed 004 (bottom face fixed, a force on the top face). Meshed by
// make_cylinder.sh into cylinder.msh.
SetFactory("OpenCASCADE");
Cylinder(1) = {0, 0, 0, 0, 0.1, 0, 0.02, 2*Pi};
Mesh.CharacteristicLengthMin = 0.006;
Mesh.CharacteristicLengthMax = 0.006;
Mesh.Algorithm3D = 1;     // Delaunay
Mesh.Optimize = 1;        // remove slivers
Mesh.OptimizeNetgen = 1;
General.RandomSeed = 1;
Physical Volume("tissue") = {1};
