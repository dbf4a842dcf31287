// SPDX-License-Identifier: MIT
#include "StateMesh.h"

#include "core/Node.h"
#include "core/StateTypes.h"
#include "simulation/MechanicalState.h"
#include "simulation/StressField.h"
#include "topology/Topology.h"

namespace stroma::vtk {

CellSelection highestDimensionCells(const Topology* topology) {
  CellSelection s;
  if (!topology) return s;
  if (!topology->tetrahedra().empty() || !topology->hexahedra().empty()) {
    s.tetrahedra = !topology->tetrahedra().empty();
    s.hexahedra = !topology->hexahedra().empty();
  } else if (!topology->triangles().empty() || !topology->quads().empty()) {
    s.triangles = !topology->triangles().empty();
    s.quads = !topology->quads().empty();
  } else {
    s.edges = !topology->edges().empty();
  }
  return s;
}

namespace {

template <class Elements>
bool appendList(const Elements& elements, CellType type, const char* name, std::size_t pointCount,
                UnstructuredMesh& mesh, std::string& error) {
  for (std::size_t e = 0; e < elements.size(); ++e) {
    for (Index p : elements[e])
      if (p >= pointCount) {
        error = std::string(name) + " " + std::to_string(e) + " uses point " + std::to_string(p) +
                ", out of the " + std::to_string(pointCount) + " points";
        return false;
      }
    mesh.addCell(type, elements[e].data());
  }
  return true;
}

}  // namespace

bool appendCells(const Topology* topology, const CellSelection& selection, std::size_t pointCount,
                 UnstructuredMesh& mesh, std::string& error) {
  if (!topology || !selection.any()) {
    for (Index p = 0; p < pointCount; ++p) mesh.addCell(CellType::vertex, &p);
    return true;
  }
  // SOFA's exporters' order: edges, triangles, quads, tetrahedra, hexahedra.
  const Topology& t = *topology;
  return (!selection.edges ||
          appendList(t.edges(), CellType::line, "edge", pointCount, mesh, error)) &&
         (!selection.triangles ||
          appendList(t.triangles(), CellType::triangle, "triangle", pointCount, mesh, error)) &&
         (!selection.quads ||
          appendList(t.quads(), CellType::quad, "quad", pointCount, mesh, error)) &&
         (!selection.tetrahedra ||
          appendList(t.tetrahedra(), CellType::tetra, "tetrahedron", pointCount, mesh, error)) &&
         (!selection.hexahedra ||
          appendList(t.hexahedra(), CellType::hexahedron, "hexahedron", pointCount, mesh, error));
}

bool nodeMesh(const Node* node, const std::vector<Vec3d>& given, const CellSelection& selection,
              UnstructuredMesh& mesh, std::string& error) {
  const Topology* topology = node ? node->getUp<Topology>() : nullptr;
  const auto* state = node ? node->get<BaseMechanicalState>() : nullptr;
  if (!given.empty())
    mesh.points = given;
  else if (state)
    mesh.points = statePoints(*state);
  else if (topology)
    mesh.points = topology->positions();
  return appendCells(topology, selection, mesh.points.size(), mesh, error);
}

std::vector<Vec3d> statePoints(const BaseMechanicalState& state) {
  std::vector<double> flat;
  state.copyPositions(flat);
  const int d = state.coordDimension();
  std::vector<Vec3d> points(state.size(), Vec3d::Zero());
  for (std::size_t i = 0; i < points.size(); ++i)
    for (int a = 0; a < std::min(d, 3); ++a) points[i][a] = flat[i * d + a];
  return points;
}

namespace {

void collectStressFields(const Node& node, const BaseMechanicalState& state,
                         std::vector<const StressField*>& out) {
  for (const auto& object : node.objects())
    if (const auto* field = dynamic_cast<const StressField*>(object.get()))
      if (field->stressState() == &state) out.push_back(field);
  for (const auto& child : node.children()) collectStressFields(*child, state, out);
}

}  // namespace

std::vector<const StressField*> findStressFields(const Node& root,
                                                 const BaseMechanicalState& state) {
  std::vector<const StressField*> fields;
  collectStressFields(root, state, fields);
  return fields;
}

void addStateFields(const BaseMechanicalState& state,
                    const std::vector<const StressField*>& stresses, UnstructuredMesh& mesh) {
  const std::size_t n = state.size();
  if (const auto* vec3 = dynamic_cast<const MechanicalState<Vec3Types>*>(&state)) {
    const auto& x = vec3->readCoord(VecId::position());
    const auto& rest = vec3->readCoord(VecId::restPosition());
    if (x.size() == n && rest.size() == n) {
      FieldArray displacement{"displacement", 3, {}};
      displacement.values.reserve(3 * n);
      for (std::size_t i = 0; i < n; ++i)
        for (int a = 0; a < 3; ++a) displacement.values.push_back(x[i][a] - rest[i][a]);
      mesh.pointFields.push_back(std::move(displacement));
    }
  }
  std::vector<double> flat;
  state.copyVelocities(flat);
  const int d = state.derivDimension();
  if (flat.size() == n * static_cast<std::size_t>(d)) {
    FieldArray velocity{"velocity", 3, std::vector<double>(3 * n, 0.0)};
    for (std::size_t i = 0; i < n; ++i)
      for (int a = 0; a < std::min(d, 3); ++a) velocity.values[3 * i + a] = flat[i * d + a];
    mesh.pointFields.push_back(std::move(velocity));
  }
  for (const StressField* field : stresses) {
    std::vector<double> perPoint, perElement;
    if (!field->vonMisesPerPoint(perPoint) || perPoint.size() != n) continue;
    mesh.pointFields.push_back({"vonMises", 1, std::move(perPoint)});
    if (field->vonMisesPerElement(perElement) && perElement.size() == mesh.cellCount() &&
        mesh.cellCount() > 0) {
      // The cells are the field's elements when they are all of one volume type, in the
      // topology's order (the order vonMisesPerElement follows).
      const CellType first = mesh.cellTypes.front();
      bool sameType = first == CellType::tetra || first == CellType::hexahedron;
      for (CellType t : mesh.cellTypes) sameType = sameType && t == first;
      if (sameType) mesh.cellFields.push_back({"vonMises", 1, std::move(perElement)});
    }
    break;
  }
}

}  // namespace stroma::vtk
