// SPDX-License-Identifier: MIT
#pragma once

#include "simulation/VecId.h"

namespace stroma {

class BaseMechanicalState;

/// A hook of CGLinearSolver (matrix-free template) for degrees of freedom that are not unknowns
/// but interpolations of others, such as the T-nodes of a multiresolution grid (seed 001,
/// Algorithm 1, "multiresolution conjugate gradient"). A projective constraint of the solver's
/// system implementing it, on one of the system's independent states, is called by CG:
///
///   interpolateDependent(p)  before each product A p (PROPAGERDEPLACEMENTS: the direction at a
///                            dependent dof is the interpolation of its parents'),
///   clearDependent(x)        on the solution at the end: it is returned in reduced form,
///                            dependent entries zero, as the projection of the same component
///                            (projectResponse) leaves increments.
///
/// The transpose (a dependent dof's force added to its parents with the weights, then zeroed:
/// REMONTERFORCES) is the component's projectResponse, which CG applies to every A p. With these
/// three, CG iterates on T^T A T, T the interpolation from the independent dofs.
class DependentDofs {
 public:
  virtual ~DependentDofs() = default;
  virtual BaseMechanicalState* dependentState() const = 0;
  virtual void interpolateDependent(VecId dx) = 0;
  virtual void clearDependent(VecId dx) = 0;
};

}  // namespace stroma
