// SPDX-License-Identifier: MIT
// The stability bound of explicit schemes: the largest time step h for which an undamped
// linear(ized) system stays bounded, h < c / omega_max, with omega_max^2 the largest
// eigenvalue of M^-1 (-K) and c a constant of the scheme (2 for central differences and
// symplectic Euler, 2 sqrt(2) for the classic Runge-Kutta). For linear tetrahedra this is the
// Courant condition of seeds 000 and 004, h < d sqrt(rho / (lambda + 2 mu)) up to a factor of
// order one set by the element shapes (d the smallest element size): the bound here is
// computed from the mesh, the material and the masses actually in the scene, whatever the
// force fields are, by power iteration on the lumped mass and the tangent stiffness.
#pragma once

#include <string>

#include "DivergenceMonitor.h"
#include "core/Data.h"
#include "simulation/Solvers.h"

namespace stroma {

class MechanicalOperations;

/// omega_max of the linearization of the current forces (call after computeForce: force fields
/// linearize at the positions of their last addForce), by `iterations` power iterations on
/// M^-1 (-K) and a final Rayleigh quotient. Returns 0 when the masses are not all lumped (the
/// estimate would need a linear solve) or when nothing is stiff. `where`, when given, receives
/// the vertex where that highest mode is largest (the stiffest or lightest spot of the mesh).
double largestFrequency(MechanicalOperations& mop, int iterations = 60,
                        std::string* where = nullptr);

/// Keeps an explicit solver's stability bound (output Data `criticalTimeStep`), estimated at the
/// first step, before anything moves (the force fields must have linearized: init is too early),
/// and again whenever dt changes. A time step above it is warned about once per value, or
/// refused when the solver's onDivergence is "stop" (DivergenceMonitor.h).
class ExplicitStabilityCheck {
 public:
  ExplicitStabilityCheck(OdeSolver& solver, double schemeConstant, const char* schemeName)
      : m_solver(solver), m_constant(schemeConstant), m_scheme(schemeName) {}

 private:
  OdeSolver& m_solver;  // first: the Data below registers with it
  double m_constant;
  const char* m_scheme;
  double m_checkedDt = -1;  // the estimate below is for this dt
  double m_bound = 0;
  bool m_aboveBound = false;
  std::string m_text, m_where;  // the report, and where the highest mode is largest

 public:
  Data<double> d_criticalTimeStep{&m_solver,
                                  "criticalTimeStep",
                                  0.0,
                                  "Output: the stability bound c / omega_max of this explicit "
                                  "scheme on the scene (0 until the first step, or when it cannot "
                                  "be estimated).",
                                  {.unit = "s", .output = true}};

  /// Call after the step's computeForce, before integrating. Returns false when dt is above the
  /// bound and `monitor` stops the run (an error then names the step and the bound).
  bool check(MechanicalOperations& mop, double dt, DivergenceMonitor& monitor, long long step);
};

}  // namespace stroma
