// SPDX-License-Identifier: MIT
#include "TetrahedralMesh.h"

#include <cmath>

#include "core/Message.h"
#include "core/Node.h"

namespace stroma {

bool TetrahedralMesh::read(Base& owner, const Link<Topology>& link, const State& state) {
  m_topology = findTetrahedralTopology(owner, link);
  if (!m_topology) return false;
  m_tetrahedra = m_topology->tetrahedra();
  m_revision = m_topology->revision();
  m_pointCount = state.size();
  m_restPositions = state.readCoord(VecId::restPosition());
  if (m_restPositions.size() != m_pointCount) {
    owner.msgError("the mechanical state " + state.path() + " has " +
                       std::to_string(m_restPositions.size()) + " rest positions for " +
                       std::to_string(m_pointCount) + " points",
                   "mstate");
    return false;
  }

  // Indices, then the rest shape of each tetrahedron.
  std::vector<Index> outOfRange, flat, inverted;
  m_shapes.assign(m_tetrahedra.size(), {});
  for (std::size_t t = 0; t < m_tetrahedra.size(); ++t) {
    fem::TetrahedronVectors rest;
    bool inRange = true;
    for (int i = 0; i < 4; ++i) {
      const Index p = m_tetrahedra[t][i];
      if (p >= m_pointCount) {
        inRange = false;
        break;
      }
      rest.col(i) = m_restPositions[p];
    }
    if (!inRange) {
      outOfRange.push_back(static_cast<Index>(t));
      continue;
    }
    if (fem::computeTetrahedronShape(rest, m_shapes[t]) != fem::ElementStatus::ok)
      flat.push_back(static_cast<Index>(t));
    else if (m_shapes[t].volume < 0)
      inverted.push_back(static_cast<Index>(t));
  }
  const std::string where = " of " + m_topology->path();
  if (!outOfRange.empty())
    owner.msgError(std::to_string(outOfRange.size()) + " tetrahedra" + where +
                       " use points out of range of the " + std::to_string(m_pointCount) +
                       " points of the mechanical state: elements " + describeIndices(outOfRange),
                   "topology");
  if (!flat.empty())
    owner.msgError(std::to_string(flat.size()) + " tetrahedra" + where +
                       " are flat in the rest shape (zero volume, or non-finite positions): "
                       "elements " +
                       describeIndices(flat),
                   "topology");
  if (!inverted.empty())
    owner.msgError(std::to_string(inverted.size()) + " tetrahedra" + where +
                       " are inverted in the rest shape (negative volume): elements " +
                       describeIndices(inverted) +
                       "; list each as (a, b, c, d) with (b-a).((c-a)x(d-a)) > 0 (SOFA's order)",
                   "topology");
  return outOfRange.empty() && flat.empty() && inverted.empty();
}

bool TetrahedralMesh::changed(const State& state) const {
  return m_topology && (m_topology->revision() != m_revision || state.size() != m_pointCount);
}

tensormass::TensorMassMesh TetrahedralMesh::tensorMassMesh() const {
  const ElementEdges<6>& edges = m_topology->tetrahedronEdges();
  const TetrahedronFaces& faces = m_topology->tetrahedronFaces();
  return {.pointCount = m_pointCount,
          .tetrahedra = m_tetrahedra,
          .shapes = m_shapes,
          .edges = edges.edges,
          .edgesInTetrahedron = edges.edgesInElement,
          .triangles = faces.faces,
          .trianglesInTetrahedron = faces.facesInElement};
}

std::optional<fem::LameParameters> readIsotropicMaterial(Base& owner, double youngModulus,
                                                         double poissonRatio, bool atInit) {
  std::string field, text;
  if (!(youngModulus > 0) || !std::isfinite(youngModulus)) {
    field = "youngModulus";
    text = "expected a finite value > 0, got " + formatNumber(youngModulus);
  } else if (!(poissonRatio > -1 && poissonRatio < 0.5)) {
    field = "poissonRatio";
    text =
        "expected -1 < poissonRatio < 0.5 (0.5 is incompressible: lambda would be "
        "infinite), got " +
        formatNumber(poissonRatio);
  } else {
    return fem::computeLameParameters(youngModulus, poissonRatio);
  }
  if (atInit)
    owner.msgError(text, field);
  else
    owner.msgWarning(text + "; the change is not applied, the previous material stays", field);
  return std::nullopt;
}

std::string describeIndices(const std::vector<Index>& indices) {
  constexpr std::size_t kShown = 10;
  std::string text;
  for (std::size_t i = 0; i < indices.size() && i < kShown; ++i)
    text += (i ? ", " : "") + std::to_string(indices[i]);
  if (indices.size() > kShown) text += ", ... (" + std::to_string(indices.size()) + " in all)";
  return text;
}

}  // namespace stroma
