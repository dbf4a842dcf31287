// SPDX-License-Identifier: MIT
#include "TetrahedralTensorMassForceField.h"

#include "TensorMass/kernels/LinearTensorMass.h"
#include "VertexEdgeMatrix.h"

namespace stroma {

void TetrahedralTensorMassForceField::init() {
  ForceField<Vec3Types>::init();
  m_ready = false;
  if (!mstate() || !m_mesh.read(*this, l_topology, *mstate()) || !build(true)) {
    setInvalid();
    return;
  }
  m_ready = true;
}

bool TetrahedralTensorMassForceField::build(bool atInit) {
  m_youngModulusVersion = d_youngModulus.version();
  m_poissonRatioVersion = d_poissonRatio.version();
  const auto lame =
      readIsotropicMaterial(*this, d_youngModulus.value(), d_poissonRatio.value(), atInit);
  if (!lame) return false;
  tensormass::buildLinearTensorMass(m_mesh.tensorMassMesh(), *lame, m_tensors);
  m_uses.build(m_mesh.tetrahedra(), m_tensors.edges, {});
  m_lame = *lame;
  m_displacement.assign(m_mesh.pointCount(), Vec3d::Zero());
  return true;
}

bool TetrahedralTensorMassForceField::refresh() {
  if (m_mesh.changed(*mstate())) {
    // Tetrahedra removed (cutting): subtract their tensors. Otherwise the mesh changed: start
    // again (allocates, as a topological change does).
    const bool followed =
        m_ready &&
        m_mesh.followRemovals(*mstate(), [this](const TopologyChange& change, auto shapes) {
          tensormass::removeFromLinearTensorMass(change.tetrahedra.removedElements, shapes, m_lame,
                                                 change.freedPoints, m_tensors, m_uses);
        });
    if (!followed) m_ready = m_mesh.read(*this, l_topology, *mstate()) && build(true);
  } else if (m_ready && (d_youngModulus.version() != m_youngModulusVersion ||
                         d_poissonRatio.version() != m_poissonRatioVersion)) {
    build(false);  // an invalid change keeps the previous tensors
  }
  return m_ready;
}

void TetrahedralTensorMassForceField::addForce(const MechanicalParams&, VecDeriv& f,
                                               const VecCoord& x, const VecDeriv&) {
  if (!mstate() || !refresh()) return;
  const std::vector<Vec3d>& rest = m_mesh.restPositions();
  for (std::size_t p = 0; p < m_displacement.size(); ++p) m_displacement[p] = x[p] - rest[p];
  tensormass::addProduct(m_tensors, m_displacement, -1.0, f);
}

void TetrahedralTensorMassForceField::addDForce(const MechanicalParams& mp, VecDeriv& df,
                                                const VecDeriv& dx) {
  if (!m_ready || mp.kFactor == 0) return;
  tensormass::addProduct(m_tensors, dx, -mp.kFactor, df);
}

void TetrahedralTensorMassForceField::addKToMatrix(const MechanicalParams& mp,
                                                   MatrixAccumulator& matrix, std::size_t offset) {
  if (m_ready) addToMatrix(m_tensors, -mp.kFactor, matrix, offset);
}

double TetrahedralTensorMassForceField::potentialEnergy(const MechanicalParams&,
                                                        const VecCoord& x) const {
  if (!m_ready) return 0;
  const std::vector<Vec3d>& rest = m_mesh.restPositions();
  std::vector<Vec3d> u(x.size());
  for (std::size_t p = 0; p < u.size(); ++p) u[p] = x[p] - rest[p];
  return tensormass::computeQuadraticEnergy(m_tensors, u);
}

}  // namespace stroma
