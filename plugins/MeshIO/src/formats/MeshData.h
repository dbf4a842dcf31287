// SPDX-License-Identifier: MIT
// Mesh file formats: parse the bytes of a mesh file into plain lists of points and elements.
//
// parseMesh() is the one entry point the loaders (and a fuzz target) use. It never throws for
// bad input and never reads out of bounds: a malformed, truncated or hostile file gives false
// and an error saying where (text formats: "line N"; binary data: "byte offset N") and what was
// expected. Sizes announced by a file are checked against the bytes present before anything is
// allocated for them.
//
// Supported:
// - Gmsh .msh: versions 1 ($NOD/$ELM), 2.x ASCII and binary, 4.1 ASCII and binary. Node tags
//   may be any positive numbers, in any order: points are numbered in file order. Elements:
//   line (1), triangle (2), quad (3), tetrahedron (4), hexahedron (5); the second-order line,
//   triangle, quad, tetrahedron and hexahedron (8, 9, 10, 11, 12, 16, 17) are read as their
//   corner (first-order) element; points (15) are ignored; other known types are skipped with
//   a warning. The physical group of each tetrahedron and hexahedron is kept (version 1: its
//   reg-phys; 2: its first tag; 4.1: the first physical group of its entity in $Entities).
// - VTK legacy .vtk, ASCII and BINARY, DATASET UNSTRUCTURED_GRID and POLYDATA (cells in the
//   classic layout or the 5.x OFFSETS/CONNECTIVITY layout); point normals from POINT_DATA.
// - VTK XML .vtu/.vtp (UnstructuredGrid, PolyData), DataArray format "ascii".
// - Wavefront .obj: v, vt, vn, f and l, indices with the v, v/vt, v//vn, v/vt/vn forms (negative
//   = relative to the end).
// - STL, ASCII and binary (told apart by size), with duplicated vertices merged.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/Types.h"
#include "topology/TopologyTypes.h"

namespace stroma {

/// What a mesh file holds, in Stroma's element types and SOFA's vertex orders.
struct MeshData {
  std::vector<Vec3d> positions;
  std::vector<Edge> edges;
  std::vector<Triangle> triangles;
  std::vector<Quad> quads;
  std::vector<Tetrahedron> tetrahedra;
  std::vector<Hexahedron> hexahedra;
  std::vector<Vec3d> normals;    ///< per point, when the file has them (else empty)
  std::vector<Vec2d> texcoords;  ///< per point, when the file has them (OBJ vt; else empty)
  /// Gmsh: the physical group of each tetrahedron and hexahedron (0: in none; an element of
  /// several groups keeps the first). Empty for the other formats.
  std::vector<int> tetrahedronGroups;
  std::vector<int> hexahedronGroups;
  /// Things read but not kept (unsupported element types...), each with its place in the file.
  std::vector<std::string> warnings;
};

enum class MeshFormat { gmsh, vtk, obj, stl };

/// "Gmsh", "VTK", "OBJ", "STL".
const char* meshFormatName(MeshFormat format);

/// The format a file name's extension implies (.msh; .vtk .vtu .vtp; .obj; .stl), if any.
std::optional<MeshFormat> meshFormatFromFileName(std::string_view fileName);

/// Options that change what some formats produce.
struct MeshParseOptions {
  /// OBJ: split quads into two triangles (polygons of 5 and more vertices always are).
  bool triangulate = false;
  /// OBJ: one point per distinct (v, vt, vn) corner, so that texture and normal seams are kept;
  /// otherwise points are the file's v lines and each keeps the last vt/vn given for it.
  bool handleSeams = false;
  /// STL: read as binary even when the file starts with "solid".
  bool forceBinary = false;
  /// STL: bytes of the binary header before the triangle count (80 in the standard).
  std::size_t stlHeaderSize = 80;
  /// STL: merge points at the same position (STL repeats them for each triangle).
  bool mergePositions = true;
};

/// Parses `bytes` as `format`. On failure returns false, leaves `mesh` in an unspecified state
/// and sets `error` ("line 12: expected 3 coordinates, got 'x'"; "byte offset 84: ...").
bool parseMesh(std::string_view bytes, MeshFormat format, MeshData& mesh, std::string& error,
               const MeshParseOptions& options = {});

/// Reads a whole file and parses it. Errors also cover a missing or unreadable file.
bool readMeshFile(const std::string& path, MeshFormat format, MeshData& mesh, std::string& error,
                  const MeshParseOptions& options = {});

}  // namespace stroma
