// SPDX-License-Identifier: MIT
#include "HardeningAnchorForceField.h"

#include "linalg/AssembledMatrix.h"
#include "simulation/MechanicalState.h"

namespace hardening {

using stroma::MechanicalParams;
using stroma::Vec3d;
using stroma::VecId;

void HardeningAnchorForceField::init() {
  ForceField::init();
  if (!mstate()) return;
  m_rest = mstate()->readCoord(VecId::restPosition());
  m_current = mstate()->readCoord(VecId::position());
}

Eigen::Matrix3d HardeningAnchorForceField::tangent(const Vec3d& u) const {
  const double k = d_stiffness.value(), c = d_hardening.value();
  return -(k + c * u.squaredNorm()) * Eigen::Matrix3d::Identity() - 2 * c * u * u.transpose();
}

void HardeningAnchorForceField::addForce(const MechanicalParams&, VecDeriv& f, const VecCoord& x,
                                         const VecDeriv&) {
  const double k = d_stiffness.value(), c = d_hardening.value();
  m_current = x;
  for (std::size_t i = 0; i < x.size() && i < m_rest.size(); ++i) {
    const Vec3d u = x[i] - m_rest[i];
    f[i] -= (k + c * u.squaredNorm()) * u;
  }
}

void HardeningAnchorForceField::addDForce(const MechanicalParams& mp, VecDeriv& df,
                                          const VecDeriv& dx) {
  for (std::size_t i = 0; i < dx.size() && i < m_rest.size(); ++i)
    df[i] += mp.kFactor * tangent(m_current[i] - m_rest[i]) * dx[i];
}

void HardeningAnchorForceField::addKToMatrix(const MechanicalParams& mp,
                                             stroma::MatrixAccumulator& matrix,
                                             std::size_t offset) {
  for (std::size_t i = 0; i < m_current.size() && i < m_rest.size(); ++i)
    matrix.addBlock(offset + 3 * i, offset + 3 * i, mp.kFactor * tangent(m_current[i] - m_rest[i]));
}

double HardeningAnchorForceField::potentialEnergy(const MechanicalParams&,
                                                  const VecCoord& x) const {
  const double k = d_stiffness.value(), c = d_hardening.value();
  double energy = 0;
  for (std::size_t i = 0; i < x.size() && i < m_rest.size(); ++i) {
    const double u2 = (x[i] - m_rest[i]).squaredNorm();
    energy += 0.5 * k * u2 + 0.25 * c * u2 * u2;
  }
  return energy;
}

}  // namespace hardening
