// SPDX-License-Identifier: MIT
#include "TriangularBendingSprings.h"

#include "SpringKernel.h"
#include "SpringPairs.h"
#include "core/Node.h"

namespace stroma {

template <class DataTypes>
void TriangularBendingSprings<DataTypes>::init() {
  this->initSprings(l_topology, "triangles");
}

template <class DataTypes>
void TriangularBendingSprings<DataTypes>::build() {
  m_topologyRevision = m_topology->revision();
  const std::size_t n = this->mstate()->size();
  const VecCoord& rest = this->mstate()->readCoord(VecId::restPosition());
  const VecCoord& x0 = rest.size() == n ? rest : this->mstate()->readCoord(VecId::position());

  const TriangleHinges found =
      findTriangleHinges(m_topology->triangles(), m_topology->triangleEdges());
  std::vector<Edge> pairs;
  pairs.reserve(found.hinges.size());
  for (const TriangleHinge& h : found.hinges) pairs.push_back({h.b, h.d});
  std::vector<LinearSpring> springs;
  const std::size_t outOfRange =
      appendSprings<kDimension>(pairs, x0, d_stiffness.value(), d_damping.value(), false, springs);
  if (outOfRange) {
    this->msgError("the triangles of " + m_topology->path() + " use points out of range of the " +
                       std::to_string(n) + " points of " + this->mstate()->path() + " (" +
                       std::to_string(outOfRange) + " springs)",
                   "topology");
    d_springs.setValue({});
    return;
  }
  if (found.nonManifoldEdges)
    this->msgWarning(std::to_string(found.nonManifoldEdges) +
                         " edges have more than two triangles: each got one spring, from its "
                         "first two triangles",
                     "topology");
  d_springs.setValue(std::move(springs));
}

template class TriangularBendingSprings<Vec2Types>;
template class TriangularBendingSprings<Vec3Types>;

}  // namespace stroma
