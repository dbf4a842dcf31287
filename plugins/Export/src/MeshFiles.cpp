// SPDX-License-Identifier: MIT
#include "MeshFiles.h"

#include <fstream>

namespace stroma::vtk {

namespace fs = std::filesystem;

namespace {

bool open(const fs::path& file, std::ofstream& out, std::string& error) {
  out.open(file, std::ios::binary | std::ios::trunc);
  if (!out) error = "cannot write '" + file.string() + "'";
  return static_cast<bool>(out);
}

bool close(std::ofstream& out, const fs::path& file, std::string& error) {
  out.flush();
  if (!out) error = "writing '" + file.string() + "' failed (disk full?)";
  return static_cast<bool>(out);
}

int gmshType(CellType type) {
  switch (type) {
    case CellType::vertex:
      return 15;
    case CellType::line:
      return 1;
    case CellType::triangle:
      return 2;
    case CellType::quad:
      return 3;
    case CellType::tetra:
      return 4;
    case CellType::hexahedron:
      return 5;
  }
  return 0;
}

void writePoint(std::ostream& out, std::size_t number, const Vec3d& p) {
  out << number << ' ' << formatNumber(p.x()) << ' ' << formatNumber(p.y()) << ' '
      << formatNumber(p.z()) << '\n';
}

}  // namespace

bool writeGmsh(const fs::path& file, const UnstructuredMesh& mesh, std::string& error) {
  if (!checkMesh(mesh, error)) {
    error = std::string("'").append(file.string()).append("': ").append(error);
    return false;
  }
  std::ofstream out;
  if (!open(file, out, error)) return false;
  out << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n" << mesh.points.size() << '\n';
  for (std::size_t i = 0; i < mesh.points.size(); ++i) writePoint(out, i + 1, mesh.points[i]);
  out << "$EndNodes\n$Elements\n" << mesh.cellCount() << '\n';
  std::size_t next = 0;
  for (std::size_t c = 0; c < mesh.cellCount(); ++c) {
    const CellType type = mesh.cellTypes[c];
    out << c + 1 << ' ' << gmshType(type) << " 2 1 1";
    for (int i = 0; i < pointCount(type); ++i) out << ' ' << mesh.connectivity[next++] + 1;
    out << '\n';
  }
  out << "$EndElements\n";
  return close(out, file, error);
}

bool writeTetgen(const fs::path& base, const UnstructuredMesh& mesh, std::string& error) {
  if (!checkMesh(mesh, error)) {
    error = std::string("'").append(base.string()).append("': ").append(error);
    return false;
  }
  for (CellType type : mesh.cellTypes)
    if (type != CellType::tetra) {
      error =
          "TetGen's .ele holds tetrahedra only; the mesh has other cells (choose tetras "
          "only, or another format)";
      return false;
    }
  const fs::path nodeFile = fs::path(base.string() + ".node");
  const fs::path eleFile = fs::path(base.string() + ".ele");
  std::ofstream nodes, elements;
  if (!open(nodeFile, nodes, error) || !open(eleFile, elements, error)) return false;
  nodes << mesh.points.size() << " 3 0 0\n";
  for (std::size_t i = 0; i < mesh.points.size(); ++i) writePoint(nodes, i + 1, mesh.points[i]);
  elements << mesh.cellCount() << " 4 0\n";
  for (std::size_t c = 0; c < mesh.cellCount(); ++c) {
    elements << c + 1;
    for (int i = 0; i < 4; ++i) elements << ' ' << mesh.connectivity[4 * c + i] + 1;
    elements << '\n';
  }
  return close(nodes, nodeFile, error) && close(elements, eleFile, error);
}

}  // namespace stroma::vtk
