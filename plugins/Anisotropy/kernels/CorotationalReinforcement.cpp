// SPDX-License-Identifier: MIT
#include "Anisotropy/kernels/CorotationalReinforcement.h"

#include <Eigen/LU>
#include <cmath>

#include "SolidMechanics/kernels/RotationExtraction.h"

namespace stroma::anisotropy {

namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;
using fem::Vector6d;

/// [w]x, with [w]x v = w x v.
Matrix3d cross(const Vector3d& w) {
  Matrix3d W;
  W << 0, -w.z(), w.y(), w.z(), 0, -w.x(), -w.y(), w.x(), 0;
  return W;
}

/// axial(skew(M)): the w with skew(M) = [w]x.
Vector3d axialOfSkew(const Matrix3d& M) {
  return 0.5 * Vector3d(M(2, 1) - M(1, 2), M(0, 2) - M(2, 0), M(1, 0) - M(0, 1));
}

/// Voigt strain (engineering shear) of a symmetric matrix, and the symmetric stress of a Voigt
/// stress; Stroma's order (xx, yy, zz, xy, yz, zx).
Vector6d strainVoigt(const Matrix3d& e) {
  Vector6d v;
  v << e(0, 0), e(1, 1), e(2, 2), e(0, 1) + e(1, 0), e(1, 2) + e(2, 1), e(2, 0) + e(0, 2);
  return v;
}

Matrix3d stressMatrix(const Vector6d& s) {
  Matrix3d m;
  m << s[0], s[3], s[5], s[3], s[1], s[4], s[5], s[4], s[2];
  return m;
}

}  // namespace

CorotationalStatus computeCorotationalReinforcement(const fem::TetrahedronShape& shape,
                                                    const fem::Matrix6d& Cr,
                                                    const fem::TetrahedronVectors& x,
                                                    double& energy, fem::TetrahedronVectors& force,
                                                    fem::Matrix12d* hessian) {
  const fem::TetrahedronVectors& g = shape.gradients;
  const double volume = std::abs(shape.volume);

  // F = R S and the corotated strain and stress (rest frame).
  const Matrix3d F = x * g.transpose();
  const Matrix3d R = fem::computePolarRotation(F);
  Matrix3d S = R.transpose() * F;
  S = (0.5 * (S + S.transpose())).eval();
  const Vector6d epsilon = strainVoigt(S - Matrix3d::Identity());
  const Vector6d sigmaVoigt = Cr * epsilon;
  const Matrix3d sigma = stressMatrix(sigmaVoigt);
  energy = 0.5 * volume * epsilon.dot(sigmaVoigt);

  // The rotation's derivative: k = G^-1 axial(skew(S sigma)).
  const Matrix3d G = S.trace() * Matrix3d::Identity() - S;
  const Eigen::FullPivLU<Matrix3d> Glu(G);
  const bool invertible =
      Glu.isInvertible() && std::abs(G.determinant()) > 1e-12 * std::pow(G.norm(), 3);
  const Vector3d k = invertible ? Vector3d(Glu.solve(axialOfSkew(S * sigma))) : Vector3d::Zero();

  // P = |V| R (sigma + 2 [k]x), f_i = -P g_i.
  const Matrix3d inner = sigma + 2 * cross(k);
  const Matrix3d P = volume * R * inner;
  force = -P * g;

  if (hessian) {
    // Column (3 j + c) of d2E/dx2: dP g_i for dF = e_c g_j^T.
    for (int j = 0; j < 4; ++j) {
      for (int c = 0; c < 3; ++c) {
        const Matrix3d dF = Vector3d::Unit(c) * g.col(j).transpose();
        const Matrix3d RtdF = R.transpose() * dF;
        const Vector3d omega =
            invertible ? Vector3d(2 * Glu.solve(axialOfSkew(RtdF))) : Vector3d::Zero();
        const Matrix3d Omega = cross(omega);
        Matrix3d dS = RtdF - Omega * S;
        dS = (0.5 * (dS + dS.transpose())).eval();
        const Matrix3d dsigma = stressMatrix(Cr * strainVoigt(dS));
        Vector3d dk = Vector3d::Zero();
        if (invertible) {
          const Vector3d dm = axialOfSkew(dS * sigma + S * dsigma);
          const Matrix3d dG = dS.trace() * Matrix3d::Identity() - dS;
          dk = Glu.solve(dm - dG * k);
        }
        const Matrix3d dP = volume * R * (Omega * inner + dsigma + 2 * cross(dk));
        const fem::TetrahedronVectors column = dP * g;
        hessian->col(3 * j + c) = Eigen::Map<const fem::ElementVector<4>>(column.data());
      }
    }
    *hessian = (0.5 * (*hessian + hessian->transpose())).eval();
  }
  return invertible ? CorotationalStatus::ok : CorotationalStatus::inverted;
}

}  // namespace stroma::anisotropy
