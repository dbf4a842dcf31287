// SPDX-License-Identifier: MIT
#include "TensorMass/kernels/HyperelasticTetrahedron.h"

#include <Eigen/LU>
#include <cmath>
#include <limits>

namespace stroma::tensormass {

using Eigen::Matrix3d;
using Eigen::Vector3d;

namespace {

Matrix3d greenStrain(const Matrix3d& H) { return 0.5 * (H + H.transpose() + H.transpose() * H); }

}  // namespace

bool computeStress(HyperelasticMaterial material, const fem::LameParameters& lame,
                   const Matrix3d& H, MaterialPoint& point, Matrix3d& P) {
  point.F = Matrix3d::Identity() + H;
  if (material == HyperelasticMaterial::stVenantKirchhoff) {
    const Matrix3d E = greenStrain(H);
    point.S = 2 * lame.mu * E;
    point.S.diagonal().array() += lame.lambda * E.trace();
    P.noalias() = point.F * point.S;
    return true;
  }
  const double J = point.F.determinant();
  if (!(J > 0)) return false;
  point.S = point.F.inverse().transpose();
  point.logJ = std::log(J);
  P = lame.mu * (point.F - point.S) + lame.lambda * point.logJ * point.S;
  return true;
}

double computeEnergyDensity(HyperelasticMaterial material, const fem::LameParameters& lame,
                            const Matrix3d& H) {
  if (material == HyperelasticMaterial::stVenantKirchhoff) {
    const Matrix3d E = greenStrain(H);
    const double trace = E.trace();
    return 0.5 * lame.lambda * trace * trace + lame.mu * E.squaredNorm();
  }
  const Matrix3d F = Matrix3d::Identity() + H;
  const double J = F.determinant();
  if (!(J > 0)) return std::numeric_limits<double>::infinity();
  const double logJ = std::log(J);
  // tr(F^T F) - 3 = 2 tr H + |H|^2, written so for small strains.
  return 0.5 * lame.mu * (2 * H.trace() + H.squaredNorm()) - lame.mu * logJ +
         0.5 * lame.lambda * logJ * logJ;
}

Matrix3d computeStressDifferential(HyperelasticMaterial material, const fem::LameParameters& lame,
                                   const MaterialPoint& point, const Matrix3d& dF) {
  if (material == HyperelasticMaterial::stVenantKirchhoff) {
    const Matrix3d FtdF = point.F.transpose() * dF;
    Matrix3d dS = lame.mu * (FtdF + FtdF.transpose());
    dS.diagonal().array() += lame.lambda * FtdF.trace();
    return dF * point.S + point.F * dS;
  }
  const Matrix3d& FinvT = point.S;
  return lame.mu * dF + (lame.mu - lame.lambda * point.logJ) * FinvT * dF.transpose() * FinvT +
         lame.lambda * (FinvT.transpose() * dF).trace() * FinvT;
}

Matrix3d computeTangentBlock(HyperelasticMaterial material, const fem::LameParameters& lame,
                             const MaterialPoint& point, const Vector3d& alphaJ,
                             const Vector3d& alphaK) {
  const double ajk = alphaJ.dot(alphaK);
  if (material == HyperelasticMaterial::stVenantKirchhoff) {
    // dF = dx alpha_k^T: dF S alpha_j + F dS alpha_j, written as a matrix acting on dx.
    const Vector3d Faj = point.F * alphaJ, Fak = point.F * alphaK;
    Matrix3d block = lame.lambda * Faj * Fak.transpose() + lame.mu * Fak * Faj.transpose() +
                     lame.mu * ajk * point.F * point.F.transpose();
    block.diagonal().array() += alphaK.dot(point.S * alphaJ);
    return block;
  }
  const Vector3d bj = point.S * alphaJ, bk = point.S * alphaK;  // F^-T alpha
  Matrix3d block = (lame.mu - lame.lambda * point.logJ) * bk * bj.transpose() +
                   lame.lambda * bj * bk.transpose();
  block.diagonal().array() += lame.mu * ajk;
  return block;
}

}  // namespace stroma::tensormass
