// SPDX-License-Identifier: MIT
#include "MeshAssimpLoader.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <sstream>

#include "formats/MeshProcessing.h"

namespace stroma {
namespace {

std::string rgbaText(const Vec4d& c) {
  std::ostringstream text;
  text << c[0] << ' ' << c[1] << ' ' << c[2] << ' ' << c[3];
  return text.str();
}

/// OglModel's material syntax: a name without spaces, then each part on (1) or off (0).
std::string materialText(const AssimpMaterial& m) {
  std::string name = m.name.empty() ? "material" : m.name;
  for (char& c : name)
    if (std::isspace(static_cast<unsigned char>(c))) c = '_';
  std::string text = name;
  const auto part = [&](const char* what, const std::optional<Vec4d>& c) {
    text += std::string(" ") + what + (c ? " 1 " + rgbaText(*c) : " 0 0 0 0 1");
  };
  part("Diffuse", m.diffuse);
  part("Ambient", m.ambient);
  part("Specular", m.specular);
  // OglModel takes [0, 128] (OpenGL's range); formats such as glTF give none.
  if (m.shininess) text += " Shininess 1 " + std::to_string(std::clamp(*m.shininess, 0.0, 128.0));
  return text;
}

}  // namespace

MeshAssimpLoader::MeshAssimpLoader() {
  for (BaseData* input : std::initializer_list<BaseData*>{
           &d_filename, &d_meshIndex, &d_meshName, &d_keepQuads, &d_joinIdenticalVertices,
           &m_placement.translation, &m_placement.rotation, &m_placement.scale3d,
           &m_placement.scale, &m_placement.transformation, &m_placement.flipNormals})
    addInput(input);
  for (BaseData* output : std::initializer_list<BaseData*>{
           &d_position, &d_edges, &d_triangles, &d_quads, &d_normals, &d_texcoords, &d_color,
           &d_material, &d_texturename, &d_meshNames})
    addOutput(output);
}

void MeshAssimpLoader::init() {
  // Read now, so that a bad file is reported by this loader even when nothing links to it.
  d_position.value();
}

void MeshAssimpLoader::clearOutputs() {
  d_position.setValue({});
  d_edges.setValue({});
  d_triangles.setValue({});
  d_quads.setValue({});
  d_normals.setValue({});
  d_texcoords.setValue({});
  d_meshNames.setValue({});
  setMaterialOutputs(nullptr);
}

void MeshAssimpLoader::setMaterialOutputs(const AssimpMaterial* material) {
  const bool given = material && !material->isDefault;
  d_color.setValue(given && material->diffuse ? rgbaText(*material->diffuse) : std::string());
  d_material.setValue(given ? materialText(*material) : std::string());
  FileName texture;
  if (given) texture.original = texture.resolved = material->texture;
  d_texturename.setValue(texture);
}

bool MeshAssimpLoader::userTransform(Eigen::Matrix4d& transform) {
  return m_placement.matrix(*this, transform);
}

std::vector<const AssimpMesh*> MeshAssimpLoader::pickMeshes(const AssimpFile& file) {
  const int index = d_meshIndex.value();
  const std::string& name = d_meshName.value();
  std::vector<const AssimpMesh*> picked;
  if (index < -1) {
    msgError("expected -1 (all meshes) or a mesh index, got " + std::to_string(index), "meshIndex");
    return picked;
  }
  if (index >= 0 && !name.empty()) {
    msgError("meshIndex and meshName both pick a mesh: give one of them", "meshName");
    return picked;
  }
  for (const AssimpMesh& m : file.meshes)
    if ((index < 0 && name.empty()) || (index >= 0 && m.fileIndex == unsigned(index)) ||
        (!name.empty() && m.name == name))
      picked.push_back(&m);
  if (!picked.empty()) return picked;
  std::string names;
  for (std::size_t i = 0; i < file.meshNames.size(); ++i)
    names += (i ? ", " : "") + std::to_string(i) + " '" + file.meshNames[i] + "'";
  if (index >= 0)
    msgError("no mesh " + std::to_string(index) + " placed in '" + d_filename.value().path() +
                 "' (its meshes: " + names + ")",
             "meshIndex");
  else
    msgError("no mesh named '" + name + "' in '" + d_filename.value().path() +
                 "' (its meshes: " + names + ")",
             "meshName");
  return picked;
}

void MeshAssimpLoader::doUpdate() {
  const FileName& file = d_filename.value();
  if (file.original.empty()) {
    msgError("no file given: set filename to a mesh file assimp reads (glTF, PLY, OBJ, STL...)",
             "filename");
    clearOutputs();
    return;
  }
  Eigen::Matrix4d transform = Eigen::Matrix4d::Identity();
  if (!userTransform(transform)) {
    clearOutputs();
    return;
  }
  std::error_code ec;
  if (!std::filesystem::exists(file.path(), ec)) {
    // The scene loader already reported the file it could not find.
    if (file.resolved.empty() && !sourceLocation().file.empty())
      setInvalid();
    else
      msgError("cannot read '" + file.path() + "': no such file", "filename");
    clearOutputs();
    return;
  }
  AssimpFile read;
  std::string error;
  const AssimpReadOptions options{.keepQuads = d_keepQuads.value(),
                                  .joinIdenticalVertices = d_joinIdenticalVertices.value()};
  if (!readAssimpFile(file.path(), options, read, error)) {
    msgError("cannot read '" + file.path() + "' with assimp: " + error, "filename");
    clearOutputs();
    return;
  }
  for (const std::string& warning : read.warnings)
    msgWarning("file '" + file.path() + "': " + warning, "filename");
  const std::vector<const AssimpMesh*> picked = pickMeshes(read);
  if (picked.empty()) {
    clearOutputs();
    return;
  }
  MeshData mesh = mergeMeshes(picked);
  if (transform != Eigen::Matrix4d::Identity()) transformMesh(mesh, transform);
  if (m_placement.flipNormals.value()) flipOrientation(mesh);

  const unsigned materialIndex = picked.front()->material;
  setMaterialOutputs(materialIndex < read.materials.size() ? &read.materials[materialIndex]
                                                           : nullptr);
  d_position.setValue(std::move(mesh.positions));
  d_edges.setValue(std::move(mesh.edges));
  d_triangles.setValue(std::move(mesh.triangles));
  d_quads.setValue(std::move(mesh.quads));
  d_normals.setValue(std::move(mesh.normals));
  d_texcoords.setValue(std::move(mesh.texcoords));
  d_meshNames.setValue(std::move(read.meshNames));
}

}  // namespace stroma
