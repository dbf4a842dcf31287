// SPDX-License-Identifier: MIT
// Checks every mapping passes, whatever its kinds of degrees of freedom, at the input's current
// positions:
//   adjoint      <J x, y> = <x, J^T y> for random x, y (applyJ and applyJT are transposes)
//   derivative   applyJ x = (apply(x_in + h x) - apply(x_in - h x)) / 2h (central difference;
//                for rigid frames "+" turns by a rotation vector and "-" is the rotation vector
//                between two orientations)
//   jacobian     jacobian() column c = applyJ e_c, and its size is (out x in) matrixSize
// plus the scene helpers the mapping tests share.
#pragma once

#include <gtest/gtest.h>

#include <Eigen/Sparse>
#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <type_traits>
#include <vector>

#include "core/PathResolver.h"
#include "core/Runtime.h"
#include "core/StateTypes.h"
#include "linalg/AssembledMatrix.h"
#include "simulation/Mapping.h"
#include "simulation/MechanicalOperations.h"
#include "simulation/Scene.h"

namespace stroma::test {

// --- Coordinates and derivatives as flat vectors ----------------------------------------------

inline void append(Eigen::VectorXd& v, Eigen::Index& k, const Vec3d& d) {
  v.segment<3>(k) = d;
  k += 3;
}
inline void append(Eigen::VectorXd& v, Eigen::Index& k, const RigidDeriv3& d) {
  v.segment<3>(k) = d.linear;
  v.segment<3>(k + 3) = d.angular;
  k += 6;
}
template <class Deriv>
inline constexpr int kDerivSize = std::is_same_v<Deriv, Vec3d> ? 3 : 6;
template <class Deriv>
Eigen::VectorXd flatten(const std::vector<Deriv>& d) {
  Eigen::VectorXd v(static_cast<Eigen::Index>(d.size()) * kDerivSize<Deriv>);
  Eigen::Index k = 0;
  for (const Deriv& x : d) append(v, k, x);
  return v;
}

inline void unflatten(const Eigen::VectorXd& v, Eigen::Index& k, Vec3d& d) {
  d = v.segment<3>(k);
  k += 3;
}
inline void unflatten(const Eigen::VectorXd& v, Eigen::Index& k, RigidDeriv3& d) {
  d.linear = v.segment<3>(k);
  d.angular = v.segment<3>(k + 3);
  k += 6;
}
template <class Deriv>
std::vector<Deriv> unflatten(const Eigen::VectorXd& v, std::size_t n) {
  std::vector<Deriv> d(n);
  Eigen::Index k = 0;
  for (Deriv& x : d) unflatten(v, k, x);
  return d;
}

/// x + h d (a rigid frame turns by the rotation vector h d.angular, in world coordinates).
inline Vec3d moved(const Vec3d& x, const Vec3d& d, double h) { return x + h * d; }
inline RigidCoord3 moved(const RigidCoord3& x, const RigidDeriv3& d, double h) {
  RigidCoord3 r = x;
  r.center += h * d.linear;
  const Vec3d w = h * d.angular;
  if (w.norm() > 0)
    r.orientation = Quat(Eigen::AngleAxisd(w.norm(), w.normalized())) * x.orientation;
  return r;
}
/// The derivative that moves b to a (the inverse of moved with h = 1).
inline Vec3d difference(const Vec3d& a, const Vec3d& b) { return a - b; }
inline RigidDeriv3 difference(const RigidCoord3& a, const RigidCoord3& b) {
  RigidDeriv3 d;
  d.linear = a.center - b.center;
  const Eigen::AngleAxisd turn(a.orientation * b.orientation.conjugate());
  d.angular = turn.angle() * turn.axis();
  return d;
}

// --- The consistency checks --------------------------------------------------------------------

struct MappingCheckReport {
  double adjoint = 0;     ///< max |<Jx,y> - <x,J^T y>| / (|Jx| |y| + |x| |J^T y|)
  double derivative = 0;  ///< max |J x - FD| / |J x|
  double jacobian = 0;    ///< max |jacobian() - applyJ columns| / max |J|
  std::string describe() const {
    return "adjoint " + std::to_string(adjoint) + ", derivative " + std::to_string(derivative) +
           ", jacobian " + std::to_string(jacobian);
  }
};

/// Measures the three checks for `samples` random vectors. `length` scales the translations of
/// the random directions (rotations are in radians); h = fdStep.
template <class In, class Out>
MappingCheckReport measureMapping(Mapping<In, Out>& mapping, double length = 1.0, int samples = 4,
                                  double fdStep = 1e-6, unsigned seed = 7) {
  using InDeriv = typename In::Deriv;
  using OutDeriv = typename Out::Deriv;
  MappingCheckReport r;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  const auto xin = mapping.input()->readCoord(VecId::position());
  const std::size_t nIn = xin.size();
  std::vector<typename Out::Coord> xout;
  mapping.apply(xout, xin);
  const std::size_t nOut = xout.size();
  const auto inSize = static_cast<Eigen::Index>(nIn * In::derivSize);
  const auto outSize = static_cast<Eigen::Index>(nOut * Out::derivSize);
  auto random = [&](Eigen::Index n, int dim) {
    Eigen::VectorXd v(n);
    for (Eigen::Index i = 0; i < n; ++i) v[i] = uniform(rng) * ((i % dim) < 3 ? length : 1.0);
    return v;
  };

  for (int s = 0; s < samples; ++s) {
    // Adjoint.
    const Eigen::VectorXd x = random(inSize, In::derivSize);
    const Eigen::VectorXd y = random(outSize, Out::derivSize);
    std::vector<OutDeriv> Jx;
    mapping.applyJ(Jx, unflatten<InDeriv>(x, nIn));
    std::vector<InDeriv> JTy(nIn, In::zeroDeriv());
    mapping.applyJT(JTy, unflatten<OutDeriv>(y, nOut));
    const Eigen::VectorXd jx = flatten(Jx), jty = flatten(JTy);
    r.adjoint = std::max(r.adjoint, std::abs(jx.dot(y) - x.dot(jty)) /
                                        (jx.norm() * y.norm() + x.norm() * jty.norm()));

    // Derivative.
    std::vector<typename In::Coord> plus(nIn), minus(nIn);
    const auto dx = unflatten<InDeriv>(x, nIn);
    for (std::size_t i = 0; i < nIn; ++i) {
      plus[i] = moved(xin[i], dx[i], fdStep);
      minus[i] = moved(xin[i], dx[i], -fdStep);
    }
    std::vector<typename Out::Coord> outPlus, outMinus;
    mapping.apply(outPlus, plus);
    mapping.apply(outMinus, minus);
    std::vector<OutDeriv> fd(nOut);
    Eigen::VectorXd fdFlat(outSize);
    Eigen::Index k = 0;
    for (std::size_t i = 0; i < nOut; ++i) append(fdFlat, k, difference(outPlus[i], outMinus[i]));
    fdFlat /= 2 * fdStep;
    r.derivative = std::max(r.derivative, (jx - fdFlat).norm() / std::max(jx.norm(), 1e-300));
  }

  // Jacobian, column by column.
  const Eigen::SparseMatrix<double>& J = mapping.jacobian();
  EXPECT_EQ(J.rows(), outSize);
  EXPECT_EQ(J.cols(), inSize);
  if (J.rows() != outSize || J.cols() != inSize) return r;
  const Eigen::MatrixXd dense = J;
  const double scale = std::max(dense.cwiseAbs().maxCoeff(), 1e-300);
  for (Eigen::Index c = 0; c < inSize; ++c) {
    const Eigen::VectorXd e = Eigen::VectorXd::Unit(inSize, c);
    std::vector<OutDeriv> Je;
    mapping.applyJ(Je, unflatten<InDeriv>(e, nIn));
    r.jacobian = std::max(r.jacobian, (flatten(Je) - dense.col(c)).cwiseAbs().maxCoeff() / scale);
  }
  return r;
}

/// Expects the three checks to hold: adjoint and jacobian to round-off, the derivative to the
/// accuracy of a central difference with h = 1e-6 (truncation h^2, round-off eps / h).
template <class In, class Out>
void expectConsistentMapping(Mapping<In, Out>& mapping, double length = 1.0) {
  const MappingCheckReport r = measureMapping(mapping, length);
  EXPECT_LT(r.adjoint, 1e-14) << r.describe();
  EXPECT_LT(r.derivative, 1e-8) << r.describe();
  EXPECT_LT(r.jacobian, 1e-14) << r.describe();
}

// --- The assembled system of a scene with mapped states ----------------------------------------

struct SystemCheckReport {
  double assembled = 0;   ///< max |A u - matrix-free u| / |A u|, A = m M + k K (J^T K J)
  double stiffness = -1;  ///< max |K u - FD of the mapped forces| / |K u|; -1: not run
};

/// On the MechanicalOperations of the scene's root: the assembled m M + k K (mapped parts as
/// J^T K J and J^T M J) against the matrix-free product, on random u; and, when
/// `finiteDifferences`, the matrix-free K u against the central difference of computeForce
/// (mapped positions propagated), which holds when the mapping is linear or the mapped forces
/// vanish (no geometric stiffness then).
inline SystemCheckReport measureSystem(Scene& scene, double mFactor, double kFactor,
                                       bool finiteDifferences, unsigned seed = 11) {
  SystemCheckReport r;
  MechanicalOperations mop(scene.root(), scene.timing());
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  const auto n = static_cast<Eigen::Index>(mop.systemSize());
  auto random = [&] {
    Eigen::VectorXd v(n);
    for (Eigen::Index i = 0; i < n; ++i) v[i] = uniform(rng);
    return v;
  };
  const VecId x = VecId::position(), v = VecId::velocity();
  const VecId f = mop.allocDeriv(), u = mop.allocDeriv(), out = mop.allocDeriv();
  const VecId x0 = mop.allocCoord();
  mop.vOp(x0, x);
  mop.propagate(x, v);
  mop.computeForce(MechanicalParams{}, f);  // linearization point

  MechanicalParams mp;
  mp.mFactor = mFactor;
  mp.kFactor = kFactor;
  AssembledMatrix A;
  mop.assemble(mp, A);
  for (int s = 0; s < 4; ++s) {
    const Eigen::VectorXd w = random();
    mop.scatter(w, u);
    mop.projectResponse(u);
    Eigen::VectorXd pw;
    mop.gather(u, pw);
    mop.computeMBKdx(mp, out, u);
    mop.projectResponse(out);
    Eigen::VectorXd aw;
    mop.gather(out, aw);
    aw += w - pw;  // assemble() puts the identity at fixed rows
    const Eigen::VectorXd assembled = A.matrix() * w;
    r.assembled = std::max(r.assembled, (assembled - aw).norm() / assembled.norm());
  }
  if (!finiteDifferences) return r;

  r.stiffness = 0;
  const double h = 1e-6;
  MechanicalParams stiffness;
  stiffness.kFactor = 1;
  for (int s = 0; s < 4; ++s) {
    const Eigen::VectorXd w = random();
    mop.scatter(w, u);
    mop.vOp(x, x0);
    mop.propagate(x, v);
    mop.computeForce(MechanicalParams{}, f);
    mop.computeMBKdx(stiffness, out, u);
    Eigen::VectorXd Ku, fPlus, fMinus;
    mop.gather(out, Ku);
    mop.vOp(x, x0, u, h);
    mop.propagate(x, v);
    mop.computeForce(MechanicalParams{}, f);
    mop.gather(f, fPlus);
    mop.vOp(x, x0, u, -h);
    mop.propagate(x, v);
    mop.computeForce(MechanicalParams{}, f);
    mop.gather(f, fMinus);
    const Eigen::VectorXd fd = (fPlus - fMinus) / (2 * h);
    r.stiffness = std::max(r.stiffness, (Ku - fd).norm() / Ku.norm());
  }
  mop.vOp(x, x0);
  mop.propagate(x, v);
  return r;
}

// --- Scenes ------------------------------------------------------------------------------------

/// The first object of type T in the scene (depth first), or nullptr.
template <class T>
T* findInScene(const Node& node) {
  if (T* t = node.get<T>()) return t;
  for (const auto& child : node.children())
    if (T* t = findInScene<T>(*child)) return t;
  return nullptr;
}

/// Every warning and error of the log, one a line.
inline std::string problems(const MessageLog& log) {
  std::string text;
  for (const Message& m : log.messages())
    if (m.level == MessageLevel::warning || m.level == MessageLevel::error)
      text += formatForConsole(m) + '\n';
  return text;
}

/// Positions of the state at `path` ("/root/Body/dofs"), flattened.
inline std::vector<double> positionsAt(const Scene& scene, const std::string& path) {
  std::string why;
  const Base* object = resolveObjectPath(scene.root(), "@" + path, why);
  const auto* state = dynamic_cast<const BaseState*>(object);
  EXPECT_NE(state, nullptr) << path << ": " << why;
  std::vector<double> x;
  if (state) state->copyPositions(x);
  return x;
}

}  // namespace stroma::test
