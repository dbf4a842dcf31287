// SPDX-License-Identifier: MIT
#include "Anisotropy/kernels/TransverselyIsotropicMaterial.h"

#include <Eigen/LU>
#include <array>
#include <cmath>

namespace stroma::anisotropy {

namespace {

// Voigt index -> tensor indices, Stroma's order (xx, yy, zz, xy, yz, zx).
constexpr std::array<std::array<int, 2>, 6> kVoigt{
    {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {1, 2}, {2, 0}}};

bool positiveFinite(double x) { return std::isfinite(x) && x > 0; }

}  // namespace

ConstantsStatus checkEngineeringConstants(const EngineeringConstants& c) {
  if (!positiveFinite(c.youngModulusL)) return ConstantsStatus::youngModulusL;
  if (!positiveFinite(c.youngModulusT)) return ConstantsStatus::youngModulusT;
  if (!positiveFinite(c.shearModulusLT)) return ConstantsStatus::shearModulusLT;
  if (!(c.poissonRatioTT > -1 && c.poissonRatioTT < 1)) return ConstantsStatus::poissonRatioTT;
  const double nu = c.poissonRatioLT;
  if (!std::isfinite(nu) ||
      !(1 - c.poissonRatioTT - 2 * nu * nu * c.youngModulusT / c.youngModulusL > 0))
    return ConstantsStatus::poissonRatioLT;
  return ConstantsStatus::ok;
}

SpencerParameters computeSpencerParameters(const EngineeringConstants& c) {
  const double EL = c.youngModulusL, ET = c.youngModulusT;
  const double nuLT = c.poissonRatioLT, nuTT = c.poissonRatioTT;
  const double D = (1 + nuTT) * (1 - nuTT - 2 * nuLT * nuLT * ET / EL);
  const double C11 = EL * (1 - nuTT * nuTT) / D;
  const double C12 = ET * nuLT * (1 + nuTT) / D;
  SpencerParameters p;
  p.lambda = ET * (nuTT + nuLT * nuLT * ET / EL) / D;
  p.muT = ET / (2 * (1 + nuTT));
  p.muL = c.shearModulusLT;
  p.alpha = C12 - p.lambda;
  p.beta = C11 - 2 * C12 + p.lambda + 2 * p.muT - 4 * p.muL;
  return p;
}

EngineeringConstants computeEngineeringConstants(const SpencerParameters& p) {
  // The compliance of the material with its fiber along x.
  const Matrix6d S = computeTransverselyIsotropicElasticity(Eigen::Vector3d::UnitX(), p).inverse();
  EngineeringConstants c;
  c.youngModulusL = 1 / S(0, 0);
  c.youngModulusT = 1 / S(1, 1);
  c.poissonRatioLT = -S(0, 1) / S(0, 0);
  c.poissonRatioTT = -S(1, 2) / S(1, 1);
  c.shearModulusLT = 1 / S(3, 3);
  return c;
}

IsotropicConstants computeIsotropicConstants(double lambda, double mu) {
  return {.youngModulus = mu * (3 * lambda + 2 * mu) / (lambda + mu),
          .poissonRatio = lambda / (2 * (lambda + mu))};
}

Matrix6d computeReinforcementElasticity(const Eigen::Vector3d& a, double alpha, double beta,
                                        double muL, double muT) {
  // C_ijkl = alpha (d_ij A_kl + A_ij d_kl) + beta A_ij A_kl
  //        + (mu_L - mu_T)(A_ik d_jl + A_il d_jk + d_ik A_jl + d_il A_jk),
  // the second derivative of W_r; Voigt entries C_IJ = C_ijkl with engineering shear.
  const Eigen::Matrix3d A = a * a.transpose();
  const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
  const double gamma = muL - muT;
  Matrix6d C;
  for (int P = 0; P < 6; ++P) {
    const int i = kVoigt[P][0], j = kVoigt[P][1];
    for (int Q = 0; Q < 6; ++Q) {
      const int k = kVoigt[Q][0], l = kVoigt[Q][1];
      C(P, Q) =
          alpha * (I(i, j) * A(k, l) + A(i, j) * I(k, l)) + beta * A(i, j) * A(k, l) +
          gamma * (A(i, k) * I(j, l) + A(i, l) * I(j, k) + I(i, k) * A(j, l) + I(i, l) * A(j, k));
    }
  }
  return C;
}

Matrix6d computeTransverselyIsotropicElasticity(const Eigen::Vector3d& a,
                                                const SpencerParameters& p) {
  Matrix6d C = computeReinforcementElasticity(a, p.alpha, p.beta, p.muL, p.muT);
  C.topLeftCorner<3, 3>().array() += p.lambda;
  for (int i = 0; i < 3; ++i) C(i, i) += 2 * p.muT;
  for (int i = 3; i < 6; ++i) C(i, i) += p.muT;
  return C;
}

double computeReinforcementEnergyDensity(const Eigen::Matrix3d& eps, const Eigen::Vector3d& a,
                                         double alpha, double beta, double muL, double muT) {
  const double trace = eps.trace();
  const double stretch = a.dot(eps * a);         // a.eps a
  const double shear = (eps * a).squaredNorm();  // a.eps^2 a = |eps a|^2
  return alpha * trace * stretch + 2 * (muL - muT) * shear + 0.5 * beta * stretch * stretch;
}

}  // namespace stroma::anisotropy
