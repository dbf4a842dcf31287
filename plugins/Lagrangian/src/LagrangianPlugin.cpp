// SPDX-License-Identifier: MIT
#include "BilateralLagrangianConstraint.h"
#include "FixedLagrangianConstraint.h"
#include "FreeMotionAnimationLoop.h"
#include "GenericConstraintSolver.h"
#include "LCPConstraintSolver.h"
#include "LinearSolverConstraintCorrection.h"
#include "MouseSettings.h"
#include "PrecomputedConstraintCorrection.h"
#include "SlidingLagrangianConstraint.h"
#include "UncoupledConstraintCorrection.h"
#include "UnilateralLagrangianConstraint.h"
#include "core/Plugin.h"

namespace {

void registerComponents(stroma::PluginRegistry& registry) {
  using namespace stroma;
  registry.add("FreeMotionAnimationLoop",
               "Free motion, collision, then Lagrangian constraints solved through compliances")
      .with<FreeMotionAnimationLoop>()
      .sofaOptions({"solveVelocityConstraintFirst", "threadSafeVisitor",
                    "parallelCollisionDetectionAndFreeMotion", "parallelODESolving",
                    "computeBoundingBox"});
  registry.add("GenericConstraintSolver",
               "Constraint problem by projected Gauss-Seidel, friction cones included")
      .with<GenericConstraintSolver>()
      .sofaOptions({"scaleTolerance", "allVerified", "computeConstraintForces", "multithreading",
                    "useSVDForRegularization"})
      .alias("BlockGaussSeidelConstraintSolver")
      .alias("ProjectedGaussSeidelConstraintSolver")
      .alias("UnbuiltGaussSeidelConstraintSolver");
  registry.add("NNCGConstraintSolver",
               "Constraint problem by the nonsmooth nonlinear conjugate gradient over "
               "Gauss-Seidel sweeps")
      .with<NNCGConstraintSolver>()
      .sofaOptions({"scaleTolerance", "allVerified", "computeConstraintForces", "multithreading",
                    "useSVDForRegularization"});
  registry.add("LCPConstraintSolver", "Contact problem with one friction coefficient")
      .with<LCPConstraintSolver>()
      .sofaOptions({"build_lcp", "displayTime", "initial_guess", "multi_grid", "multi_grid_levels"});
  registry.add("UncoupledConstraintCorrection",
               "Compliance of each degree of freedom alone (1 / mass)")
      .with<UncoupledConstraintCorrection>()
      .sofaOptions({"defaultCompliance", "useOdeSolverIntegrationFactors"});
  registry.add("LinearSolverConstraintCorrection",
               "Compliance through the solver's own system and linear solver")
      .with<LinearSolverConstraintCorrection>()
      .sofaOptions({"ODESolver", "wire_optimization", "solverName"})
      .alias("GenericConstraintCorrection");
  registry.add("PrecomputedConstraintCorrection",
               "Compliance of the solver's system computed once (cached on disk), turned with "
               "the body; a precomputed model's own basis")
      .with<PrecomputedConstraintCorrection>()
      .sofaOptions({"restDeformations", "debugViewFrameScale"});
  registry.add("BilateralLagrangianConstraint", "Points or frames held together by multipliers")
      .with<BilateralLagrangianConstraint<Vec3Types>>("Vec3d")
      .with<BilateralLagrangianConstraint<Rigid3Types>>("Rigid3d")
      .sofaOptions({"numericalTolerance", "topology1", "topology2"})
      .alias("BilateralInteractionConstraint");
  registry.add("FixedLagrangianConstraint", "Points or frames held where they start by multipliers")
      .with<FixedLagrangianConstraint<Vec3Types>>("Vec3d")
      .with<FixedLagrangianConstraint<Rigid3Types>>("Rigid3d");
  registry.add("SlidingLagrangianConstraint", "A point sliding along a segment of two points")
      .with<SlidingLagrangianConstraint>("Vec3d")
      .alias("SlidingConstraint");
  registry.add("UnilateralLagrangianConstraint",
               "Points kept beyond others along a direction, with Coulomb friction")
      .with<UnilateralLagrangianConstraint>("Vec3d")
      .alias("UnilateralInteractionConstraint");
  registry.add("AttachBodyButtonSetting", "Viewer's mouse: drag a picked body by a spring")
      .with<AttachBodyButtonSetting>();
  registry.add("ConstraintAttachButtonSetting",
               "Viewer's mouse: drag a picked body by a bilateral constraint")
      .with<ConstraintAttachButtonSetting>();
}

}  // namespace

extern "C" STROMA_PLUGIN_EXPORT const stroma::PluginEntry* stroma_plugin_entry() {
  static const stroma::PluginEntry entry = stroma::makePluginEntry(
      "Lagrangian", "0.1.0", "Lagrangian constraints: free motion, compliances, multipliers",
      registerComponents);
  return &entry;
}
