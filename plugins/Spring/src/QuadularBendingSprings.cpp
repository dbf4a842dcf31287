// SPDX-License-Identifier: MIT
#include "QuadularBendingSprings.h"

#include "SpringKernel.h"
#include "SpringPairs.h"
#include "core/Node.h"

namespace stroma {

template <class DataTypes>
void QuadularBendingSprings<DataTypes>::init() {
  this->initSprings(l_topology, "quads");
}

template <class DataTypes>
void QuadularBendingSprings<DataTypes>::build() {
  m_topologyRevision = m_topology->revision();
  const std::size_t n = this->mstate()->size();
  const VecCoord& rest = this->mstate()->readCoord(VecId::restPosition());
  const VecCoord& x0 = rest.size() == n ? rest : this->mstate()->readCoord(VecId::position());

  const BendingPairs found =
      findQuadBendingPairs(m_topology->quads(), m_topology->quadEdges(), false);
  const std::vector<Edge>& pairs = found.pairs;
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

template class QuadularBendingSprings<Vec2Types>;
template class QuadularBendingSprings<Vec3Types>;

}  // namespace stroma
