// SPDX-License-Identifier: MIT
#include "CGImplicitSolver.h"
#include "CentralDifferenceSolver.h"
#include "EulerExplicitSolver.h"
#include "EulerImplicitSolver.h"
#include "NewmarkImplicitSolver.h"
#include "NewtonRaphsonSolver.h"
#include "RungeKutta2Solver.h"
#include "RungeKutta4Solver.h"
#include "StaticSolver.h"
#include "core/Plugin.h"

namespace {

void registerComponents(stroma::PluginRegistry& registry) {
  using namespace stroma;
  registry.add("EulerExplicitSolver", "Explicit (symplectic by default) Euler integration")
      .with<EulerExplicitSolver>();
  registry
      .add("EulerImplicitSolver",
           "Implicit Euler with Rayleigh damping, linearized or with Newton iterations")
      .with<EulerImplicitSolver>()
      .alias("EulerImplicit");
  // SOFA reads its old CGImplicit element as an EulerImplicitSolver and a CGLinearSolver: the same
  // model, here one component owning both (CGImplicitSolver.h).
  registry
      .add("CGImplicitSolver", "Implicit Euler with a conjugate gradient of its own (SOFA's older solver)")
      .with<CGImplicitSolver>()
      .alias("CGImplicit");
  registry
      .add("CentralDifferenceSolver",
           "Explicit central differences (leapfrog) with Rayleigh mass damping")
      .with<CentralDifferenceSolver>();
  registry.add("RungeKutta2Solver", "Explicit midpoint rule (second-order Runge-Kutta)")
      .with<RungeKutta2Solver>();
  registry.add("RungeKutta4Solver", "Classic explicit fourth-order Runge-Kutta")
      .with<RungeKutta4Solver>();
  registry.add("NewmarkImplicitSolver", "Newmark beta implicit integration (average acceleration)")
      .with<NewmarkImplicitSolver>();
  registry.add("StaticSolver", "Static equilibrium by Newton-Raphson with a line search")
      .with<StaticSolver>();
  registry.add("NewtonRaphsonSolver", "Newton-Raphson parameters for StaticSolver (newtonSolver)")
      .with<NewtonRaphsonSolver>();
}

}  // namespace

extern "C" STROMA_PLUGIN_EXPORT const stroma::PluginEntry* stroma_plugin_entry() {
  static const stroma::PluginEntry entry =
      stroma::makePluginEntry("ODESolver", "0.1.0", "Time integration", registerComponents);
  return &entry;
}
