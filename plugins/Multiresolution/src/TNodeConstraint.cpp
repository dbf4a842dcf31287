// SPDX-License-Identifier: MIT
#include "TNodeConstraint.h"

#include "MultiresolutionGridTopology.h"
#include "core/Node.h"

namespace stroma {

void TNodeConstraint::init() {
  ProjectiveConstraint<Vec3Types>::init();
  m_tNodes.clear();
  if (!mstate()) return;
  const MultiresolutionGridTopology* grid = nullptr;
  if (l_topology) {
    grid = dynamic_cast<const MultiresolutionGridTopology*>(l_topology.get());
    if (!grid) {
      msgError("the linked component is not a MultiresolutionGridTopology", "topology");
      return;
    }
  } else if (node()) {
    grid = node()->get<MultiresolutionGridTopology>();
  }
  if (!grid) {
    msgError("no MultiresolutionGridTopology in " + (node() ? node()->path() : std::string("?")) +
                 " (link one with topology=\"@...\")",
             "topology");
    return;
  }
  const std::size_t n = mstate()->size();
  for (const auto& t : grid->tNodes()) {
    bool inRange = t.node < n;
    for (int k = 0; k < t.parentCount; ++k) inRange = inRange && t.parents[k] < n;
    if (!inRange) {
      msgError("the grid's T-nodes refer to points beyond the " + std::to_string(n) +
                   " points of " + mstate()->path() + ": the state is not the grid's",
               "topology");
      m_tNodes.clear();
      return;
    }
    m_tNodes.push_back(t);
  }
  // The forces pushed to fixed parents must be zeroed after: this must come first.
  if (node())
    for (const auto& object : node()->objects()) {
      if (object.get() == this) break;
      if (dynamic_cast<BaseProjectiveConstraint*>(object.get()))
        msgWarning(object->name() +
                       " comes before it in the node: a T-node's force added to a parent that " +
                       object->name() + " constrains would escape it; place TNodeConstraint first",
                   "");
    }
}

template <class Vector>
void TNodeConstraint::interpolate(Vector& values) const {
  // Parents are coarse nodes, never T-nodes themselves: the order does not matter.
  for (const auto& t : m_tNodes) {
    if (t.node >= values.size()) continue;
    typename Vector::value_type sum = Vec3d::Zero();
    for (int k = 0; k < t.parentCount; ++k) sum += t.weights[k] * values[t.parents[k]];
    values[t.node] = sum;
  }
}

void TNodeConstraint::projectResponse(VecDeriv& dx) {
  for (const auto& t : m_tNodes) {
    if (t.node >= dx.size()) continue;
    for (int k = 0; k < t.parentCount; ++k) dx[t.parents[k]] += t.weights[k] * dx[t.node];
    dx[t.node] = Vec3d::Zero();
  }
}

void TNodeConstraint::projectVelocity(VecDeriv& v, double) { interpolate(v); }
void TNodeConstraint::projectPosition(VecCoord& x, double) { interpolate(x); }

void TNodeConstraint::interpolateDependent(VecId dx) { interpolate(mstate()->writeDeriv(dx)); }

void TNodeConstraint::clearDependent(VecId dx) {
  auto& values = mstate()->writeDeriv(dx);
  for (const auto& t : m_tNodes)
    if (t.node < values.size()) values[t.node] = Vec3d::Zero();
}

void TNodeConstraint::fixedRows(std::vector<std::size_t>& rows) const {
  if (m_tNodes.empty()) return;
  if (!m_reportedAssembled) {
    m_reportedAssembled = true;
    msgWarning("the solver assembles the matrix, which cannot hold the interpolation of the " +
                   std::to_string(m_tNodes.size()) +
                   " T-nodes: they are solved as fixed and interpolated after, which is not the "
                   "equilibrium; use CGLinearSolver with its default (matrix-free) template",
               "");
  }
  for (const auto& t : m_tNodes)
    for (std::size_t k = 0; k < 3; ++k) rows.push_back(3 * std::size_t(t.node) + k);
}

}  // namespace stroma
