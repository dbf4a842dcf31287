// SPDX-License-Identifier: MIT
// A liver-like organ for Stroma's demo scenes: a large right lobe and a smaller left lobe,
// flattened ellipsoids fused together, about 0.2 m x 0.12 m x 0.08 m (SI units, metres).
// Regenerate organ.msh with ./make_organ.sh (gmsh from Debian's package `gmsh`).
SetFactory("OpenCASCADE");

// Right lobe
Sphere(1) = {0, 0, 0, 1};
Dilate {{0, 0, 0}, {0.075, 0.045, 0.05}} { Volume{1}; }
// Left lobe, thinner, offset to the left and slightly up
Sphere(2) = {0, 0, 0, 1};
Dilate {{0, 0, 0}, {0.06, 0.03, 0.035}} { Volume{2}; }
Rotate {{0, 0, 1}, {0, 0, 0}, 0.25} { Volume{2}; }
Translate {-0.085, 0.015, 0.005} { Volume{2}; }
// A bump under the right lobe (the caudate region)
Sphere(3) = {0.02, -0.03, 0.0, 0.028};

BooleanUnion(10) = { Volume{1}; Delete; }{ Volume{2, 3}; Delete; };

Mesh.CharacteristicLengthMin = 0.012;
Mesh.CharacteristicLengthMax = 0.018;
Mesh.Optimize = 1;
Mesh.MshFileVersion = 2.2;
