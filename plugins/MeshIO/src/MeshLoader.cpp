// SPDX-License-Identifier: MIT
#include "MeshLoader.h"

#include <filesystem>

#include "formats/MeshProcessing.h"

namespace stroma {

MeshLoader::MeshLoader(MeshFormat format) : m_format(format) {
  for (BaseData* input : std::initializer_list<BaseData*>{
           &d_filename, &m_placement.translation, &m_placement.rotation, &m_placement.scale3d,
           &m_placement.scale, &m_placement.transformation, &m_placement.flipNormals, &d_triangulate, &d_createSubelements, &d_onlyAttachedPoints})
    addInput(input);
  for (BaseData* output : std::initializer_list<BaseData*>{
           &d_position, &d_edges, &d_triangles, &d_quads, &d_tetrahedra, &d_hexahedra, &d_normals})
    addOutput(output);
}

void MeshLoader::init() {
  // Read now, so that a bad file is reported by this loader even when nothing links to it.
  d_position.value();
}

void MeshLoader::clearOutputs() {
  d_position.setValue({});
  d_edges.setValue({});
  d_triangles.setValue({});
  d_quads.setValue({});
  d_tetrahedra.setValue({});
  d_hexahedra.setValue({});
  d_normals.setValue({});
  clearFormatOutputs();
}

void MeshLoader::doUpdate() {
  const FileName& file = d_filename.value();
  if (file.original.empty()) {
    msgError(
        "no file given: set filename to a " + std::string(meshFormatName(m_format)) + " mesh file",
        "filename");
    clearOutputs();
    return;
  }
  // Transformation settings, checked before the file is read.
  Eigen::Matrix4d transform = Eigen::Matrix4d::Identity();
  if (!m_placement.matrix(*this, transform)) {
    clearOutputs();
    return;
  }

  // A file the scene named but the scene loader could not find is already reported there.
  std::error_code ec;
  if (file.resolved.empty() && !sourceLocation().file.empty() &&
      !std::filesystem::exists(file.original, ec)) {
    setInvalid();
    clearOutputs();
    return;
  }
  MeshData mesh;
  std::string error;
  if (!readMeshFile(file.path(), m_format, mesh, error, parseOptions())) {
    msgError("cannot read " + std::string(meshFormatName(m_format)) + " file '" + file.path() +
                 "': " + error,
             "filename");
    clearOutputs();
    return;
  }
  for (const std::string& warning : mesh.warnings)
    msgWarning("file '" + file.path() + "': " + warning, "filename");

  if (d_triangulate.value()) triangulateQuads(mesh);
  if (d_createSubelements.value()) createSubelements(mesh);
  if (d_onlyAttachedPoints.value()) removeUnattachedPoints(mesh);
  if (transform != Eigen::Matrix4d::Identity()) transformMesh(mesh, transform);
  if (m_placement.flipNormals.value()) flipOrientation(mesh);

  d_position.setValue(std::move(mesh.positions));
  d_edges.setValue(std::move(mesh.edges));
  d_triangles.setValue(std::move(mesh.triangles));
  d_quads.setValue(std::move(mesh.quads));
  d_tetrahedra.setValue(std::move(mesh.tetrahedra));
  d_hexahedra.setValue(std::move(mesh.hexahedra));
  d_normals.setValue(std::move(mesh.normals));
  setFormatOutputs(mesh);
}

}  // namespace stroma
