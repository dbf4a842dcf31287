// SPDX-License-Identifier: MIT
#include "TetrahedralVolumePenaltyForceField.h"

namespace stroma {

void TetrahedralVolumePenaltyForceField::init() {
  ForceField<Vec3Types>::init();
  m_ready = false;
  if (!mstate() || !m_mesh.read(*this, l_topology, *mstate())) {
    setInvalid();
    return;
  }
  m_restVolumes.resize(m_mesh.tetrahedra().size());
  for (std::size_t t = 0; t < m_restVolumes.size(); ++t)
    m_restVolumes[t] = m_mesh.shapes()[t].volume;
  m_positions = m_mesh.restPositions();
  m_ready = true;
}

fem::TetrahedronVectors TetrahedralVolumePenaltyForceField::gather(const VecCoord& x,
                                                                   const Tetrahedron& t) const {
  fem::TetrahedronVectors values;
  for (int i = 0; i < 4; ++i) values.col(i) = x[t[i]];
  return values;
}

void TetrahedralVolumePenaltyForceField::addForce(const MechanicalParams&, VecDeriv& f,
                                                  const VecCoord& x, const VecDeriv&) {
  if (!mstate()) return;
  if (m_mesh.changed(*mstate())) {
    // Tetrahedra removed (cutting): their rest volumes go with them. Otherwise start again.
    const bool followed =
        m_ready && m_mesh.followRemovals(*mstate(), [this](const TopologyChange& change, auto) {
          applyRemoval(m_restVolumes, change.tetrahedra.removed);
        });
    if (!followed) init();
  }
  if (!m_ready) return;
  m_positions.assign(x.begin(), x.end());
  const double gamma = d_stiffness.value();
  const auto& tetrahedra = m_mesh.tetrahedra();
  for (std::size_t t = 0; t < tetrahedra.size(); ++t) {
    const fem::TetrahedronVectors forces =
        tensormass::computeVolumePenaltyForce(gather(x, tetrahedra[t]), m_restVolumes[t], gamma);
    for (int i = 0; i < 4; ++i) f[tetrahedra[t][i]] += forces.col(i);
  }
}

void TetrahedralVolumePenaltyForceField::addDForce(const MechanicalParams& mp, VecDeriv& df,
                                                   const VecDeriv& dx) {
  if (!m_ready || mp.kFactor == 0) return;
  const double gamma = d_stiffness.value();
  const auto& tetrahedra = m_mesh.tetrahedra();
  for (std::size_t t = 0; t < tetrahedra.size(); ++t) {
    const fem::TetrahedronVectors change = tensormass::computeVolumePenaltyHessianProduct(
        gather(m_positions, tetrahedra[t]), m_restVolumes[t], gamma, gather(dx, tetrahedra[t]));
    for (int i = 0; i < 4; ++i) df[tetrahedra[t][i]] -= mp.kFactor * change.col(i);
  }
}

void TetrahedralVolumePenaltyForceField::addKToMatrix(const MechanicalParams& mp,
                                                      MatrixAccumulator& matrix,
                                                      std::size_t offset) {
  if (!m_ready) return;
  const double gamma = d_stiffness.value();
  const auto& tetrahedra = m_mesh.tetrahedra();
  for (std::size_t t = 0; t < tetrahedra.size(); ++t) {
    const fem::Matrix12d H = tensormass::computeVolumePenaltyHessian(
        gather(m_positions, tetrahedra[t]), m_restVolumes[t], gamma);
    for (int j = 0; j < 4; ++j)
      for (int k = 0; k < 4; ++k)
        matrix.addBlock(offset + 3 * std::size_t{tetrahedra[t][j]},
                        offset + 3 * std::size_t{tetrahedra[t][k]},
                        -mp.kFactor * H.block<3, 3>(3 * j, 3 * k));
  }
}

double TetrahedralVolumePenaltyForceField::potentialEnergy(const MechanicalParams&,
                                                           const VecCoord& x) const {
  if (!m_ready) return 0;
  const double gamma = d_stiffness.value();
  const auto& tetrahedra = m_mesh.tetrahedra();
  double energy = 0;
  for (std::size_t t = 0; t < tetrahedra.size(); ++t)
    energy +=
        tensormass::computeVolumePenaltyEnergy(gather(x, tetrahedra[t]), m_restVolumes[t], gamma);
  return energy;
}

}  // namespace stroma
