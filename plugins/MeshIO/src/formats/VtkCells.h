// SPDX-License-Identifier: MIT
// VTK cells to Stroma elements, shared by the legacy and the XML VTK readers.
#pragma once

#include <string>
#include <vector>

#include "MeshData.h"

namespace stroma::meshio {

/// Cells as VTK stores them: cell i has the points connectivity[offsets[i]] ..
/// connectivity[offsets[i + 1] - 1].
struct VtkCells {
  std::vector<long long> offsets{0};  ///< (cells + 1), starts at 0
  std::vector<long long> connectivity;
  std::size_t size() const { return offsets.size() - 1; }
};

/// Checks that offsets increase from 0 to connectivity.size() and that every point index is in
/// [0, nbPoints). On failure `error` names the cell (`what`: "cell", "polygon"...).
bool checkVtkCells(const VtkCells& cells, std::size_t nbPoints, const char* what,
                   std::string& error);

/// Adds the cells of an unstructured grid with their VTK cell types (checked cells).
/// Vertices are ignored; wedges, pyramids and other types are skipped with a warning;
/// quadratic edges, triangles, quads, tetrahedra and hexahedra keep their corners.
bool addVtkCells(const VtkCells& cells, const std::vector<long long>& types, MeshData& mesh,
                 std::string& error);

/// The sections of a polygonal dataset (checked cells).
enum class VtkPolyKind { vertices, lines, polygons, strips };
void addVtkPolyData(const VtkCells& cells, VtkPolyKind kind, MeshData& mesh);

}  // namespace stroma::meshio
