// SPDX-License-Identifier: MIT
// The force of a linear spring and its derivatives, for sets of springs between the points of
// two states (the same state for springs inside one body). Knows nothing of components.
//
// For a spring from p1 to p2 with u = p2 - p1, l = |u|, e = u / l, rest length L, stiffness ks
// and damping kd, the force on p1 is (p2 receives the opposite)
//   f1 = ks (l - L) e + kd ((v2 - v1).e) e,        energy ks (l - L)^2 / 2.
// Its derivatives (Baraff and Witkin 1998, section 4; Nealen et al. 2006):
//   df1/dp2 = Ks = ks [ e e^T + (1 - L/l) (I - e e^T) ]    (exact elastic tangent, the second
//                                                           term being the geometric one)
//   df1/dv2 = Bs = kd e e^T
// with df1/dp1 = -Ks, df2/dp2 = -Ks, df2/dp1 = Ks (and the same pattern for Bs). The position
// derivative of the damping force, kd [ s (I - e e^T) + e (v2 - v1)^T (I - e e^T) ] / l with
// s = (v2 - v1).e, has a symmetric part that Ks keeps, as SOFA's springs do (their geometric
// term is (ks (l - L) + kd s) / l: measured with runSofa, 5e-7), and a non-symmetric part that
// is left out; both vanish at zero relative velocity, so the tangent is exact for a spring at
// rest or without damping. The velocities come with the positions (SpringStates), zero when
// not given.
// Under compression (l < L) Ks is indefinite: that is the exact tangent, not an approximation.
// A zero rest length gives the linear spring f1 = ks u, Ks = ks I, defined even at l = 0.
//
// N is the number of coordinates of a point: 3, or 2 and 1 for points in a plane or on a line
// (SOFA's Vec2d, Vec1d). On a line e = +-1 and Ks = ks: the geometric term vanishes.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "LinearSpring.h"
#include "core/Types.h"
#include "linalg/AssembledMatrix.h"

namespace stroma {

/// What one spring does at given positions and velocities.
template <int N>
struct SpringResponse {
  static_assert(N >= 1 && N <= 3, "A spring joins points of 1, 2 or 3 coordinates.");
  using Matrix = Eigen::Matrix<double, N, N>;
  Vec<N> force = Vec<N>::Zero();      ///< on the first point; the second gets -force
  Matrix stiffness = Matrix::Zero();  ///< Ks = df1/dp2
  Matrix damping = Matrix::Zero();    ///< Bs = df1/dv2
  double energy = 0;
};

/// Force, derivatives and energy of one spring. An elongation-only spring that is shorter than
/// its rest length, or a spring of non-zero rest length whose ends coincide (no direction), does
/// nothing.
template <int N>
SpringResponse<N> evaluateSpring(const LinearSpring& s, const Vec<N>& p1, const Vec<N>& p2,
                                 const Vec<N>& v1, const Vec<N>& v2);

/// The arrays of the two states a set of springs connects (the same arrays for springs inside
/// one state). Forces, increments and results are indexed by point.
template <int N>
struct SpringStates {
  const std::vector<Vec<N>>& x1;
  const std::vector<Vec<N>>& x2;
  /// Velocities of the two states, for the damping part of the tangent (null: zero).
  const std::vector<Vec<N>>* v1 = nullptr;
  const std::vector<Vec<N>>* v2 = nullptr;
};

/// f += spring forces at (x, v); returns the elastic energy.
template <int N>
double addSpringForces(const std::vector<LinearSpring>& springs, const SpringStates<N>& x,
                       const std::vector<Vec<N>>& v1, const std::vector<Vec<N>>& v2,
                       std::vector<Vec<N>>& f1, std::vector<Vec<N>>& f2);
/// df += kFactor K dx + bFactor B dx at positions x (and velocities, when x has them).
template <int N>
void addSpringDForces(const std::vector<LinearSpring>& springs, const SpringStates<N>& x,
                      const std::vector<Vec<N>>& dx1, const std::vector<Vec<N>>& dx2,
                      std::vector<Vec<N>>& df1, std::vector<Vec<N>>& df2, double kFactor,
                      double bFactor);
/// Adds kFactor K + bFactor B at positions x, the first state's rows from offset1 and the second
/// one's from offset2.
template <int N>
void addSpringMatrix(const std::vector<LinearSpring>& springs, const SpringStates<N>& x,
                     MatrixAccumulator& matrix, std::size_t offset1, std::size_t offset2,
                     double kFactor, double bFactor);
/// Elastic energy at positions x.
template <int N>
double springEnergy(const std::vector<LinearSpring>& springs, const SpringStates<N>& x);

// Definitions.

template <int N>
SpringResponse<N> evaluateSpring(const LinearSpring& s, const Vec<N>& p1, const Vec<N>& p2,
                                 const Vec<N>& v1, const Vec<N>& v2) {
  using Matrix = typename SpringResponse<N>::Matrix;
  SpringResponse<N> r;
  const Vec<N> u = p2 - p1;
  const double l = u.norm();
  if (s.elongationOnly && l < s.restLength) return r;
  const double tiny = 1e-14 * (1 + s.restLength);
  if (s.restLength == 0) {
    // Linear spring: f1 = ks u, defined everywhere.
    r.force = s.ks * u;
    r.stiffness = s.ks * Matrix::Identity();
    r.energy = 0.5 * s.ks * u.squaredNorm();
    if (l > tiny) {
      const Vec<N> e = u / l;
      const Matrix eeT = e * e.transpose();
      const double dampingForce = s.kd * (v2 - v1).dot(e);
      r.force += dampingForce * e;
      r.stiffness += (dampingForce / l) * (Matrix::Identity() - eeT);
      r.damping = s.kd * eeT;
    }
    return r;
  }
  if (l <= tiny) return r;  // no direction: the ends coincide
  const Vec<N> e = u / l;
  const Matrix eeT = e * e.transpose();
  const double stretch = l - s.restLength;
  const double intensity = s.ks * stretch + s.kd * (v2 - v1).dot(e);
  r.force = intensity * e;
  r.stiffness = s.ks * eeT + (intensity / l) * (Matrix::Identity() - eeT);
  r.damping = s.kd * eeT;
  r.energy = 0.5 * s.ks * stretch * stretch;
  return r;
}

namespace internal {
// Point i's velocity, zero without velocities.
template <int N>
Vec<N> velocityOf(const std::vector<Vec<N>>* v, std::uint32_t i) {
  return v && i < v->size() ? (*v)[i] : Vec<N>::Zero();
}
// Adds an N x N block at (row, col).
template <int N>
void addBlock(MatrixAccumulator& matrix, std::size_t row, std::size_t col,
              const Eigen::Matrix<double, N, N>& block) {
  for (int i = 0; i < N; ++i)
    for (int j = 0; j < N; ++j) matrix.add(row + i, col + j, block(i, j));
}
}  // namespace internal

template <int N>
double addSpringForces(const std::vector<LinearSpring>& springs, const SpringStates<N>& x,
                       const std::vector<Vec<N>>& v1, const std::vector<Vec<N>>& v2,
                       std::vector<Vec<N>>& f1, std::vector<Vec<N>>& f2) {
  const Vec<N> zero = Vec<N>::Zero();
  double energy = 0;
  for (const LinearSpring& s : springs) {
    const SpringResponse<N> r =
        evaluateSpring<N>(s, x.x1[s.m1], x.x2[s.m2], s.m1 < v1.size() ? v1[s.m1] : zero,
                          s.m2 < v2.size() ? v2[s.m2] : zero);
    f1[s.m1] += r.force;
    f2[s.m2] -= r.force;
    energy += r.energy;
  }
  return energy;
}

template <int N>
void addSpringDForces(const std::vector<LinearSpring>& springs, const SpringStates<N>& x,
                      const std::vector<Vec<N>>& dx1, const std::vector<Vec<N>>& dx2,
                      std::vector<Vec<N>>& df1, std::vector<Vec<N>>& df2, double kFactor,
                      double bFactor) {
  for (const LinearSpring& s : springs) {
    const SpringResponse<N> r =
        evaluateSpring<N>(s, x.x1[s.m1], x.x2[s.m2], internal::velocityOf<N>(x.v1, s.m1),
                          internal::velocityOf<N>(x.v2, s.m2));
    const Vec<N> d = dx2[s.m2] - dx1[s.m1];
    const Vec<N> df = kFactor * (r.stiffness * d) + bFactor * (r.damping * d);
    df1[s.m1] += df;
    df2[s.m2] -= df;
  }
}

template <int N>
void addSpringMatrix(const std::vector<LinearSpring>& springs, const SpringStates<N>& x,
                     MatrixAccumulator& matrix, std::size_t offset1, std::size_t offset2,
                     double kFactor, double bFactor) {
  for (const LinearSpring& s : springs) {
    const SpringResponse<N> r =
        evaluateSpring<N>(s, x.x1[s.m1], x.x2[s.m2], internal::velocityOf<N>(x.v1, s.m1),
                          internal::velocityOf<N>(x.v2, s.m2));
    const typename SpringResponse<N>::Matrix K = kFactor * r.stiffness + bFactor * r.damping;
    const std::size_t row1 = offset1 + N * std::size_t{s.m1};
    const std::size_t row2 = offset2 + N * std::size_t{s.m2};
    internal::addBlock<N>(matrix, row1, row1, -K);
    internal::addBlock<N>(matrix, row1, row2, K);
    internal::addBlock<N>(matrix, row2, row1, K);
    internal::addBlock<N>(matrix, row2, row2, -K);
  }
}

template <int N>
double springEnergy(const std::vector<LinearSpring>& springs, const SpringStates<N>& x) {
  const Vec<N> zero = Vec<N>::Zero();
  double energy = 0;
  for (const LinearSpring& s : springs)
    energy += evaluateSpring<N>(s, x.x1[s.m1], x.x2[s.m2], zero, zero).energy;
  return energy;
}

}  // namespace stroma
