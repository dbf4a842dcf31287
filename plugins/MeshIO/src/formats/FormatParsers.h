// SPDX-License-Identifier: MIT
// The parser of each format (internal to the format library; use parseMesh()).
#pragma once

#include <string>
#include <string_view>

#include "MeshData.h"

namespace stroma::meshio {

bool parseGmsh(std::string_view bytes, MeshData& mesh, std::string& error);
/// Legacy .vtk or XML .vtu/.vtp, told apart by their first bytes.
bool parseVtk(std::string_view bytes, MeshData& mesh, std::string& error);
bool parseVtkLegacy(std::string_view bytes, MeshData& mesh, std::string& error);
bool parseVtkXml(std::string_view bytes, MeshData& mesh, std::string& error);
bool parseObj(std::string_view bytes, const MeshParseOptions& options, MeshData& mesh,
              std::string& error);
bool parseStl(std::string_view bytes, const MeshParseOptions& options, MeshData& mesh,
              std::string& error);

/// Reads a whole file (an empty one too). On failure sets `error`: "no such file", "not a
/// regular file", "cannot open the file" or "cannot read the file".
bool readFileBytes(const std::string& path, std::string& bytes, std::string& error);

/// How many items of at least `minBytes` bytes each `bytes` can hold: the cap on what a count
/// read from the file may reserve.
inline std::size_t maxItems(std::string_view bytes, std::size_t minBytes) {
  return bytes.size() / (minBytes ? minBytes : 1) + 1;
}

/// Adds a polygon of point indices: a triangle, a quad (unless `triangulate`), or a fan of
/// triangles from its first vertex. Fewer than 3 vertices: nothing.
void addPolygon(MeshData& mesh, const Index* vertices, std::size_t count, bool triangulate);

}  // namespace stroma::meshio
