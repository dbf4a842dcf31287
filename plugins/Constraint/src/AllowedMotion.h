// SPDX-License-Identifier: MIT
// The motions a constrained point may take, as an orthogonal projector: the kernel of the
// projective constraints that keep points on a plane, on a line or at a point
// (PlaneProjectiveConstraint, LineProjectiveConstraint, PointProjectiveConstraint), let them
// move along one direction only (DirectionProjectiveConstraint) or zero one direction of their
// displacement (FixedPlaneProjectiveConstraint).
//
// P is the 3x3 orthogonal projector on the allowed displacements: symmetric and idempotent
// (P P = P), so that projecting twice changes nothing and P v is the allowed vector nearest to v.
//   plane with unit normal n:      P = I - n n^T   (moves in the plane)
//   line with unit direction d:    P = d d^T       (moves along the line)
//   point:                         P = 0           (does not move)
// A deriv (force, increment, velocity) becomes P v; a position becomes o + P (x - o), its
// orthogonal projection on the affine set through o.
#pragma once

#include <array>
#include <cmath>
#include <vector>

#include "core/Types.h"

namespace stroma::constraint {

struct AllowedMotion {
  Eigen::Matrix3d P = Eigen::Matrix3d::Identity();

  /// Moves in the plane of unit normal n.
  static AllowedMotion inPlane(const Vec3d& n) {
    return {Eigen::Matrix3d::Identity() - n * n.transpose()};
  }
  /// Moves along the unit direction d.
  static AllowedMotion alongLine(const Vec3d& d) { return {d * d.transpose()}; }
  /// Does not move.
  static AllowedMotion none() { return {Eigen::Matrix3d::Zero()}; }

  Vec3d project(const Vec3d& v) const { return P * v; }
  /// The orthogonal projection of x on the allowed set through `origin`.
  Vec3d projectPosition(const Vec3d& x, const Vec3d& origin) const {
    return origin + P * (x - origin);
  }

  /// When P is diagonal (the constrained directions are coordinate axes), the axes it zeroes:
  /// an assembled matrix holds the projection exactly as fixed rows. False when P is oblique
  /// (it mixes the axes) and fixed rows cannot express it.
  bool fixedAxes(std::array<bool, 3>& fixed) const {
    constexpr double tolerance = 1e-12;
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c)
        if (r != c && std::abs(P(r, c)) > tolerance) return false;
    for (int k = 0; k < 3; ++k) {
      if (std::abs(P(k, k)) <= tolerance)
        fixed[static_cast<std::size_t>(k)] = true;
      else if (std::abs(P(k, k) - 1) <= tolerance)
        fixed[static_cast<std::size_t>(k)] = false;
      else
        return false;
    }
    return true;
  }
};

/// The unit vector along v, or false when v is (numerically) zero.
inline bool unitVector(const Vec3d& v, Vec3d& unit) {
  const double norm = v.norm();
  if (!(norm > 1e-300) || !std::isfinite(norm)) return false;
  unit = v / norm;
  return true;
}

// --- The same motion for a list of points of a state (indices out of range are skipped: the
// components report them) --------------------------------------------------------------------

template <class Indices>
void projectDerivs(const AllowedMotion& motion, const Indices& indices, std::vector<Vec3d>& v) {
  for (const auto i : indices)
    if (static_cast<std::size_t>(i) < v.size()) v[i] = motion.project(v[i]);
}

template <class Indices>
void projectPositions(const AllowedMotion& motion, const Vec3d& origin, const Indices& indices,
                      std::vector<Vec3d>& x) {
  for (const auto i : indices)
    if (static_cast<std::size_t>(i) < x.size()) x[i] = motion.projectPosition(x[i], origin);
}

/// True when an index is >= n (checked before building an error message).
template <class Indices>
bool anyOutOfRange(const Indices& indices, std::size_t n) {
  for (const auto i : indices)
    if (static_cast<std::size_t>(i) >= n) return true;
  return false;
}

/// Appends the scalar rows (3 i + k) that the motion zeroes for each point i < n of `indices`.
/// Returns false, appending nothing, when the motion is oblique (see AllowedMotion::fixedAxes).
template <class Indices>
bool appendFixedRows(const AllowedMotion& motion, const Indices& indices, std::size_t n,
                     std::vector<std::size_t>& rows) {
  std::array<bool, 3> fixed{};
  if (!motion.fixedAxes(fixed)) return false;
  for (const auto i : indices)
    if (static_cast<std::size_t>(i) < n)
      for (std::size_t k = 0; k < 3; ++k)
        if (fixed[k]) rows.push_back(3 * static_cast<std::size_t>(i) + k);
  return true;
}

/// The warning of a constraint whose projection an assembled matrix cannot hold.
inline constexpr const char* kObliqueAssembledWarning =
    "the solver assembles the matrix, and fixed rows can only hold a projection along the "
    "coordinate axes: the linear solve ignores this oblique constraint and only the end of each "
    "step (velocities and positions projected) enforces it; use CGLinearSolver with its default "
    "(matrix-free) template for the exact constrained solve";

}  // namespace stroma::constraint
