// SPDX-License-Identifier: MIT
#pragma once

#include <vector>

#include "simulation/DependentDofs.h"
#include "MultiresolutionGrid.h"
#include "core/StateTypes.h"
#include "simulation/ProjectiveConstraint.h"

namespace stroma {

class MultiresolutionGridTopology;

/// Keeps the T-nodes of a MultiresolutionGridTopology on the coarse edge or face they lie on
/// (seed 001, chapter 4 section 4, Algorithm 1). A T-node t with parents p_k and weights w_k is
/// not an unknown: u_t = sum_k w_k u_pk. With T that interpolation from the other nodes, the
/// system solved is T^T A T u = T^T b:
///
///   projectResponse(f):  f_pk += w_k f_t, then f_t = 0        (REMONTERFORCES, T^T)
///   interpolateDependent(dx): dx_t = sum_k w_k dx_pk           (PROPAGERDEPLACEMENTS, T)
///   projectPosition / projectVelocity: x_t, v_t interpolated the same way
///
/// CGLinearSolver (matrix-free) calls interpolateDependent before each product (DependentDofs.h)
/// and returns its solution with the T-node entries zero, which projectPosition/Velocity fill at
/// the end of the step; so does the explicit path. An assembled matrix (direct solvers, CG's
/// CompressedRowSparseMatrix template) cannot express T: the T-nodes are then solved as fixed
/// and interpolated after, which is not the equilibrium; a warning says so.
///
/// Place it before the other projective constraints of the node (FixedProjectiveConstraint...):
/// a fixed parent must be zeroed after a T-node's force was added to it (a warning otherwise).
class TNodeConstraint final : public ProjectiveConstraint<Vec3Types>, public DependentDofs {
 public:
  Link<Base> l_topology{this, "topology",
                        "The MultiresolutionGridTopology giving the T-nodes (default: the "
                        "node's)."};

  void init() override;
  void reinit() override { init(); }

  void projectResponse(VecDeriv& dx) override;
  void projectVelocity(VecDeriv& v, double time) override;
  void projectPosition(VecCoord& x, double time) override;
  void fixedRows(std::vector<std::size_t>& rows) const override;

  BaseMechanicalState* dependentState() const override { return state(); }
  void interpolateDependent(VecId dx) override;
  void clearDependent(VecId dx) override;

  const std::vector<multiresolution::TNode>& tNodes() const { return m_tNodes; }

 private:
  template <class Vector>
  void interpolate(Vector& values) const;

  std::vector<multiresolution::TNode> m_tNodes;
  mutable bool m_reportedAssembled = false;
};

}  // namespace stroma
