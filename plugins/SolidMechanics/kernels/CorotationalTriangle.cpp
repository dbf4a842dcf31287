// SPDX-License-Identifier: MIT
#include "SolidMechanics/kernels/CorotationalTriangle.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace stroma::fem {

namespace {

// The in-plane displacements of corners x in frame R, before the rest corners are subtracted.
Vector6d localPositions(const Eigen::Matrix3d& R, const TriangleVectors& x) {
  Vector6d q;
  for (int i = 0; i < 3; ++i) {
    const Eigen::Vector3d d = x.col(i) - x.col(0);
    q[2 * i] = R.col(0).dot(d);
    q[2 * i + 1] = R.col(1).dot(d);
  }
  return q;
}

// Corner vectors R P^T g_i of an in-plane vector g (6).
TriangleVectors toGlobal(const Eigen::Matrix3d& R, const Vector6d& g) {
  TriangleVectors out;
  for (int i = 0; i < 3; ++i) out.col(i) = R.col(0) * g[2 * i] + R.col(1) * g[2 * i + 1];
  return out;
}

}  // namespace

Eigen::Matrix3d computeMembraneElasticity(double E, double nu, MembraneLaw law) {
  Eigen::Matrix3d D = Eigen::Matrix3d::Zero();
  if (law == MembraneLaw::planeStress) {
    const double k = E / (1 - nu * nu);
    D(0, 0) = D(1, 1) = k;
    D(0, 1) = D(1, 0) = k * nu;
    D(2, 2) = k * (1 - nu) / 2;
  } else {
    const double k = E / ((1 + nu) * (1 - 2 * nu));
    D(0, 0) = D(1, 1) = k * (1 - nu);
    D(0, 1) = D(1, 0) = k * nu;
    D(2, 2) = k * (1 - 2 * nu) / 2;
  }
  return D;
}

bool computeTriangleFrame(const TriangleVectors& x, Eigen::Matrix3d& R) {
  const Eigen::Vector3d a = x.col(1) - x.col(0);
  const Eigen::Vector3d b = x.col(2) - x.col(0);
  const Eigen::Vector3d normal = a.cross(b);
  const double longest = std::max({a.squaredNorm(), b.squaredNorm(), (b - a).squaredNorm()});
  const double doubleArea = normal.norm();
  if (!std::isfinite(doubleArea) || !(doubleArea > 2e-12 * longest)) return false;
  const Eigen::Vector3d e1 = a.normalized();
  const Eigen::Vector3d n = normal / doubleArea;
  R.col(0) = e1;
  R.col(1) = n.cross(e1);
  R.col(2) = n;
  return true;
}

ElementStatus computeTriangleConstants(const TriangleVectors& rest, const Eigen::Matrix3d& D,
                                       double thickness, double restScale,
                                       CorotationalTriangle& out) {
  if (!computeTriangleFrame(rest, out.restFrame)) return ElementStatus::degenerate;
  const Vector6d q = localPositions(out.restFrame, rest);
  for (int i = 0; i < 3; ++i) out.restLocal.col(i) = Eigen::Vector2d(q[2 * i], q[2 * i + 1]);
  // Shape-function gradients of the linear triangle (positive: p2 lies at y > 0).
  const Eigen::Matrix<double, 2, 3>& p = out.restLocal;
  const double doubleArea =
      (p(0, 1) - p(0, 0)) * (p(1, 2) - p(1, 0)) - (p(0, 2) - p(0, 0)) * (p(1, 1) - p(1, 0));
  out.area = doubleArea / 2;
  Eigen::Matrix<double, 3, 6> B = Eigen::Matrix<double, 3, 6>::Zero();
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    const double b = (p(1, j) - p(1, k)) / doubleArea;
    const double c = (p(0, k) - p(0, j)) / doubleArea;
    B(0, 2 * i) = b;
    B(1, 2 * i + 1) = c;
    B(2, 2 * i) = c;
    B(2, 2 * i + 1) = b;
  }
  out.stiffness = thickness * out.area * B.transpose() * D * B;
  out.restLocal *= restScale;
  return ElementStatus::ok;
}

Eigen::Matrix3d computeTriangleRotation(TriangleMethod method, const CorotationalTriangle& c,
                                        const TriangleVectors& x, const Eigen::Matrix3d& previous) {
  if (method == TriangleMethod::small) return c.restFrame;
  Eigen::Matrix3d R = previous;
  computeTriangleFrame(x, R);
  return R;
}

Eigen::Matrix<double, 6, 1> computeTriangleDisplacement(const CorotationalTriangle& c,
                                                        const Eigen::Matrix3d& R,
                                                        const TriangleVectors& x) {
  return localPositions(R, x) - Eigen::Map<const Vector6d>(c.restLocal.data());
}

TriangleVectors computeTriangleForce(const CorotationalTriangle& c, const Eigen::Matrix3d& R,
                                     const TriangleVectors& x) {
  return toGlobal(R, -(c.stiffness * computeTriangleDisplacement(c, R, x)));
}

TriangleVectors computeTriangleDForce(const CorotationalTriangle& c, const Eigen::Matrix3d& R,
                                      const TriangleVectors& dx) {
  Vector6d local;
  for (int i = 0; i < 3; ++i) {
    local[2 * i] = R.col(0).dot(dx.col(i));
    local[2 * i + 1] = R.col(1).dot(dx.col(i));
  }
  return toGlobal(R, -(c.stiffness * local));
}

Matrix9d computeTriangleStiffness(const CorotationalTriangle& c, const Eigen::Matrix3d& R) {
  Eigen::Matrix<double, 9, 6> T = Eigen::Matrix<double, 9, 6>::Zero();
  for (int i = 0; i < 3; ++i) T.block<3, 2>(3 * i, 2 * i) = R.leftCols<2>();
  return T * c.stiffness * T.transpose();
}

double computeTriangleEnergy(const CorotationalTriangle& c, const Eigen::Matrix3d& R,
                             const TriangleVectors& x) {
  const Vector6d u = computeTriangleDisplacement(c, R, x);
  return 0.5 * u.dot(c.stiffness * u);
}

}  // namespace stroma::fem
