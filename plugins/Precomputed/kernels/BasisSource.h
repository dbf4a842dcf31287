// SPDX-License-Identifier: MIT
// What a solver offers when its states answer forces through a deformation basis: the
// precomputed linear model (PrecomputedLinearModel) is K^-1 on its basis nodes, so a
// constraint correction in its node (PrecomputedConstraintCorrection) takes its compliance from
// that basis instead of factorising anything again.
#pragma once

#include "Precomputed/kernels/DeformationBasis.h"

namespace stroma::precomputed {

/// Implemented beside OdeSolver by a solver whose response to a force f on its basis nodes is
/// u = B f (static: positions move by u, velocities stay zero). Found with a dynamic_cast from
/// the solver.
class BasisSource {
 public:
  /// The basis in use, null until it is computed or loaded (the solver's bwdInit) or when it
  /// could not be.
  virtual const DeformationBasis* deformationBasis() const = 0;

 protected:
  ~BasisSource() = default;
};

}  // namespace stroma::precomputed
