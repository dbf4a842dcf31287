// SPDX-License-Identifier: MIT
// Helpers for the tests of mechanical components (masses, constraints, loads, springs): load a
// scene from a string, reach its components and Data, and check a node's force fields against
// finite differences through MechanicalOperations, the interface the solvers use.
//
// The consistency checks work on the whole system of a node (every force field of its subtree),
// so a test builds a scene with just the component under test.
#pragma once

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <random>
#include <sstream>
#include <string>

#include "core/PathResolver.h"
#include "core/Runtime.h"
#include "core/StateTypes.h"
#include "linalg/AssembledMatrix.h"
#include "plugins/TestPlugin/TestSupport.h"
#include "simulation/MechanicalOperations.h"
#include "simulation/MechanicalState.h"
#include "simulation/Scene.h"

namespace stroma::test {

/// A scene loaded from XML, with access to its objects and Data by path.
class SceneHolder {
 public:
  SceneHolder() : m_scene(m_runtime) {}

  /// Loads `xml`; the test fails with the log on an error, or on a warning unless allowed.
  bool load(const std::string& xml, bool allowWarnings = false) {
    const bool ok = m_scene.loadString(xml);
    EXPECT_TRUE(ok) << describe(m_scene.log());
    if (!allowWarnings) expectNoWarning();
    return ok;
  }
  void expectNoWarning() {
    for (const Message& m : m_scene.log().messages())
      EXPECT_NE(m.level, MessageLevel::warning) << formatForConsole(m);
  }
  /// Loads `xml`, expecting it to fail with an error containing every one of `needles`.
  Message loadFailing(const std::string& xml, std::initializer_list<std::string_view> needles) {
    EXPECT_FALSE(m_scene.loadString(xml)) << "expected the load to fail";
    for (const Message& m : errors(m_scene.log())) {
      bool all = true;
      for (std::string_view n : needles) all &= m.text.find(n) != std::string::npos;
      if (all) return m;
    }
    std::string wanted;
    for (std::string_view n : needles) wanted += " '" + std::string(n) + "'";
    ADD_FAILURE() << "no error containing" << wanted << " in:\n" << describe(m_scene.log());
    return {};
  }

  Scene& scene() { return m_scene; }
  Node& root() { return m_scene.root(); }

  template <class T = Base>
  T* get(const std::string& path) {
    std::string why;
    Base* found = resolveObjectPath(m_scene.root(), path, why);
    EXPECT_NE(found, nullptr) << path << ": " << why;
    T* typed = dynamic_cast<T*>(found);
    EXPECT_NE(typed, nullptr) << path << " is not of the expected type";
    return typed;
  }
  BaseData* data(const std::string& path) {
    std::string why;
    BaseData* found = resolveDataPath(m_scene.root(), path, why);
    EXPECT_NE(found, nullptr) << path << ": " << why;
    return found;
  }
  std::string text(const std::string& path) {
    BaseData* d = data(path);
    return d ? d->valueText() : std::string();
  }
  void set(const std::string& path, const std::string& value) {
    std::string error;
    BaseData* d = data(path);
    ASSERT_TRUE(d && d->read(value, error)) << path << ": " << error;
  }

  /// Steps; the test fails on an error or a warning.
  bool step(int count = 1) {
    for (int i = 0; i < count; ++i)
      if (!m_scene.step()) {
        ADD_FAILURE() << describe(m_scene.log());
        return false;
      }
    expectNoWarning();
    return true;
  }

 private:
  Runtime m_runtime;
  Scene m_scene;
};

/// A list of numbers parsed from a Data's text.
inline std::vector<double> numbers(const std::string& text) {
  std::vector<double> values;
  std::istringstream in(text);
  for (double v; in >> v;) values.push_back(v);
  return values;
}

/// The points' positions of a Vec3d state as one vector (3n).
inline Eigen::VectorXd positionsOf(MechanicalState<Vec3Types>& state, VecId v = VecId::position()) {
  const auto& x = state.readCoord(v);
  Eigen::VectorXd out(3 * static_cast<Eigen::Index>(x.size()));
  for (std::size_t i = 0; i < x.size(); ++i)
    out.segment<3>(3 * static_cast<Eigen::Index>(i)) = x[i];
  return out;
}

/// Consistency of the force fields of `node`'s system with finite differences, at the current
/// positions of its Vec3d states (velocities as they are). Central differences of step h.
class ForceFieldChecker {
 public:
  explicit ForceFieldChecker(Scene& scene, Node& node)
      : m_scene(scene), m_mop(node, scene.timing()) {
    for (BaseMechanicalState* s : m_mop.independentStates()) {
      auto* typed = dynamic_cast<MechanicalState<Vec3Types>*>(s);
      EXPECT_NE(typed, nullptr) << "the checker handles Vec3d states only";
      m_states.push_back(typed);
    }
  }

  MechanicalOperations& mop() { return m_mop; }
  std::size_t size() const { return m_mop.systemSize(); }

  /// f(x) as a global vector.
  Eigen::VectorXd force() {
    MechanicalParams mp;
    m_mop.computeForce(mp, VecId::force());
    Eigen::VectorXd f;
    m_mop.gather(VecId::force(), f);
    return f;
  }
  double energy() { return m_mop.potentialEnergy(MechanicalParams{}); }

  /// K = df/dx by central differences.
  Eigen::MatrixXd finiteDifferenceStiffness(double h = 1e-6) {
    const auto n = static_cast<Eigen::Index>(size());
    Eigen::MatrixXd K(n, n);
    for (Eigen::Index j = 0; j < n; ++j) {
      shift(j, h);
      const Eigen::VectorXd fp = force();
      shift(j, -2 * h);
      const Eigen::VectorXd fm = force();
      shift(j, h);
      K.col(j) = (fp - fm) / (2 * h);
    }
    return K;
  }
  /// -dE/dx by central differences.
  Eigen::VectorXd finiteDifferenceForce(double h = 1e-6) {
    const auto n = static_cast<Eigen::Index>(size());
    Eigen::VectorXd f(n);
    for (Eigen::Index j = 0; j < n; ++j) {
      shift(j, h);
      const double ep = energy();
      shift(j, -2 * h);
      const double em = energy();
      shift(j, h);
      f[j] = -(ep - em) / (2 * h);
    }
    return f;
  }
  /// The matrix-free K (column by column through computeMBKdx with kFactor 1, bFactor b).
  Eigen::MatrixXd matrixFreeStiffness(double b = 0) {
    const auto n = static_cast<Eigen::Index>(size());
    Eigen::MatrixXd K(n, n);
    const VecId dx = m_mop.allocDeriv(), out = m_mop.allocDeriv();
    MechanicalParams mp;
    mp.kFactor = 1;
    mp.bFactor = b;
    for (Eigen::Index j = 0; j < n; ++j) {
      Eigen::VectorXd e = Eigen::VectorXd::Unit(n, j);
      m_mop.scatter(e, dx);
      m_mop.computeMBKdx(mp, out, dx);
      Eigen::VectorXd column;
      m_mop.gather(out, column);
      K.col(j) = column;
    }
    m_mop.freeVec(dx);
    m_mop.freeVec(out);
    return K;
  }
  /// The assembled m M + b B + k K (rows of fixed degrees of freedom replaced by the identity).
  Eigen::MatrixXd assembled(double m, double b, double k) {
    MechanicalParams mp;
    mp.mFactor = m;
    mp.bFactor = b;
    mp.kFactor = k;
    AssembledMatrix A;
    m_mop.assemble(mp, A);
    return Eigen::MatrixXd(A.matrix());
  }
  /// M applied column by column (computeMBKdx with mFactor 1).
  Eigen::MatrixXd matrixFreeMass() {
    const auto n = static_cast<Eigen::Index>(size());
    Eigen::MatrixXd M(n, n);
    const VecId dx = m_mop.allocDeriv(), out = m_mop.allocDeriv();
    MechanicalParams mp;
    mp.mFactor = 1;
    mp.kFactor = 0;
    for (Eigen::Index j = 0; j < n; ++j) {
      m_mop.scatter(Eigen::VectorXd::Unit(n, j), dx);
      m_mop.computeMBKdx(mp, out, dx);
      Eigen::VectorXd column;
      m_mop.gather(out, column);
      M.col(j) = column;
    }
    m_mop.freeVec(dx);
    m_mop.freeVec(out);
    return M;
  }

  /// Moves global coordinate j of the positions by h.
  void shift(Eigen::Index j, double h) {
    for (auto* s : m_states) {
      const auto n = static_cast<Eigen::Index>(3 * s->size());
      if (j < n) {
        s->writeCoord(VecId::position())[static_cast<std::size_t>(j / 3)][j % 3] += h;
        return;
      }
      j -= n;
    }
  }

 private:
  Scene& m_scene;
  MechanicalOperations m_mop;
  std::vector<MechanicalState<Vec3Types>*> m_states;
};

/// Largest absolute entry, at least `floor`, for relative comparisons.
inline double scaleOf(const Eigen::MatrixXd& m, double floor = 1.0) {
  return std::max(floor, m.cwiseAbs().maxCoeff());
}

}  // namespace stroma::test
