// SPDX-License-Identifier: MIT
#include "QuadBendingSprings.h"

#include "SpringKernel.h"
#include "SpringPairs.h"
#include "core/Node.h"

namespace stroma {

template <class DataTypes>
void QuadBendingSprings<DataTypes>::init() {
  this->initSprings(l_topology, "quads");
}

template <class DataTypes>
void QuadBendingSprings<DataTypes>::build() {
  m_topologyRevision = m_topology->revision();
  const std::size_t n = this->mstate()->size();
  // As SOFA: the rest lengths are measured on the positions (at init, or when the mesh changes).
  const VecCoord& x0 = this->mstate()->readCoord(VecId::position());

  const BendingPairs found =
      findQuadBendingPairs(m_topology->quads(), m_topology->quadEdges(), true);
  const Vec2i range = d_localRange.value();
  std::vector<Edge> pairs;
  for (const Edge& p : found.pairs) {
    if (range[0] >= 0 && (p[0] < Index(range[0]) || p[1] < Index(range[0]))) continue;
    if (range[1] >= 0 && p[0] > Index(range[1]) && p[1] > Index(range[1])) continue;
    pairs.push_back(p);
  }
  std::vector<LinearSpring> springs;
  const std::size_t outOfRange =
      appendSprings<kDimension>(pairs, x0, d_stiffness.value(), d_damping.value(), false, springs);
  if (outOfRange) {
    this->msgError("the quads of " + m_topology->path() + " use points out of range of the " +
                       std::to_string(n) + " points of " + this->mstate()->path() + " (" +
                       std::to_string(outOfRange) + " springs)",
                   "topology");
    d_springs.setValue({});
    return;
  }
  if (found.nonManifoldEdges)
    this->msgWarning(std::to_string(found.nonManifoldEdges) +
                         " edges have more than two quads: each got its springs from its first "
                         "two quads",
                     "topology");
  d_springs.setValue(std::move(springs));
}

template class QuadBendingSprings<Vec2Types>;
template class QuadBendingSprings<Vec3Types>;

}  // namespace stroma
