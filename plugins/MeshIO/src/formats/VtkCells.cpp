// SPDX-License-Identifier: MIT
// VTK cell types and vertex orders: "VTK File Formats", Kitware (VTK User's Guide, figure of
// the linear and quadratic cell types).
#include "VtkCells.h"

#include <map>

#include "FormatParsers.h"

namespace stroma::meshio {

namespace {

const char* cellTypeName(long long type) {
  switch (type) {
    case 13:
      return "wedge";
    case 14:
      return "pyramid";
    case 26:
      return "quadratic wedge";
    case 27:
      return "quadratic pyramid";
    default:
      return "unsupported";
  }
}

void addStrip(const long long* p, std::size_t n, MeshData& mesh) {
  // Triangle k of a strip is (k, k+1, k+2), every other one turned to keep the orientation.
  for (std::size_t k = 0; k + 2 < n; ++k) {
    const Index a = static_cast<Index>(p[k]), b = static_cast<Index>(p[k + 1]),
                c = static_cast<Index>(p[k + 2]);
    if (k % 2 == 0)
      mesh.triangles.push_back({a, b, c});
    else
      mesh.triangles.push_back({b, a, c});
  }
}

void addPolyline(const long long* p, std::size_t n, MeshData& mesh) {
  for (std::size_t k = 0; k + 1 < n; ++k)
    mesh.edges.push_back({static_cast<Index>(p[k]), static_cast<Index>(p[k + 1])});
}

}  // namespace

bool checkVtkCells(const VtkCells& cells, std::size_t nbPoints, const char* what,
                   std::string& error) {
  if (cells.offsets.empty() || cells.offsets.front() != 0) {
    error = "the cell offsets do not start at 0";
    return false;
  }
  for (std::size_t i = 0; i < cells.size(); ++i) {
    if (cells.offsets[i + 1] < cells.offsets[i] ||
        cells.offsets[i + 1] > static_cast<long long>(cells.connectivity.size())) {
      error = std::string(what) + " " + std::to_string(i) + ": offset " +
              std::to_string(cells.offsets[i + 1]) + " is out of order or past the " +
              std::to_string(cells.connectivity.size()) + " connectivity entries";
      return false;
    }
    for (long long k = cells.offsets[i]; k < cells.offsets[i + 1]; ++k) {
      const long long p = cells.connectivity[k];
      if (p < 0 || static_cast<std::size_t>(p) >= nbPoints) {
        error = std::string(what) + " " + std::to_string(i) + " uses point " + std::to_string(p) +
                ", out of range: there are " + std::to_string(nbPoints) + " points";
        return false;
      }
    }
  }
  return true;
}

bool addVtkCells(const VtkCells& cells, const std::vector<long long>& types, MeshData& mesh,
                 std::string& error) {
  if (types.size() != cells.size()) {
    error = "there are " + std::to_string(cells.size()) + " cells but " +
            std::to_string(types.size()) + " cell types";
    return false;
  }
  std::map<long long, std::size_t> skipped, reduced;
  for (std::size_t i = 0; i < cells.size(); ++i) {
    const long long* p = cells.connectivity.data() + cells.offsets[i];
    const std::size_t n = static_cast<std::size_t>(cells.offsets[i + 1] - cells.offsets[i]);
    const long long type = types[i];
    auto need = [&](std::size_t count, const char* name) {
      if (n >= count) return true;
      error = "cell " + std::to_string(i) + " of type " + std::to_string(type) + " (" + name +
              ") has " + std::to_string(n) + " points; expected " + std::to_string(count);
      return false;
    };
    auto at = [&](int k) { return static_cast<Index>(p[k]); };
    switch (type) {
      case 1:
      case 2:
        break;  // vertex, poly-vertex: points only
      case 3:
      case 21:  // line, quadratic edge
        if (!need(2, "line")) return false;
        mesh.edges.push_back({at(0), at(1)});
        if (type == 21) ++reduced[type];
        break;
      case 4:
        addPolyline(p, n, mesh);
        break;
      case 5:
      case 22:  // triangle, quadratic triangle
        if (!need(3, "triangle")) return false;
        mesh.triangles.push_back({at(0), at(1), at(2)});
        if (type == 22) ++reduced[type];
        break;
      case 6:
        addStrip(p, n, mesh);
        break;
      case 7: {
        std::vector<Index> polygon(p, p + n);
        addPolygon(mesh, polygon.data(), polygon.size(), false);
        break;
      }
      case 8:  // pixel: a quad with its last two points swapped
        if (!need(4, "pixel")) return false;
        mesh.quads.push_back({at(0), at(1), at(3), at(2)});
        break;
      case 9:
      case 23:  // quad, quadratic quad
        if (!need(4, "quad")) return false;
        mesh.quads.push_back({at(0), at(1), at(2), at(3)});
        if (type == 23) ++reduced[type];
        break;
      case 10:
      case 24:  // tetrahedron, quadratic tetrahedron
        if (!need(4, "tetrahedron")) return false;
        mesh.tetrahedra.push_back({at(0), at(1), at(2), at(3)});
        if (type == 24) ++reduced[type];
        break;
      case 11:  // voxel: a hexahedron with x-fastest corner order
        if (!need(8, "voxel")) return false;
        mesh.hexahedra.push_back({at(0), at(1), at(3), at(2), at(4), at(5), at(7), at(6)});
        break;
      case 12:
      case 25:  // hexahedron, quadratic hexahedron
        if (!need(8, "hexahedron")) return false;
        mesh.hexahedra.push_back({at(0), at(1), at(2), at(3), at(4), at(5), at(6), at(7)});
        if (type == 25) ++reduced[type];
        break;
      default:
        ++skipped[type];
        break;
    }
  }
  for (const auto& [type, count] : skipped)
    mesh.warnings.push_back(std::to_string(count) + " cells of VTK type " + std::to_string(type) +
                            " (" + cellTypeName(type) +
                            ") skipped: Stroma keeps lines, triangles, quads, tetrahedra and "
                            "hexahedra");
  for (const auto& [type, count] : reduced)
    mesh.warnings.push_back(std::to_string(count) + " quadratic cells of VTK type " +
                            std::to_string(type) + " read as linear cells (corner points only)");
  return true;
}

void addVtkPolyData(const VtkCells& cells, VtkPolyKind kind, MeshData& mesh) {
  std::vector<Index> polygon;
  for (std::size_t i = 0; i < cells.size(); ++i) {
    const long long* p = cells.connectivity.data() + cells.offsets[i];
    const std::size_t n = static_cast<std::size_t>(cells.offsets[i + 1] - cells.offsets[i]);
    switch (kind) {
      case VtkPolyKind::vertices:
        break;
      case VtkPolyKind::lines:
        addPolyline(p, n, mesh);
        break;
      case VtkPolyKind::strips:
        addStrip(p, n, mesh);
        break;
      case VtkPolyKind::polygons:
        polygon.assign(p, p + n);
        addPolygon(mesh, polygon.data(), polygon.size(), false);
        break;
    }
  }
}

}  // namespace stroma::meshio
