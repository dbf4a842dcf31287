// SPDX-License-Identifier: MIT
// What the constraint corrections share: the lumped mass of a solver's degrees of freedom, and
// moving its states by a correction. Free functions (STYLE.md section 4).
#pragma once

#include <Eigen/Core>

#include "simulation/Constraints.h"

namespace stroma {
class MechanicalOperations;
}

namespace stroma::lagrangian {

/// M 1 over the solver's system: each degree of freedom's row sum of the mass matrix.
Eigen::VectorXd massRowSums(MechanicalOperations& mop);

/// x += positionFactor u, v += velocityFactor u (u over the solver's system; rigid orientations
/// turned by the rotation vector), then the mapped states follow.
void moveStates(MechanicalOperations& mop, const ConstraintResponse& response,
                const Eigen::VectorXd& u);

}  // namespace stroma::lagrangian
