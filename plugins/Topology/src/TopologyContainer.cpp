// SPDX-License-Identifier: MIT
#include "TopologyContainer.h"

#include "formats/MeshData.h"

namespace stroma {

bool givenInScene(const BaseData& data) {
  return !data.linkText().empty() || (data.isSet() && data.parent() == nullptr);
}

TopologyContainer::TopologyContainer(unsigned held, bool createsSubElements)
    : m_kinds(held), m_createsSubElements(createsSubElements) {}

void TopologyContainer::init() {
  adoptAlias(d_points, d_position);
  adoptAlias(d_fileTopology, d_filename);
  adoptAliases();
  readFile();
  reinit();
}

void TopologyContainer::reinit() {
  dropUnheldKinds();
  // Sub-elements are made from checked elements only, so that errors name the given lists.
  if (checkElements() && m_createsSubElements) createSubElements();
}

void TopologyContainer::readFile() {
  // A filename that only follows src="@loader" is the loader's business: the loader read it.
  if (m_fileRead || !givenInScene(d_filename) || d_filename.value().original.empty()) return;
  m_fileRead = true;
  const std::string path = d_filename.value().path();
  const auto format = meshFormatFromFileName(path);
  if (!format) {
    msgError("cannot tell the format of '" + path +
                 "' from its extension: expected .msh, .vtk, .vtu, .vtp, .obj or .stl",
             "filename");
    return;
  }
  MeshData mesh;
  std::string error;
  if (!readMeshFile(path, *format, mesh, error)) {
    msgError(
        "cannot read " + std::string(meshFormatName(*format)) + " file '" + path + "': " + error,
        "filename");
    return;
  }
  for (const std::string& warning : mesh.warnings)
    msgWarning("file '" + path + "': " + warning, "filename");
  // The file fills what the scene did not give here.
  auto fill = [](auto& data, auto&& values) {
    if (givenInScene(data)) return;
    std::string ignored;
    data.setParent(nullptr, ignored);
    data.setValue(std::move(values));
  };
  fill(d_position, std::move(mesh.positions));
  fill(d_edges, std::move(mesh.edges));
  fill(d_triangles, std::move(mesh.triangles));
  fill(d_quads, std::move(mesh.quads));
  fill(d_tetrahedra, std::move(mesh.tetrahedra));
  fill(d_hexahedra, std::move(mesh.hexahedra));
}

void TopologyContainer::dropUnheldKinds() {
  auto drop = [&](unsigned kind, auto& data) {
    if (holds(kind) || data.value().empty()) return;
    if (givenInScene(data))
      msgWarning(std::to_string(data.value().size()) + " " + data.name() + " ignored: a " +
                     className() + " keeps no " + data.name() +
                     " (MeshTopology keeps every kind of element)",
                 data.name());
    std::string ignored;
    data.setParent(nullptr, ignored);
    data.setValue({});
  };
  drop(kinds::edges, d_edges);
  drop(kinds::triangles, d_triangles);
  drop(kinds::quads, d_quads);
  drop(kinds::tetrahedra, d_tetrahedra);
  drop(kinds::hexahedra, d_hexahedra);
}

void TopologyContainer::createSubElements() {
  // A list this container made before is made again from the current elements.
  auto make = [](bool& made, auto& data, auto&& values) {
    if (!made && !data.value().empty()) return;
    made = !values.empty();
    if (made || !data.value().empty()) data.setValue(std::move(values));
  };
  if (holds(kinds::tetrahedra) && holds(kinds::triangles))
    make(m_madeTriangles, d_triangles, std::vector<Triangle>(tetrahedronFaces().faces));
  if (holds(kinds::hexahedra) && holds(kinds::quads))
    make(m_madeQuads, d_quads, std::vector<Quad>(hexahedronFaces().faces));
  if (holds(kinds::edges)) {
    const bool generate = m_madeEdges || d_edges.value().empty();
    if (generate)
      make(m_madeEdges, d_edges,
           computeAllEdges({}, triangles(), quads(), tetrahedra(), hexahedra()));
  }
}

}  // namespace stroma
