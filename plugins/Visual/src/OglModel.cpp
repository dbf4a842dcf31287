// SPDX-License-Identifier: MIT
#include "OglModel.h"

#include <cmath>
#include <sstream>

#include "core/Node.h"
#include "formats/MeshData.h"
#include "simulation/Color.h"
#include "simulation/Mapping.h"

namespace stroma {

namespace {

// Area-weighted vertex normals (the cross product of two edges is twice the area).
void computeNormals(const std::vector<Vec3d>& points, const std::vector<Vec3i>& triangles,
                    std::vector<Vec3d>& normals) {
  normals.assign(points.size(), Vec3d::Zero());
  for (const Vec3i& t : triangles) {
    const Vec3d n = (points[t[1]] - points[t[0]]).cross(points[t[2]] - points[t[0]]);
    for (int k = 0; k < 3; ++k) normals[t[k]] += n;
  }
  for (Vec3d& n : normals) {
    const double length = n.norm();
    n = length > 0 ? Vec3d(n / length) : Vec3d(0, 0, 1);
  }
}

// SOFA's material text: "<name> Diffuse <on> r g b a Ambient <on> r g b a Specular <on> r g b a
// Emissive <on> r g b a Shininess <on> s"; a part switched off (or absent) keeps its default.
bool parseMaterial(const std::string& text, VisualMaterial& material, std::string& error) {
  std::istringstream in(text);
  std::string word;
  in >> word;  // the material's name
  while (in >> word) {
    int on = 0;
    if (!(in >> on)) {
      error = "expected 0 or 1 after '" + word + "'";
      return false;
    }
    if (word == "Shininess") {
      double s = 0;
      if (!(in >> s) || s < 0 || s > 128) {
        error = "Shininess takes one number in [0, 128]";
        return false;
      }
      if (on) material.shininess = s;
      continue;
    }
    Vec4d* target = word == "Diffuse"    ? &material.diffuse
                    : word == "Ambient"  ? &material.ambient
                    : word == "Specular" ? &material.specular
                    : word == "Emissive" ? &material.emissive
                                         : nullptr;
    if (!target) {
      error = "unknown part '" + word + "' (Diffuse, Ambient, Specular, Emissive, Shininess)";
      return false;
    }
    Vec4d c;
    if (!(in >> c[0] >> c[1] >> c[2] >> c[3])) {
      error = word + " takes four numbers r g b a";
      return false;
    }
    if (on) *target = c;
  }
  return true;
}

}  // namespace

// Checks what is cheap to check (the color and material texts) without reading the mesh, which
// waits for a renderer.
void OglModel::init() {
  std::string error;
  VisualMaterial material;
  if (!d_material.value().empty() && !parseMaterial(d_material.value(), material, error))
    msgWarning("'" + d_material.value() + "': " + error + "; the default material is used",
               "material");
  Vec4d c;
  if (!d_color.value().empty() && !parseColor(d_color.value(), c, error))
    msgWarning(error + "; the default color is used", "color");
}

BaseMapping* OglModel::findMapping() const {
  if (!node()) return nullptr;
  for (const auto& object : node()->objects())
    if (auto* mapping = dynamic_cast<BaseMapping*>(object.get()))
      if (mapping->visualOutput() == this) return mapping;
  return nullptr;
}

void OglModel::updateVisual() {
  if (!m_prepared) {
    m_prepared = true;
    m_ready = loadRestSurface();
    m_mapping = m_ready ? findMapping() : nullptr;
  }
  if (!m_ready) return;
  if (m_mapping) {
    if (!m_mapping->applyToVisual(m_surface.positions)) {
      m_mapping = nullptr;  // reported once by the mapping; the surface stays at rest
      return;
    }
    // Given normals describe the rest shape only: a mapped surface gets its own.
    computeNormals(m_surface.positions, m_surface.triangles, m_surface.normals);
  } else if (d_position.parent()) {
    // Positions linked to another component's (a state's): follow them.
    std::vector<Vec3d> points = d_position.value();
    if (points.size() == m_surface.positions.size()) {
      std::vector<Vec3d> unused;
      applyTransform(points, unused);
      m_surface.positions = std::move(points);
      computeNormals(m_surface.positions, m_surface.triangles, m_surface.normals);
    }
  }
}

bool OglModel::loadRestSurface() {
  VisualSurface& s = m_surface;
  const bool fromFile = !d_filename.value().original.empty() && d_position.value().empty();
  if (fromFile) {
    if (!readFile(s.positions, s.triangles, s.normals, s.texcoords)) return false;
  } else {
    s.positions = d_position.value();
    s.triangles = d_triangles.value();
    for (const auto& q : d_quads.value()) {
      s.triangles.push_back(Vec3i(q[0], q[1], q[2]));
      s.triangles.push_back(Vec3i(q[0], q[2], q[3]));
    }
    s.texcoords = d_texcoords.value();
    s.normals = d_normal.value();
    const auto& flat = d_normals.value();
    if (s.normals.empty() && flat.size() == 3 * s.positions.size() && !flat.empty())
      for (std::size_t i = 0; i < s.positions.size(); ++i)
        s.normals.emplace_back(flat[3 * i], flat[3 * i + 1], flat[3 * i + 2]);
  }
  const auto n = static_cast<int>(s.positions.size());
  for (std::size_t t = 0; t < s.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k)
      if (s.triangles[t][k] < 0 || s.triangles[t][k] >= n) {
        msgError("triangle " + std::to_string(t) + " uses point " +
                     std::to_string(s.triangles[t][k]) + ", out of range of the " +
                     std::to_string(n) + " points",
                 "triangles");
        return false;
      }
  if (!s.texcoords.empty() && s.texcoords.size() != s.positions.size()) {
    msgWarning("has " + std::to_string(s.texcoords.size()) + " texture coordinates for " +
                   std::to_string(n) + " points; drawn without texture",
               "texcoords");
    s.texcoords.clear();
  }
  const Vec2d scaleTex = d_scaleTex.value();
  for (Vec2d& uv : s.texcoords) uv = uv.cwiseProduct(scaleTex);
  m_givenNormals = s.normals.size() == s.positions.size() && !s.normals.empty() &&
                   d_useNormals.value();
  applyTransform(s.positions, s.normals);
  if (!m_givenNormals) computeNormals(s.positions, s.triangles, s.normals);
  readMaterial();
  s.texture = d_texturename.value().original.empty() ? std::string()
                                                      : d_texturename.value().path();
  s.alphaBlend = d_alphaBlend.value() || s.material.diffuse[3] < 1.0;
  return true;
}

bool OglModel::readFile(std::vector<Vec3d>& positions, std::vector<Vec3i>& triangles,
                        std::vector<Vec3d>& normals, std::vector<Vec2d>& texcoords) {
  const std::string& path = d_filename.value().path();
  const auto format = meshFormatFromFileName(path);
  if (!format) {
    msgError("'" + d_filename.value().original +
                 "': unknown mesh format (OBJ, STL, VTK, Gmsh by extension)",
             "filename");
    return false;
  }
  MeshData mesh;
  std::string error;
  MeshParseOptions options;
  options.triangulate = true;
  options.handleSeams = true;  // texture seams keep their own points
  if (!readMeshFile(path, *format, mesh, error, options)) {
    msgError(d_filename.value().original + ": " + error, "filename");
    return false;
  }
  for (const std::string& w : mesh.warnings)
    msgWarning(d_filename.value().original + ": " + w, "filename");
  positions = std::move(mesh.positions);
  triangles.clear();
  for (const Triangle& t : mesh.triangles)
    triangles.push_back(Vec3i(static_cast<int>(t[0]), static_cast<int>(t[1]),
                              static_cast<int>(t[2])));
  for (const Quad& q : mesh.quads) {
    triangles.push_back(Vec3i(static_cast<int>(q[0]), static_cast<int>(q[1]),
                              static_cast<int>(q[2])));
    triangles.push_back(Vec3i(static_cast<int>(q[0]), static_cast<int>(q[2]),
                              static_cast<int>(q[3])));
  }
  normals = std::move(mesh.normals);
  texcoords = std::move(mesh.texcoords);
  if (triangles.empty())
    msgWarning(d_filename.value().original + " has no triangles: nothing to draw", "filename");
  return true;
}

// SOFA's order: scale, then the rotation (Euler angles about x, then y, then z, in degrees),
// then the translation.
void OglModel::applyTransform(std::vector<Vec3d>& points, std::vector<Vec3d>& normals) const {
  Vec3d scale = d_scale3d.value();
  const auto& s = d_scale.value();
  if (s.size() == 1) scale *= s[0];
  else if (s.size() == 3) scale = scale.cwiseProduct(Vec3d(s[0], s[1], s[2]));
  const Vec3d angles =
      (d_rotation.value() + Vec3d(d_rx.value(), d_ry.value(), d_rz.value())) * M_PI / 180.0;
  const Quat rotation = Eigen::AngleAxisd(angles.z(), Vec3d::UnitZ()) *
                        Eigen::AngleAxisd(angles.y(), Vec3d::UnitY()) *
                        Eigen::AngleAxisd(angles.x(), Vec3d::UnitX());
  const Vec3d translation =
      d_translation.value() + Vec3d(d_dx.value(), d_dy.value(), d_dz.value());
  const bool identity = scale == Vec3d::Ones() && angles == Vec3d::Zero() &&
                        translation == Vec3d::Zero();
  if (identity) return;
  for (Vec3d& p : points) p = rotation * p.cwiseProduct(scale) + translation;
  // Normals transform with the inverse transpose of the scaling.
  const Vec3d inverseScale = scale.cwiseInverse();
  for (Vec3d& n : normals) {
    n = rotation * n.cwiseProduct(inverseScale);
    const double length = n.norm();
    if (length > 0) n /= length;
  }
}

// The material text, then the color (which, when set, gives the diffuse color and a darker
// ambient one).
void OglModel::readMaterial() {
  VisualMaterial& m = m_surface.material;
  m = VisualMaterial{};
  std::string error;  // both texts were checked (and reported) by init()
  if (!d_material.value().empty() && !parseMaterial(d_material.value(), m, error))
    m = VisualMaterial{};
  Vec4d c;
  if (!d_color.value().empty() && parseColor(d_color.value(), c, error)) {
    m.diffuse = c;
    m.ambient = Vec4d(0.2 * c[0], 0.2 * c[1], 0.2 * c[2], c[3]);
  }
}

}  // namespace stroma
