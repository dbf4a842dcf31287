// SPDX-License-Identifier: MIT
#include "HexahedronFEMForceField.h"

#include "CorotationalStress.h"
#include "core/Node.h"

namespace stroma {

void HexahedronFEMForceField::init() {
  ForceField<Vec3Types>::init();
  m_model.elements().setVolumetricStiffness(toVolumetricStiffness(d_volumetricIntegration.value()));
  if (!m_model.init(mstate(), rotationMethod())) setInvalid();
}

void HexahedronFEMForceField::addForce(const MechanicalParams&, VecDeriv& f, const VecCoord& x,
                                       const VecDeriv&) {
  if (!m_model.refresh(*mstate(), rotationMethod())) return;
  m_model.elements().addForce(rotationMethod(), x, f, node()->threadPool());
}

void HexahedronFEMForceField::addDForce(const MechanicalParams& mp, VecDeriv& df,
                                        const VecDeriv& dx) {
  if (!m_model.ready() || mp.kFactor == 0) return;
  m_model.elements().addDForce(dx, df, mp.kFactor, node()->threadPool());
}

void HexahedronFEMForceField::addKToMatrix(const MechanicalParams& mp, MatrixAccumulator& matrix,
                                           std::size_t offset) {
  if (!m_model.ready()) return;
  m_model.elements().addKToMatrix(matrix, offset, mp.kFactor, node()->threadPool());
}

double HexahedronFEMForceField::potentialEnergy(const MechanicalParams&, const VecCoord& x) const {
  if (!m_model.ready()) return 0;
  return m_model.elements().energy(rotationMethod(), x);
}

bool HexahedronFEMForceField::vonMisesPerElement(std::vector<double>& stress) const {
  if (!m_model.ready() || !mstate()) return false;
  return computeVonMisesPerElement(m_model.elements(), rotationMethod(),
                                   mstate()->readCoord(VecId::position()), d_youngModulus.value(),
                                   d_poissonRatio.value(), stress);
}

bool HexahedronFEMForceField::vonMisesPerPoint(std::vector<double>& stress) const {
  std::vector<double> perElement;
  if (!vonMisesPerElement(perElement)) return false;
  averageAroundPoints(m_model.elements(), perElement, mstate()->size(), stress);
  return true;
}

}  // namespace stroma
