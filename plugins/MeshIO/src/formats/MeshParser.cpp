// SPDX-License-Identifier: MIT
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "FormatParsers.h"
#include "MeshData.h"

namespace stroma {

namespace meshio {

void addPolygon(MeshData& mesh, const Index* v, std::size_t count, bool triangulate) {
  if (count == 3) {
    mesh.triangles.push_back({v[0], v[1], v[2]});
  } else if (count == 4 && !triangulate) {
    mesh.quads.push_back({v[0], v[1], v[2], v[3]});
  } else {
    for (std::size_t k = 2; k < count; ++k) mesh.triangles.push_back({v[0], v[k - 1], v[k]});
  }
}

bool readFileBytes(const std::string& path, std::string& bytes, std::string& error) {
  bytes.clear();
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    error = std::filesystem::exists(path, ec) ? "not a regular file" : "no such file";
    return false;
  }
  std::ifstream file(path, std::ios::binary);
  if (!file) {
    error = "cannot open the file";
    return false;
  }
  std::ostringstream content;
  content << file.rdbuf();
  if (file.bad()) {
    error = "cannot read the file";
    return false;
  }
  bytes = std::move(content).str();
  return true;
}

}  // namespace meshio

const char* meshFormatName(MeshFormat format) {
  switch (format) {
    case MeshFormat::gmsh:
      return "Gmsh";
    case MeshFormat::vtk:
      return "VTK";
    case MeshFormat::obj:
      return "OBJ";
    case MeshFormat::stl:
      return "STL";
  }
  return "?";
}

std::optional<MeshFormat> meshFormatFromFileName(std::string_view fileName) {
  const auto dot = fileName.rfind('.');
  if (dot == std::string_view::npos) return std::nullopt;
  std::string extension;
  for (char c : fileName.substr(dot + 1))
    extension += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (extension == "msh") return MeshFormat::gmsh;
  if (extension == "vtk" || extension == "vtu" || extension == "vtp") return MeshFormat::vtk;
  if (extension == "obj") return MeshFormat::obj;
  if (extension == "stl") return MeshFormat::stl;
  return std::nullopt;
}

bool parseMesh(std::string_view bytes, MeshFormat format, MeshData& mesh, std::string& error,
               const MeshParseOptions& options) {
  mesh = MeshData{};
  error.clear();
  bool ok = false;
  switch (format) {
    case MeshFormat::gmsh:
      ok = meshio::parseGmsh(bytes, mesh, error);
      break;
    case MeshFormat::vtk:
      ok = meshio::parseVtk(bytes, mesh, error);
      break;
    case MeshFormat::obj:
      ok = meshio::parseObj(bytes, options, mesh, error);
      break;
    case MeshFormat::stl:
      ok = meshio::parseStl(bytes, options, mesh, error);
      break;
  }
  if (!ok) {
    if (error.empty()) error = "unreadable file";
    return false;
  }
  // Per-point data covers every point or none.
  if (!mesh.normals.empty()) mesh.normals.resize(mesh.positions.size(), Vec3d::Zero());
  if (!mesh.texcoords.empty()) mesh.texcoords.resize(mesh.positions.size(), Vec2d::Zero());
  return true;
}

bool readMeshFile(const std::string& path, MeshFormat format, MeshData& mesh, std::string& error,
                  const MeshParseOptions& options) {
  std::string bytes;
  if (!meshio::readFileBytes(path, bytes, error)) return false;
  if (bytes.empty()) {
    error = "the file is empty";
    return false;
  }
  return parseMesh(bytes, format, mesh, error, options);
}

}  // namespace stroma
