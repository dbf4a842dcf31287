// SPDX-License-Identifier: MIT
#include "TetrahedronFEMForceField.h"

#include "CorotationalStress.h"
#include "FemMaterial.h"
#include "core/Node.h"

namespace stroma {

void TetrahedronFEMForceField::init() {
  ForceField<Vec3Types>::init();
  if (d_plasticYieldThreshold.value() > 0)
    msgWarning("plasticity is not implemented: the material stays elastic",
               "plasticYieldThreshold");
  // With nodal volumetric integration the elements keep the deviatoric part only.
  m_model.elements().setVolumetricStiffness(toVolumetricStiffness(d_volumetricIntegration.value()));
  m_pressureElementsRevision = 0;
  if (!m_model.init(mstate(), rotationMethod())) {
    setInvalid();
    return;
  }
  refreshNodalPressure();
}

void TetrahedronFEMForceField::refreshNodalPressure() {
  if (!usesNodalPressure()) return;
  const bool elementsChanged = m_model.elementsRevision() != m_pressureElementsRevision;
  const bool materialChanged = d_youngModulus.version() != m_pressureYoungModulusVersion ||
                               d_poissonRatio.version() != m_pressurePoissonRatioVersion;
  if (!elementsChanged && !materialChanged) return;
  m_pressureYoungModulusVersion = d_youngModulus.version();
  m_pressurePoissonRatioVersion = d_poissonRatio.version();
  // An invalid material change was refused by m_model (a warning): keep the previous one.
  if (!elementsChanged && checkMaterial(d_youngModulus.value(), d_poissonRatio.value(),
                                        m_model.elements().size(), "tetrahedra"))
    return;
  m_pressureElementsRevision = m_model.elementsRevision();
  m_pressure.setup(m_model.elements(), d_youngModulus.value(), d_poissonRatio.value());
}

void TetrahedronFEMForceField::addForce(const MechanicalParams&, VecDeriv& f, const VecCoord& x,
                                        const VecDeriv&) {
  if (!m_model.refresh(*mstate(), rotationMethod())) return;
  m_model.elements().addForce(rotationMethod(), x, f, node()->threadPool());
  if (usesNodalPressure()) {
    refreshNodalPressure();
    m_pressure.addForce(m_model.elements(), x, f, node()->threadPool());
  }
}

void TetrahedronFEMForceField::addDForce(const MechanicalParams& mp, VecDeriv& df,
                                         const VecDeriv& dx) {
  if (!m_model.ready() || mp.kFactor == 0) return;
  m_model.elements().addDForce(dx, df, mp.kFactor, node()->threadPool());
  if (usesNodalPressure())
    m_pressure.addDForce(m_model.elements(), dx, df, mp.kFactor, node()->threadPool());
}

void TetrahedronFEMForceField::addKToMatrix(const MechanicalParams& mp, MatrixAccumulator& matrix,
                                            std::size_t offset) {
  if (!m_model.ready()) return;
  m_model.elements().addKToMatrix(matrix, offset, mp.kFactor, node()->threadPool());
  if (usesNodalPressure()) m_pressure.addKToMatrix(m_model.elements(), matrix, offset, mp.kFactor);
}

double TetrahedronFEMForceField::potentialEnergy(const MechanicalParams&, const VecCoord& x) const {
  if (!m_model.ready()) return 0;
  double energy = m_model.elements().energy(rotationMethod(), x);
  if (usesNodalPressure()) energy += m_pressure.energy(m_model.elements(), rotationMethod(), x);
  return energy;
}

bool TetrahedronFEMForceField::vonMisesPerElement(std::vector<double>& stress) const {
  if (!m_model.ready() || !mstate()) return false;
  return computeVonMisesPerElement(m_model.elements(), rotationMethod(),
                                   mstate()->readCoord(VecId::position()), d_youngModulus.value(),
                                   d_poissonRatio.value(), stress);
}

bool TetrahedronFEMForceField::vonMisesPerPoint(std::vector<double>& stress) const {
  std::vector<double> perElement;
  if (!vonMisesPerElement(perElement)) return false;
  averageAroundPoints(m_model.elements(), perElement, mstate()->size(), stress);
  return true;
}

}  // namespace stroma
