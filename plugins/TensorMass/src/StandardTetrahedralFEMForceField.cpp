// SPDX-License-Identifier: MIT
#include "StandardTetrahedralFEMForceField.h"

#include <cmath>

#include "core/Node.h"

namespace stroma {

using tensormass::HyperelasticMaterial;

void StandardTetrahedralFEMForceField::init() {
  ForceField<Vec3Types>::init();
  m_ready = false;
  if (!mstate() || !m_mesh.read(*this, l_topology, *mstate()) || !readMaterial(true)) {
    setInvalid();
    return;
  }
  const auto& tetrahedra = m_mesh.tetrahedra();
  m_elements.resize(tetrahedra.size());
  for (std::size_t e = 0; e < tetrahedra.size(); ++e)
    m_elements[e] = {tetrahedra[e], m_mesh.shapes()[e].gradients,
                     std::abs(m_mesh.shapes()[e].volume)};
  m_points.assign(m_elements.size(), {});
  m_inverted.assign(m_elements.size(), 0);
  m_ready = true;
}

bool StandardTetrahedralFEMForceField::readMaterial(bool atInit) {
  m_materialVersion = d_materialName.version() + d_parameterSet.version() +
                      d_youngModulus.version() + d_poissonRatio.version();
  // Reports bad input: an error at init, a warning (and no change) while running.
  const auto report = [&](const std::string& text, const std::string& field) {
    if (atInit)
      msgError(text, field);
    else
      msgWarning(text + "; the change is not applied, the previous material stays", field);
    return false;
  };
  HyperelasticMaterial material;
  switch (d_materialName.value()) {
    case HyperelasticMaterialName::StVenantKirchhoff:
      material = HyperelasticMaterial::stVenantKirchhoff;
      break;
    case HyperelasticMaterialName::NeoHookean:
      material = HyperelasticMaterial::neoHookean;
      break;
    default:
      return report(std::string("material ") +
                        std::string(EnumKeywords<HyperelasticMaterialName>::names[static_cast<int>(
                            d_materialName.value())]) +
                        " is not implemented (SOFA's default is ArrudaBoyce): use "
                        "materialName=\"StVenantKirchhoff\" or \"NeoHookean\"",
                    "materialName");
  }

  fem::LameParameters lame;
  const std::vector<double>& parameters = d_parameterSet.value();
  if (!parameters.empty()) {
    if (d_youngModulus.isSet() || d_poissonRatio.isSet())
      return report(
          "give the material either as ParameterSet=\"mu lambda\" or as youngModulus and "
          "poissonRatio, not both",
          "ParameterSet");
    if (parameters.size() != 2)
      return report(
          "expected 2 values \"mu lambda\" (Pa), got " + std::to_string(parameters.size()),
          "ParameterSet");
    lame = {.lambda = parameters[1], .mu = parameters[0]};
    // mu > 0 and a positive bulk modulus lambda + 2 mu / 3: -1 < nu < 0.5.
    if (!(lame.mu > 0) || !(lame.lambda + 2 * lame.mu / 3 > 0))
      return report("expected mu > 0 and lambda > -2 mu / 3, got mu = " + std::to_string(lame.mu) +
                        ", lambda = " + std::to_string(lame.lambda),
                    "ParameterSet");
  } else {
    const auto fromModuli =
        readIsotropicMaterial(*this, d_youngModulus.value(), d_poissonRatio.value(), atInit);
    if (!fromModuli) return false;
    lame = *fromModuli;
  }
  m_material = material;
  m_lame = lame;
  return true;
}

bool StandardTetrahedralFEMForceField::refresh() {
  if (m_mesh.changed(*mstate())) {
    // Tetrahedra removed (cutting): their elements go, the others move with the topology's
    // renumbering. Otherwise start again.
    const bool followed =
        m_ready && m_mesh.followRemovals(*mstate(), [this](const TopologyChange& change, auto) {
          applyRemoval(m_elements, change.tetrahedra.removed);
          applyRemoval(m_points, change.tetrahedra.removed);
          applyRemoval(m_inverted, change.tetrahedra.removed);
        });
    if (!followed) init();
  } else if (m_ready && d_materialName.version() + d_parameterSet.version() +
                                d_youngModulus.version() + d_poissonRatio.version() !=
                            m_materialVersion) {
    readMaterial(false);
  }
  return m_ready;
}

void StandardTetrahedralFEMForceField::addForce(const MechanicalParams&, VecDeriv& f,
                                                const VecCoord& x, const VecDeriv&) {
  if (!mstate() || !refresh()) return;
  const std::vector<Vec3d>& rest = m_mesh.restPositions();
  Index firstInverted = kInvalidIndex;
  for (std::size_t e = 0; e < m_elements.size(); ++e) {
    const Element& element = m_elements[e];
    fem::TetrahedronVectors u;
    for (int i = 0; i < 4; ++i) u.col(i) = x[element.vertices[i]] - rest[element.vertices[i]];
    const Mat3d H = tensormass::computeDisplacementGradient(element.alpha, u);
    Mat3d P;
    m_inverted[e] = !tensormass::computeStress(m_material, m_lame, H, m_points[e], P);
    if (m_inverted[e]) {
      if (firstInverted == kInvalidIndex) firstInverted = static_cast<Index>(e);
      continue;
    }
    // f_j = -V P alpha_j.
    const fem::TetrahedronVectors forces = -element.volume * P * element.alpha;
    for (int i = 0; i < 4; ++i) f[element.vertices[i]] += forces.col(i);
  }
  if (firstInverted != kInvalidIndex && !m_inversionReported) {
    m_inversionReported = true;
    msgWarning("tetrahedron " + std::to_string(firstInverted) +
               " is inverted (det F <= 0) at t = " + std::to_string(node() ? node()->time() : 0.0) +
               ": the neo-Hookean energy is not defined there, the element gives no force while "
               "inverted (later inversions are not reported)");
  }
}

void StandardTetrahedralFEMForceField::addDForce(const MechanicalParams& mp, VecDeriv& df,
                                                 const VecDeriv& dx) {
  if (!m_ready || mp.kFactor == 0) return;
  for (std::size_t e = 0; e < m_elements.size(); ++e) {
    if (m_inverted[e]) continue;
    const Element& element = m_elements[e];
    fem::TetrahedronVectors du;
    for (int i = 0; i < 4; ++i) du.col(i) = dx[element.vertices[i]];
    const Mat3d dP = tensormass::computeStressDifferential(
        m_material, m_lame, m_points[e],
        tensormass::computeDisplacementGradient(element.alpha, du));
    const fem::TetrahedronVectors change = (-mp.kFactor * element.volume) * dP * element.alpha;
    for (int i = 0; i < 4; ++i) df[element.vertices[i]] += change.col(i);
  }
}

void StandardTetrahedralFEMForceField::addKToMatrix(const MechanicalParams& mp,
                                                    MatrixAccumulator& matrix, std::size_t offset) {
  if (!m_ready) return;
  for (std::size_t e = 0; e < m_elements.size(); ++e) {
    if (m_inverted[e]) continue;
    const Element& element = m_elements[e];
    const double scale = -mp.kFactor * element.volume;
    for (int j = 0; j < 4; ++j)
      for (int k = 0; k < 4; ++k)
        matrix.addBlock(
            offset + 3 * std::size_t{element.vertices[j]},
            offset + 3 * std::size_t{element.vertices[k]},
            scale * tensormass::computeTangentBlock(m_material, m_lame, m_points[e],
                                                    element.alpha.col(j), element.alpha.col(k)));
  }
}

double StandardTetrahedralFEMForceField::potentialEnergy(const MechanicalParams&,
                                                         const VecCoord& x) const {
  if (!m_ready) return 0;
  const std::vector<Vec3d>& rest = m_mesh.restPositions();
  double energy = 0;
  for (const Element& element : m_elements) {
    fem::TetrahedronVectors u;
    for (int i = 0; i < 4; ++i) u.col(i) = x[element.vertices[i]] - rest[element.vertices[i]];
    energy += element.volume *
              tensormass::computeEnergyDensity(
                  m_material, m_lame, tensormass::computeDisplacementGradient(element.alpha, u));
  }
  return energy;
}

}  // namespace stroma
