// SPDX-License-Identifier: MIT
#include "SolidMechanics/kernels/RotationExtraction.h"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <Eigen/SVD>
#include <cmath>

namespace stroma::fem {

std::string_view rotationMethodName(RotationMethod method) {
  switch (method) {
    case RotationMethod::small:
      return "small";
    case RotationMethod::large:
      return "large";
    case RotationMethod::polar:
      return "polar";
    case RotationMethod::svd:
      return "svd";
  }
  return "";
}

std::optional<RotationMethod> parseRotationMethod(std::string_view name) {
  for (RotationMethod method :
       {RotationMethod::small, RotationMethod::large, RotationMethod::polar, RotationMethod::svd}) {
    if (rotationMethodName(method) == name) return method;
  }
  return std::nullopt;
}

Eigen::Matrix3d computeFrameFromEdges(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  const double aNorm = a.norm();
  if (!(aNorm > 0) || !std::isfinite(aNorm)) return Eigen::Matrix3d::Identity();
  const Eigen::Vector3d e1 = a / aNorm;
  const Eigen::Vector3d normal = a.cross(b);
  const double normalNorm = normal.norm();
  // Flat pair: any axis orthogonal to e1 keeps the frame a rotation.
  const Eigen::Vector3d e3 = normalNorm > 1e-12 * aNorm * b.norm() && std::isfinite(normalNorm)
                                 ? Eigen::Vector3d(normal / normalNorm)
                                 : e1.unitOrthogonal();
  Eigen::Matrix3d frame;
  frame << e1, e3.cross(e1), e3;
  return frame;
}

Eigen::Matrix3d computePolarRotation(const Eigen::Matrix3d& F) {
  const double scale = F.norm() / std::sqrt(3.0);
  const double det = F.determinant();
  if (!(det > 1e-6 * scale * scale * scale) || !F.allFinite()) return computeSvdRotation(F);

  // Scaled Newton iteration X <- (z X + X^-T / z) / 2 (Higham 1986, eq. 3.2), converging
  // quadratically to R for det F > 0. X^-T is built from the cross products of the columns of
  // X; z is the Frobenius-norm scaling z = (|X^-1|_F / |X|_F)^(1/2) (Higham 1986, sec. 3).
  Eigen::Matrix3d X = F;
  for (int iteration = 0; iteration < 30; ++iteration) {
    Eigen::Matrix3d cofactor;
    cofactor << X.col(1).cross(X.col(2)), X.col(2).cross(X.col(0)), X.col(0).cross(X.col(1));
    const Eigen::Matrix3d inverseTransposed = cofactor * (1.0 / X.col(0).dot(cofactor.col(0)));
    const double zeta = std::sqrt(std::sqrt(inverseTransposed.squaredNorm() / X.squaredNorm()));
    const Eigen::Matrix3d next = (0.5 * zeta) * X + (0.5 / zeta) * inverseTransposed;
    const double squaredChange = (next - X).squaredNorm();
    X = next;
    // Quadratic convergence: after a step of 1e-8 the error left is at round-off level.
    if (squaredChange <= 1e-16) break;
  }
  return X;
}

Eigen::Matrix3d computeSvdRotation(const Eigen::Matrix3d& F) {
  if (!F.allFinite()) return Eigen::Matrix3d::Identity();
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(F, Eigen::ComputeFullU | Eigen::ComputeFullV);
  // Singular values come sorted in decreasing order: column 2 is the smallest.
  Eigen::Matrix3d U = svd.matrixU();
  const Eigen::Matrix3d& V = svd.matrixV();
  if ((U * V.transpose()).determinant() < 0) U.col(2) = -U.col(2);
  return U * V.transpose();
}

}  // namespace stroma::fem
