// SPDX-License-Identifier: MIT
// Writers of volume-mesh formats that meshers and FEM codes read (MeshExporter): Gmsh's .msh
// (version 2.2 ASCII) and TetGen's .node/.ele pair. Fields are not written (these formats are
// for meshes); VtkFiles.h writes the VTK formats.
#pragma once

#include <filesystem>
#include <string>

#include "VtkFiles.h"

namespace stroma::vtk {

/// Gmsh 2.2 ASCII: $Nodes (numbered from 1) and $Elements (lines, triangles, quads, tetrahedra,
/// hexahedra; vertices as points), each with the two tags physical = elementary = 1.
bool writeGmsh(const std::filesystem::path& file, const UnstructuredMesh& mesh, std::string& error);

/// TetGen: `base`.node (the points, numbered from 1) and `base`.ele (the tetrahedra, numbered
/// from 1). Refused, with `error`, when the mesh has cells other than tetrahedra.
bool writeTetgen(const std::filesystem::path& base, const UnstructuredMesh& mesh,
                 std::string& error);

}  // namespace stroma::vtk
