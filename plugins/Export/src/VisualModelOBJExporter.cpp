// SPDX-License-Identifier: MIT
#include "VisualModelOBJExporter.h"

#include <filesystem>
#include <fstream>

#include "OutputFile.h"
#include "VtkFiles.h"
#include "core/Node.h"
#include "simulation/VisualModel.h"

namespace stroma {

namespace {

void collectVisualModels(Node& node, std::vector<VisualModel*>& models) {
  for (VisualModel* model : node.getAll<VisualModel>()) models.push_back(model);
  for (const auto& child : node.children()) collectVisualModels(*child, models);
}

std::string number(double v) { return vtk::formatNumber(v); }

std::string color(const Vec4d& c) { return number(c[0]) + " " + number(c[1]) + " " + number(c[2]); }

/// A name usable in OBJ and MTL statements (no spaces).
std::string plainName(std::string name, std::size_t index) {
  for (char& c : name)
    if (c == ' ' || c == '\t' || c == '\n') c = '_';
  return name.empty() ? "model" + std::to_string(index) : name;
}

}  // namespace

void VisualModelOBJExporter::init() {
  m_ready = false;
  const std::string base = stripExtension(d_filename.value().original, ".obj").string();
  if (!checkOutputFolder(*this, base, "filename")) return setInvalid();
  m_ready = true;
}

void VisualModelOBJExporter::bwdInit() {
  if (m_ready && m_schedule.atBegin()) write(m_schedule.nextFileSuffix());
}

void VisualModelOBJExporter::stepEnd(double, double) {
  if (m_ready && m_schedule.stepDone()) write(m_schedule.nextFileSuffix());
}

void VisualModelOBJExporter::cleanup() {
  if (m_ready && m_schedule.atEnd()) write(m_schedule.nextFileSuffix());
  m_ready = false;
}

void VisualModelOBJExporter::write(const std::string& suffix) {
  const std::string base = stripExtension(d_filename.value().original, ".obj").string() + suffix;
  const std::string objFile = base + ".obj", mtlFile = base + ".mtl";
  std::ofstream obj(objFile, std::ios::binary | std::ios::trunc);
  std::ofstream mtl(mtlFile, std::ios::binary | std::ios::trunc);
  if (!obj || !mtl) {
    msgError("cannot write '" + (obj ? mtlFile : objFile) + "'", "filename");
    m_ready = false;
    return;
  }
  std::vector<VisualModel*> models;
  if (node()) collectVisualModels(*node(), models);
  obj << "# Stroma VisualModelOBJExporter\nmtllib "
      << std::filesystem::path(mtlFile).filename().string() << '\n';
  std::size_t firstPosition = 1, firstTexcoord = 1, firstNormal = 1, written = 0;
  for (std::size_t m = 0; m < models.size(); ++m) {
    VisualModel& model = *models[m];
    model.updateVisual();
    const VisualSurface* surface = model.surface();
    if (!surface || surface->positions.empty()) continue;
    const std::string name = plainName(model.name(), m);
    const std::size_t n = surface->positions.size();
    const bool hasTexcoords = surface->texcoords.size() == n;
    const bool hasNormals = surface->normals.size() == n;

    const VisualMaterial& material = surface->material;
    mtl << "newmtl " << name << "\nKa " << color(material.ambient) << "\nKd "
        << color(material.diffuse) << "\nKs " << color(material.specular) << "\nKe "
        << color(material.emissive) << "\nNs " << number(material.shininess) << "\nd "
        << number(material.diffuse[3]) << '\n';
    if (!surface->texture.empty()) mtl << "map_Kd " << surface->texture << '\n';
    mtl << '\n';

    obj << "o " << name << "\nusemtl " << name << '\n';
    for (const Vec3d& p : surface->positions)
      obj << "v " << number(p.x()) << ' ' << number(p.y()) << ' ' << number(p.z()) << '\n';
    if (hasTexcoords)
      for (const Vec2d& t : surface->texcoords)
        obj << "vt " << number(t.x()) << ' ' << number(t.y()) << '\n';
    if (hasNormals)
      for (const Vec3d& v : surface->normals)
        obj << "vn " << number(v.x()) << ' ' << number(v.y()) << ' ' << number(v.z()) << '\n';
    for (const Vec3i& t : surface->triangles) {
      obj << 'f';
      for (int k = 0; k < 3; ++k) {
        const auto i = static_cast<std::size_t>(t[k]);
        obj << ' ' << firstPosition + i;
        if (hasTexcoords || hasNormals) obj << '/';
        if (hasTexcoords) obj << firstTexcoord + i;
        if (hasNormals) obj << '/' << firstNormal + i;
      }
      obj << '\n';
    }
    firstPosition += n;
    if (hasTexcoords) firstTexcoord += n;
    if (hasNormals) firstNormal += n;
    ++written;
  }
  obj.flush();
  mtl.flush();
  if (!obj || !mtl) {
    msgError("writing '" + objFile + "' failed (disk full?)", "filename");
    m_ready = false;
    return;
  }
  if (written == 0 && !m_warnedEmpty) {
    msgWarning("no visual model with a surface under " + (node() ? node()->path() : "?") + ": '" +
               objFile + "' holds no object");
    m_warnedEmpty = true;
  }
  m_written.push_back(objFile);
}

}  // namespace stroma
