// SPDX-License-Identifier: MIT
#include "SolidMechanics/kernels/LinearTetrahedron.h"

#include <Eigen/LU>
#include <cmath>

#include "SolidMechanics/kernels/StrainDisplacement.h"

namespace stroma::fem {

namespace {

Eigen::Matrix3d edgeMatrix(const TetrahedronVectors& x) {
  Eigen::Matrix3d D;
  D << x.col(1) - x.col(0), x.col(2) - x.col(0), x.col(3) - x.col(0);
  return D;
}

}  // namespace

double computeTetrahedronVolume(const TetrahedronVectors& x) {
  return edgeMatrix(x).determinant() / 6.0;
}

ElementStatus computeTetrahedronShape(const TetrahedronVectors& rest, TetrahedronShape& shape) {
  if (!rest.allFinite()) return ElementStatus::degenerate;
  const Eigen::Matrix3d Dm = edgeMatrix(rest);
  const double det = Dm.determinant();
  const double longest = Dm.colwise().norm().maxCoeff();
  if (!(std::abs(det) > 1e-12 * longest * longest * longest)) return ElementStatus::degenerate;

  // grad N_j (j = 1, 2, 3) is row j of Dm^-1; the gradients sum to zero.
  const Eigen::Matrix3d DmInverseTransposed = Dm.inverse().transpose();
  shape.gradients.rightCols<3>() = DmInverseTransposed;
  shape.gradients.col(0) = -DmInverseTransposed.rowwise().sum();
  shape.volume = det / 6.0;
  return ElementStatus::ok;
}

Matrix12d computeTetrahedronStiffness(const TetrahedronShape& shape, const Matrix6d& C) {
  const Eigen::Matrix<double, 6, 12> B = computeStrainDisplacement<4>(shape.gradients);
  const Matrix12d Ke = std::abs(shape.volume) * (B.transpose() * C * B);
  // Symmetric to the last bit, so that solvers that test symmetry accept it.
  return 0.5 * (Ke + Ke.transpose());
}

TetrahedronVectors computeLinearForce(const Matrix12d& Ke, const TetrahedronVectors& u) {
  TetrahedronVectors f;
  Eigen::Map<ElementVector<4>>(f.data()).noalias() = -Ke * asElementVector<4>(u);
  return f;
}

}  // namespace stroma::fem
