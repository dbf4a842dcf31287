// SPDX-License-Identifier: MIT
#include "TetrahedralStVKTensorMassForceField.h"

#include "VertexEdgeMatrix.h"

namespace stroma {

void TetrahedralStVKTensorMassForceField::init() {
  ForceField<Vec3Types>::init();
  m_ready = false;
  if (!mstate() || !m_mesh.read(*this, l_topology, *mstate()) || !build(true)) {
    setInvalid();
    return;
  }
  m_ready = true;
}

bool TetrahedralStVKTensorMassForceField::build(bool atInit) {
  m_youngModulusVersion = d_youngModulus.version();
  m_poissonRatioVersion = d_poissonRatio.version();
  const auto lame =
      readIsotropicMaterial(*this, d_youngModulus.value(), d_poissonRatio.value(), atInit);
  if (!lame) return false;
  tensormass::buildStVKTensorMass(m_mesh.tensorMassMesh(), *lame, m_model);
  m_uses.build(m_mesh.tetrahedra(), m_model.edges, m_model.triangles);
  m_lame = *lame;
  m_hessian.reset(m_mesh.pointCount(), m_model.edges);
  m_hessianCurrent = false;
  // Until the first addForce, the tangent is taken at the rest shape.
  m_displacement.assign(m_mesh.pointCount(), Vec3d::Zero());
  return true;
}

bool TetrahedralStVKTensorMassForceField::refresh() {
  if (m_mesh.changed(*mstate())) {
    // Tetrahedra removed (cutting): subtract their terms. Otherwise start again.
    const bool followed =
        m_ready &&
        m_mesh.followRemovals(*mstate(), [this](const TopologyChange& change, auto shapes) {
          tensormass::removeFromStVKTensorMass(change.tetrahedra.removed, shapes, m_lame,
                                               change.freedPoints, m_model, m_uses);
        });
    if (followed) {
      m_hessian.reset(m_mesh.pointCount(), m_model.edges);
      m_hessianCurrent = false;
    } else {
      m_ready = m_mesh.read(*this, l_topology, *mstate()) && build(true);
    }
  } else if (m_ready && (d_youngModulus.version() != m_youngModulusVersion ||
                         d_poissonRatio.version() != m_poissonRatioVersion)) {
    build(false);
  }
  return m_ready;
}

void TetrahedralStVKTensorMassForceField::addForce(const MechanicalParams&, VecDeriv& f,
                                                   const VecCoord& x, const VecDeriv&) {
  if (!mstate() || !refresh()) return;
  const std::vector<Vec3d>& rest = m_mesh.restPositions();
  for (std::size_t p = 0; p < m_displacement.size(); ++p) m_displacement[p] = x[p] - rest[p];
  m_hessianCurrent = false;
  tensormass::addStVKForce(m_model, m_displacement, f);
}

const tensormass::VertexEdgeTensors& TetrahedralStVKTensorMassForceField::hessian() {
  if (!m_hessianCurrent) {
    tensormass::computeStVKHessian(m_model, m_displacement, m_hessian);
    m_hessianCurrent = true;
  }
  return m_hessian;
}

void TetrahedralStVKTensorMassForceField::addDForce(const MechanicalParams& mp, VecDeriv& df,
                                                    const VecDeriv& dx) {
  if (!m_ready || mp.kFactor == 0) return;
  tensormass::addProduct(hessian(), dx, -mp.kFactor, df);
}

void TetrahedralStVKTensorMassForceField::addKToMatrix(const MechanicalParams& mp,
                                                       MatrixAccumulator& matrix,
                                                       std::size_t offset) {
  if (m_ready) addToMatrix(hessian(), -mp.kFactor, matrix, offset);
}

double TetrahedralStVKTensorMassForceField::potentialEnergy(const MechanicalParams&,
                                                            const VecCoord& x) const {
  if (!m_ready) return 0;
  const std::vector<Vec3d>& rest = m_mesh.restPositions();
  std::vector<Vec3d> u(x.size());
  for (std::size_t p = 0; p < u.size(); ++p) u[p] = x[p] - rest[p];
  return tensormass::computeStVKEnergy(m_model, u);
}

}  // namespace stroma
