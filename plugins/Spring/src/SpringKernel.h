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
// derivative of the damping force is left out (it is not symmetric); it vanishes at rest.
// Under compression (l < L) Ks is indefinite: that is the exact tangent, not an approximation.
// A zero rest length gives the linear spring f1 = ks u, Ks = ks I, defined even at l = 0.
#pragma once

#include <vector>

#include "LinearSpring.h"
#include "core/Types.h"
#include "linalg/AssembledMatrix.h"

namespace stroma {

/// What one spring does at given positions and velocities.
struct SpringResponse {
  Vec3d force = Vec3d::Zero();      ///< on the first point; the second gets -force
  Mat3d stiffness = Mat3d::Zero();  ///< Ks = df1/dp2
  Mat3d damping = Mat3d::Zero();    ///< Bs = df1/dv2
  double energy = 0;
};

/// Force, derivatives and energy of one spring. An elongation-only spring that is shorter than
/// its rest length, or a spring of non-zero rest length whose ends coincide (no direction), does
/// nothing.
SpringResponse evaluateSpring(const LinearSpring& s, const Vec3d& p1, const Vec3d& p2,
                              const Vec3d& v1, const Vec3d& v2);

/// The arrays of the two states a set of springs connects (the same arrays for springs inside
/// one state). Forces, increments and results are indexed by point.
struct SpringStates {
  const std::vector<Vec3d>& x1;
  const std::vector<Vec3d>& x2;
};

/// f += spring forces at (x, v); returns the elastic energy.
double addSpringForces(const std::vector<LinearSpring>& springs, const SpringStates& x,
                       const std::vector<Vec3d>& v1, const std::vector<Vec3d>& v2,
                       std::vector<Vec3d>& f1, std::vector<Vec3d>& f2);
/// df += kFactor K dx + bFactor B dx at positions x.
void addSpringDForces(const std::vector<LinearSpring>& springs, const SpringStates& x,
                      const std::vector<Vec3d>& dx1, const std::vector<Vec3d>& dx2,
                      std::vector<Vec3d>& df1, std::vector<Vec3d>& df2, double kFactor,
                      double bFactor);
/// Adds kFactor K + bFactor B at positions x, the first state's rows from offset1 and the second
/// one's from offset2.
void addSpringMatrix(const std::vector<LinearSpring>& springs, const SpringStates& x,
                     MatrixAccumulator& matrix, std::size_t offset1, std::size_t offset2,
                     double kFactor, double bFactor);
/// Elastic energy at positions x.
double springEnergy(const std::vector<LinearSpring>& springs, const SpringStates& x);

}  // namespace stroma
