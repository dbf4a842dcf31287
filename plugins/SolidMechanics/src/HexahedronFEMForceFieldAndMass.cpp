// SPDX-License-Identifier: MIT
#include "HexahedronFEMForceFieldAndMass.h"

#include "CorotationalStress.h"
#include "core/Node.h"

namespace stroma {

void HexahedronFEMForceFieldAndMass::init() {
  Mass<Vec3Types>::init();
  if (!m_model.init(mstate(), rotationMethod())) {
    setInvalid();
    return;
  }
  if (!(d_density.value() > 0)) {
    msgError("expected a density > 0, got " + std::to_string(d_density.value()), "density");
    return;
  }
  computeMass();
}

void HexahedronFEMForceFieldAndMass::computeMass() {
  const auto& elements = m_model.elements();
  const double density = d_density.value();
  const auto& rest = mstate()->readCoord(VecId::restPosition());
  m_elementMasses.resize(elements.size());
  m_vertexMasses.assign(elements.pointCount(), 0.0);
  node()->threadPool().parallelFor(elements.size(), 64, [&](std::size_t begin, std::size_t end) {
    for (std::size_t e = begin; e < end; ++e)
      m_elementMasses[e] = fem::computeHexahedronConsistentMass(elements.gather(rest, e), density);
  });
  // Row sums, added per vertex in element order.
  for (std::size_t e = 0; e < elements.size(); ++e) {
    const fem::Vector8d rowSums = m_elementMasses[e].rowwise().sum();
    for (int i = 0; i < 8; ++i) m_vertexMasses[elements.elements()[e][i]] += rowSums[i];
  }
  m_densityVersion = d_density.version();
  m_elementsRevision = m_model.elementsRevision();
}

void HexahedronFEMForceFieldAndMass::refreshMass() {
  if (m_elementsRevision == m_model.elementsRevision() && m_densityVersion == d_density.version())
    return;
  if (!(d_density.value() > 0)) {
    msgWarning("expected a density > 0, got " + std::to_string(d_density.value()) +
                   "; the change is not applied",
               "density");
    m_densityVersion = d_density.version();
    if (m_elementsRevision == m_model.elementsRevision()) return;
  }
  computeMass();
}

void HexahedronFEMForceFieldAndMass::addForce(const MechanicalParams&, VecDeriv& f,
                                              const VecCoord& x, const VecDeriv&) {
  if (!m_model.refresh(*mstate(), rotationMethod())) return;
  refreshMass();
  m_model.elements().addForce(rotationMethod(), x, f, node()->threadPool());
  const Vec3d g = node()->gravity();
  for (std::size_t i = 0; i < m_vertexMasses.size() && i < f.size(); ++i)
    f[i] += m_vertexMasses[i] * g;
}

void HexahedronFEMForceFieldAndMass::addDForce(const MechanicalParams& mp, VecDeriv& df,
                                               const VecDeriv& dx) {
  if (!m_model.ready() || mp.kFactor == 0) return;
  m_model.elements().addDForce(dx, df, mp.kFactor, node()->threadPool());
}

void HexahedronFEMForceFieldAndMass::addKToMatrix(const MechanicalParams& mp,
                                                  MatrixAccumulator& matrix, std::size_t offset) {
  if (!m_model.ready()) return;
  m_model.elements().addKToMatrix(matrix, offset, mp.kFactor, node()->threadPool());
}

double HexahedronFEMForceFieldAndMass::potentialEnergy(const MechanicalParams&,
                                                       const VecCoord& x) const {
  if (!m_model.ready()) return 0;
  double gravity = 0;
  const Vec3d g = node()->gravity();
  for (std::size_t i = 0; i < m_vertexMasses.size() && i < x.size(); ++i)
    gravity -= m_vertexMasses[i] * g.dot(x[i]);
  return m_model.elements().energy(rotationMethod(), x) + gravity;
}

void HexahedronFEMForceFieldAndMass::addMDx(VecDeriv& f, const VecDeriv& dx, double factor) {
  if (!m_model.ready() || factor == 0) return;
  if (d_lumpedMass.value()) {
    for (std::size_t i = 0; i < m_vertexMasses.size() && i < f.size(); ++i)
      f[i] += (factor * m_vertexMasses[i]) * dx[i];
    return;
  }
  auto& elements = m_model.elements();
  elements.accumulate(f, factor, node()->threadPool(),
                      [&](std::size_t e, Eigen::Map<fem::HexahedronVectors> corner) {
                        // (M (x) I_3) dx, node-major: column i = sum_j M_ij dx_j (M symmetric).
                        corner.noalias() = elements.gather(dx, e) * m_elementMasses[e];
                      });
}

void HexahedronFEMForceFieldAndMass::accFromF(VecDeriv& a, const VecDeriv& f) {
  // Only meaningful for the lumped mass (isDiagonal()); the lumped inverse otherwise.
  for (std::size_t i = 0; i < m_vertexMasses.size() && i < a.size(); ++i)
    a[i] = m_vertexMasses[i] > 0 ? Vec3d(f[i] / m_vertexMasses[i]) : Vec3d::Zero();
}

void HexahedronFEMForceFieldAndMass::addMToMatrix(MatrixAccumulator& matrix, std::size_t offset,
                                                  double factor) {
  if (!m_model.ready() || factor == 0) return;
  if (d_lumpedMass.value()) {
    for (std::size_t i = 0; i < m_vertexMasses.size(); ++i)
      for (std::size_t k = 0; k < 3; ++k)
        matrix.add(offset + 3 * i + k, offset + 3 * i + k, factor * m_vertexMasses[i]);
    return;
  }
  m_model.elements().addNodalMatrices(matrix, offset, factor, m_elementMasses);
}

double HexahedronFEMForceFieldAndMass::kineticEnergy(const VecDeriv& v) const {
  if (!m_model.ready()) return 0;
  double e = 0;
  if (d_lumpedMass.value()) {
    for (std::size_t i = 0; i < m_vertexMasses.size() && i < v.size(); ++i)
      e += m_vertexMasses[i] * v[i].squaredNorm();
  } else {
    const auto& elements = m_model.elements();
    for (std::size_t k = 0; k < elements.size(); ++k) {
      const fem::HexahedronVectors ve = elements.gather(v, k);
      e += (ve * m_elementMasses[k]).cwiseProduct(ve).sum();
    }
  }
  return 0.5 * e;
}

bool HexahedronFEMForceFieldAndMass::vonMisesPerElement(std::vector<double>& stress) const {
  if (!m_model.ready() || !mstate()) return false;
  return computeVonMisesPerElement(m_model.elements(), rotationMethod(),
                                   mstate()->readCoord(VecId::position()), d_youngModulus.value(),
                                   d_poissonRatio.value(), stress);
}

bool HexahedronFEMForceFieldAndMass::vonMisesPerPoint(std::vector<double>& stress) const {
  std::vector<double> perElement;
  if (!vonMisesPerElement(perElement)) return false;
  averageAroundPoints(m_model.elements(), perElement, mstate()->size(), stress);
  return true;
}

}  // namespace stroma
