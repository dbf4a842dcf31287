// SPDX-License-Identifier: MIT
// Cantilever scenes for the multigrid tests: a RegularGridTopology beam of hexahedra clamped at
// x = 0 under gravity, with the solvers given as XML; the assembled system and its solutions by
// every linear solver of the body.
#pragma once

#include <gtest/gtest.h>

#include <Eigen/Sparse>
#include <memory>
#include <string>
#include <vector>

#include "core/Message.h"
#include "core/Runtime.h"
#include "core/Types.h"
#include "simulation/MechanicalOperations.h"
#include "simulation/Scene.h"
#include "simulation/Solvers.h"

namespace stroma::test {

/// A beam of cells.x x cells.y x cells.z hexahedra over [0, length] x [0, 1] x [0, 1] (node
/// "Body", topology "grid", state "dofs"), clamped at x = 0, E and nu given, small-strain
/// (linear) or corotational elements, total mass `mass`, gravity -g along y.
inline std::string cantileverScene(const Vec3i& cells, double length, double youngModulus,
                                   double poissonRatio, const std::string& solvers,
                                   const std::string& method = "small", double g = 1e6 * 9.81,
                                   double mass = 1.0, double dt = 0.01) {
  auto n = [&](int a) { return std::to_string(cells[a] + 1); };
  return "<Node name=\"root\" dt=\"" + std::to_string(dt) + "\" gravity=\"0 " + std::to_string(-g) +
         " 0\">\n<Node name=\"Body\">\n" + solvers + "\n" +
         "<RegularGridTopology name=\"grid\" n=\"" + n(0) + " " + n(1) + " " + n(2) +
         "\" min=\"0 0 0\" max=\"" + std::to_string(length) + " 1 1\"/>\n" +
         "<MechanicalObject name=\"dofs\" position=\"@grid.position\"/>\n" +
         "<UniformMass name=\"mass\" totalMass=\"" + std::to_string(mass) + "\"/>\n" +
         "<BoxROI name=\"clampedEnd\" box=\"-0.001 -1 -1  0.001 2 2\" "
         "position=\"@dofs.rest_position\"/>\n" +
         "<FixedProjectiveConstraint name=\"clamp\" indices=\"@clampedEnd.indices\"/>\n" +
         "<HexahedronFEMForceField name=\"FEM\" method=\"" + method + "\" youngModulus=\"" +
         std::to_string(youngModulus) + "\" poissonRatio=\"" + std::to_string(poissonRatio) +
         "\"/>\n</Node>\n</Node>\n";
}

/// A loaded scene and the Runtime it was made with (destroyed after it).
struct LoadedScene {
  explicit LoadedScene(const std::string& xml) { loaded = scene->loadString(xml); }
  ~LoadedScene() { scene.reset(); }
  std::string log() const {
    std::string text;
    for (const Message& m : scene->log().messages()) text += formatForConsole(m) + '\n';
    return text;
  }
  /// Whether an error or warning with `field` and `words` in its text was reported.
  bool reported(MessageLevel level, const std::string& field, const std::string& words) const {
    for (const Message& m : scene->log().messages())
      if (m.level == level && m.field == field && m.text.find(words) != std::string::npos)
        return true;
    return false;
  }
  Node& body() { return *scene->root().findChild("Body"); }

  std::unique_ptr<Runtime> runtime = std::make_unique<Runtime>();
  std::unique_ptr<Scene> scene = std::make_unique<Scene>(*runtime);
  bool loaded = false;
};

/// The static problem K u = f of the loaded beam (f: gravity, projected by the clamp), solved by
/// each linear solver of the body in scene order; other factors give (m M + k K) u = f.
inline std::vector<Eigen::VectorXd> solveStatic(LoadedScene& s,
                                                std::vector<LinearSolveReport>* reports = nullptr,
                                                double mFactor = 0, double kFactor = -1) {
  Node& body = s.body();
  MechanicalOperations mop(body, s.scene->timing());
  const VecId f = mop.allocDeriv(), u = mop.allocDeriv();
  mop.computeForce(MechanicalParams{}, f);
  mop.projectResponse(f);
  MechanicalParams mp;  // by default A = -df/dx = K, as StaticSolver
  mp.mFactor = mFactor;
  mp.kFactor = kFactor;
  std::vector<Eigen::VectorXd> solutions;
  for (LinearSolver* solver : body.getAll<LinearSolver>()) {
    mop.vOp(u, VecId::null(), VecId::null(), 0.0);
    const LinearSolveReport report = solver->solve(mop, mp, u, f);
    if (reports) reports->push_back(report);
    Eigen::VectorXd solution;
    mop.gather(u, solution);
    solutions.push_back(solution);
  }
  return solutions;
}

/// ||a - reference|| / ||reference||.
inline double relativeError(const Eigen::VectorXd& a, const Eigen::VectorXd& reference) {
  return (a - reference).norm() / reference.norm();
}

}  // namespace stroma::test
