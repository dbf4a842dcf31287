// SPDX-License-Identifier: MIT
#include "TetrahedralFiberReinforcementForceField.h"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <span>
#include <string>

#include "Anisotropy/kernels/CorotationalReinforcement.h"
#include "FiberReinforcementInput.h"
#include "core/Node.h"
#include "topology/TopologyChange.h"

namespace stroma {

namespace {

using anisotropy::ConstantsStatus;
using anisotropy::EngineeringConstants;
using anisotropy::SpencerParameters;
using reinforcement::describeElements;
using Vector12d = fem::ElementVector<4>;

constexpr const char* kEngineeringNames =
    "youngModulusL, youngModulusT, poissonRatioLT, poissonRatioTT, shearModulusLT";
constexpr const char* kSpencerNames = "alpha, beta, shearModulusL, shearModulusT";

}  // namespace

void TetrahedralFiberReinforcementForceField::init() {
  ForceField<Vec3Types>::init();
  m_ready = false;
  if (!mstate() || !readMesh() || !build(true)) {
    setInvalid();
    return;
  }
  m_ready = true;
}

void TetrahedralFiberReinforcementForceField::bwdInit() {
  // After every init of the node: the fields beside have found their states.
  if (m_ready) compareWithIsotropicNeighbours(true);
}

void TetrahedralFiberReinforcementForceField::report(bool atInit, const std::string& text,
                                                     const std::string& field) {
  if (atInit)
    msgError(text, field);
  else
    msgWarning(text + "; the change is not applied, the previous material and fibers stay", field);
}

bool TetrahedralFiberReinforcementForceField::readMesh() {
  m_topology = findTetrahedralTopology(*this, l_topology);
  if (!m_topology) return false;
  m_tetrahedra = m_topology->tetrahedra();
  m_topologyRevision = m_topology->revision();
  m_pointCount = mstate()->size();
  m_restPositions = mstate()->readCoord(VecId::restPosition());
  if (m_restPositions.size() != m_pointCount) {
    msgError("the mechanical state " + mstate()->path() + " has " +
                 std::to_string(m_restPositions.size()) + " rest positions for " +
                 std::to_string(m_pointCount) + " points",
             "mstate");
    return false;
  }
  // The rest shape of each tetrahedron; both orientations work (Ke uses |V|).
  return reinforcement::computeRestShapes(*this, *m_topology, m_restPositions, m_shapes);
}

std::optional<SpencerParameters> TetrahedralFiberReinforcementForceField::readMaterial(
    bool atInit) {
  const std::vector<const Data<double>*> engineering{
      &d_youngModulusL, &d_youngModulusT, &d_poissonRatioLT, &d_poissonRatioTT, &d_shearModulusLT};
  const std::vector<const Data<double>*> spencer{&d_alpha, &d_beta, &d_shearModulusL,
                                                 &d_shearModulusT};
  auto anySet = [](const auto& fields) {
    for (const auto* d : fields)
      if (d->isSet()) return true;
    return false;
  };
  const bool useEngineering = anySet(engineering), useSpencer = anySet(spencer);
  if (useEngineering && useSpencer) {
    report(atInit,
           std::string("give either the engineering constants (") + kEngineeringNames +
               ") or Spencer's parameters (" + kSpencerNames + "), not both",
           "alpha");
    return std::nullopt;
  }
  if (!useEngineering && !useSpencer) {
    report(atInit,
           std::string("no material: give the five engineering constants of the "
                       "fiber-reinforced material (") +
               kEngineeringNames + "), or Spencer's parameters (" + kSpencerNames + ")",
           "youngModulusL");
    return std::nullopt;
  }
  // Every parameter of the chosen set: none has a meaningful default.
  bool complete = true;
  for (const auto* d : useEngineering ? engineering : spencer) {
    if (d->isSet()) continue;
    report(atInit,
           "missing: " + std::string(useEngineering
                                         ? std::string("the engineering constants need all "
                                                       "five of ") +
                                               kEngineeringNames
                                         : std::string("Spencer's parameters need all four of ") +
                                               kSpencerNames),
           d->name());
    complete = false;
  }
  if (!complete) return std::nullopt;

  if (useSpencer) {
    m_engineering = false;
    for (const Data<double>* d : {&d_shearModulusL, &d_shearModulusT})
      if (!(d->value() > 0)) {
        report(atInit, "expected a shear modulus > 0, got " + formatNumber(d->value()), d->name());
        return std::nullopt;
      }
    return SpencerParameters{.lambda = 0,
                             .muT = d_shearModulusT.value(),
                             .alpha = d_alpha.value(),
                             .beta = d_beta.value(),
                             .muL = d_shearModulusL.value()};
  }

  m_engineering = true;
  const EngineeringConstants c{.youngModulusL = d_youngModulusL.value(),
                               .youngModulusT = d_youngModulusT.value(),
                               .poissonRatioLT = d_poissonRatioLT.value(),
                               .poissonRatioTT = d_poissonRatioTT.value(),
                               .shearModulusLT = d_shearModulusLT.value()};
  switch (anisotropy::checkEngineeringConstants(c)) {
    case ConstantsStatus::ok:
      break;
    case ConstantsStatus::youngModulusL:
      report(atInit, "expected E_L > 0, got " + formatNumber(c.youngModulusL), "youngModulusL");
      return std::nullopt;
    case ConstantsStatus::youngModulusT:
      report(atInit, "expected E_T > 0, got " + formatNumber(c.youngModulusT), "youngModulusT");
      return std::nullopt;
    case ConstantsStatus::shearModulusLT:
      report(atInit, "expected G_LT > 0, got " + formatNumber(c.shearModulusLT), "shearModulusLT");
      return std::nullopt;
    case ConstantsStatus::poissonRatioTT:
      report(atInit,
             "expected -1 < poissonRatioTT < 1 (the material is not positive definite "
             "otherwise), got " +
                 formatNumber(c.poissonRatioTT),
             "poissonRatioTT");
      return std::nullopt;
    case ConstantsStatus::poissonRatioLT:
      report(atInit,
             "the compliance is not positive definite: expected poissonRatioLT^2 < "
             "(1 - poissonRatioTT) youngModulusL / (2 youngModulusT) = " +
                 formatNumber((1 - c.poissonRatioTT) * c.youngModulusL / (2 * c.youngModulusT)) +
                 ", got poissonRatioLT = " + formatNumber(c.poissonRatioLT),
             "poissonRatioLT");
      return std::nullopt;
  }
  // The isotropic part must be one an isotropic force field accepts (3 lambda + 2 mu_T > 0).
  const double n = c.youngModulusT / c.youngModulusL;
  if (!(1 + 2 * c.poissonRatioTT + c.poissonRatioLT * c.poissonRatioLT * n > 0)) {
    report(atInit,
           "the isotropic part of this material has no positive bulk modulus (no youngModulus "
           "and poissonRatio in (-1, 0.5) give it): expected 1 + 2 poissonRatioTT + "
           "poissonRatioLT^2 youngModulusT / youngModulusL > 0, got poissonRatioTT = " +
               formatNumber(c.poissonRatioTT),
           "poissonRatioTT");
    return std::nullopt;
  }
  return anisotropy::computeSpencerParameters(c);
}

bool TetrahedralFiberReinforcementForceField::readFibers(bool atInit,
                                                         std::vector<Vec3d>& directions) {
  const std::vector<Vec3d>& perElement = d_fiberDirections.value();
  if (perElement.empty()) {
    const Vec3d a = d_fiberDirection.value();
    if (!(a.norm() > 0) || !a.allFinite()) {
      report(atInit,
             "expected a non-zero direction, got " + formatNumber(a.x()) + " " +
                 formatNumber(a.y()) + " " + formatNumber(a.z()),
             "fiberDirection");
      return false;
    }
    directions.assign(1, a.normalized());
    return true;
  }
  if (perElement.size() != m_tetrahedra.size()) {
    report(atInit,
           "expected one direction per tetrahedron: got " + std::to_string(perElement.size()) +
               " directions for the " + std::to_string(m_tetrahedra.size()) + " tetrahedra of " +
               m_topology->path(),
           "fiberDirections");
    return false;
  }
  std::vector<std::size_t> zero;
  directions.resize(perElement.size());
  for (std::size_t t = 0; t < perElement.size(); ++t) {
    if (!(perElement[t].norm() > 0) || !perElement[t].allFinite())
      zero.push_back(t);
    else
      directions[t] = perElement[t].normalized();
  }
  if (!zero.empty()) {
    report(atInit,
           "expected non-zero directions; zero for " + std::to_string(zero.size()) +
               " tetrahedra: elements " + describeElements(zero),
           "fiberDirections");
    return false;
  }
  return true;
}

std::uint64_t TetrahedralFiberReinforcementForceField::parameterVersion() const {
  // Versions only grow: their sum changes whenever one of them does.
  return d_method.version() + d_fiberDirection.version() + d_fiberDirections.version() +
         d_youngModulusL.version() + d_youngModulusT.version() + d_poissonRatioLT.version() +
         d_poissonRatioTT.version() + d_shearModulusLT.version() + d_alpha.version() +
         d_beta.version() + d_shearModulusL.version() + d_shearModulusT.version();
}

bool TetrahedralFiberReinforcementForceField::build(bool atInit) {
  m_parameterVersion = parameterVersion();
  const std::optional<SpencerParameters> parameters = readMaterial(atInit);
  std::vector<Vec3d> directions;
  const bool fibersRead = readFibers(atInit, directions);
  if (!parameters || !fibersRead) return false;
  m_parameters = *parameters;
  const SpencerParameters& p = m_parameters;

  // C_r about each fiber direction, and Ke = V B^T C_r B of each tetrahedron (the tangent at
  // rest of method polar).
  m_elasticity.resize(directions.size());
  for (std::size_t i = 0; i < directions.size(); ++i)
    m_elasticity[i] =
        anisotropy::computeReinforcementElasticity(directions[i], p.alpha, p.beta, p.muL, p.muT);
  m_stiffness.resize(m_tetrahedra.size());
  for (std::size_t t = 0; t < m_tetrahedra.size(); ++t)
    m_stiffness[t] = fem::computeTetrahedronStiffness(m_shapes[t], elasticity(t));
  m_invertedWarnings = 0;

  if (m_engineering) {
    const anisotropy::IsotropicConstants iso =
        anisotropy::computeIsotropicConstants(p.lambda, p.muT);
    d_isotropicYoungModulus.setValue(iso.youngModulus);
    d_isotropicPoissonRatio.setValue(iso.poissonRatio);
    msgInfo("transversely isotropic material lambda = " + formatNumber(p.lambda) +
            " Pa, mu_T = " + formatNumber(p.muT) + " Pa, alpha = " + formatNumber(p.alpha) +
            " Pa, beta = " + formatNumber(p.beta) + " Pa, mu_L = " + formatNumber(p.muL) +
            " Pa: this component adds the alpha, beta and mu_L - mu_T terms; give the isotropic "
            "force field beside it youngModulus=\"" +
            formatNumber(iso.youngModulus) + "\" poissonRatio=\"" + formatNumber(iso.poissonRatio) +
            "\" (or link them to @" + name() + ".isotropicYoungModulus and @" + name() +
            ".isotropicPoissonRatio)");
  }
  return true;
}

void TetrahedralFiberReinforcementForceField::compareWithIsotropicNeighbours(bool atInit) {
  if (!node()) return;
  bool found = false;
  for (const reinforcement::IsotropicPartner& partner :
       reinforcement::findIsotropicPartners(*node(), *this, mstate())) {
    found = true;
    const BaseForceField* field = partner.field;
    const double E = partner.youngModulus, nu = partner.poissonRatio;
    const std::string who = field->className() + " " + field->path();

    // Both small, or both corotational: else a rotation of the body strains one of them.
    if (const BaseData* method = partner.method) {
      const bool mineSmall = d_method.value() == FiberMethod::small;
      const bool theirsSmall = method->valueText() == "small";
      if (mineSmall != theirsSmall)
        msgWarning("the isotropic force field " + who + " has method=\"" + method->valueText() +
                       "\" and this reinforcement method=\"" + d_method.valueText() +
                       "\": one is linear, the other corotational, so a rotation of the body "
                       "strains the linear one; use small with small, polar (or large) with a "
                       "corotational field",
                   "method");
    }

    if (m_engineering) {
      const anisotropy::IsotropicConstants iso =
          anisotropy::computeIsotropicConstants(m_parameters.lambda, m_parameters.muT);
      if (std::abs(E - iso.youngModulus) > 1e-3 * iso.youngModulus ||
          std::abs(nu - iso.poissonRatio) > 1e-3)
        msgWarning("the isotropic force field " + who + " has youngModulus=" + formatNumber(E) +
                       " poissonRatio=" + formatNumber(nu) +
                       "; with these engineering constants the isotropic part is "
                       "youngModulus=" +
                       formatNumber(iso.youngModulus) + " poissonRatio=" +
                       formatNumber(iso.poissonRatio) + ": the sum is not the material asked for",
                   "youngModulusL");
    } else if (nu > -1 && nu < 0.5 && E > 0) {
      const double mu = E / (2 * (1 + nu)), lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
      if (std::abs(mu - m_parameters.muT) > 1e-3 * m_parameters.muT)
        msgWarning("the isotropic force field " + who +
                       " has the shear modulus E / (2 (1 + nu)) = " + formatNumber(mu) +
                       " Pa, shearModulusT is " + formatNumber(m_parameters.muT) + " Pa",
                   "shearModulusT");
      // The sum must be positive definite (the reinforcement alone need not be).
      SpencerParameters total = m_parameters;
      total.lambda = lambda;
      const Eigen::SelfAdjointEigenSolver<fem::Matrix6d> eigen(
          anisotropy::computeTransverselyIsotropicElasticity(Vec3d::UnitX(), total));
      if (!(eigen.eigenvalues().minCoeff() > 0)) {
        report(atInit,
               "with the isotropic part of " + who + " (lambda = " + formatNumber(lambda) +
                   " Pa), the material is not positive definite (smallest eigenvalue of its "
                   "elasticity " +
                   formatNumber(eigen.eigenvalues().minCoeff()) +
                   " Pa): change alpha, beta or shearModulusL",
               "beta");
        if (atInit) {
          m_ready = false;
          setInvalid();
        }
      }
    }
  }
  if (!found)
    msgInfo(
        "no isotropic force field with one youngModulus and poissonRatio beside it: this "
        "component adds only the anisotropic part of the material");
}

bool TetrahedralFiberReinforcementForceField::followRemovals() {
  if (!m_ready || mstate()->size() != m_pointCount) return false;
  const auto changes = m_topology->changesSince(m_topologyRevision);
  if (!changes || changes->empty() || changes->front().tetrahedra.sizeBefore != m_tetrahedra.size())
    return false;
  // Replay SOFA's renumbering on everything kept per tetrahedron (TopologyChange.h), the
  // per-element fiber directions included: cost proportional to what was removed.
  std::vector<Vec3d>* directions =
      d_fiberDirections.value().empty() ? nullptr : &d_fiberDirections.edit();
  for (const TopologyChange& change : *changes) {
    const std::span<const Index> removed = change.tetrahedra.removed;
    applyRemoval(m_tetrahedra, removed);
    applyRemoval(m_shapes, removed);
    applyRemoval(m_stiffness, removed);
    if (m_elasticity.size() > 1) applyRemoval(m_elasticity, removed);
    if (directions) applyRemoval(*directions, removed);
  }
  m_topologyRevision = m_topology->revision();
  m_parameterVersion = parameterVersion();  // the directions followed the mesh: nothing to redo
  return m_tetrahedra.size() == m_topology->tetrahedra().size();
}

bool TetrahedralFiberReinforcementForceField::refresh() {
  if (m_topology &&
      (m_topology->revision() != m_topologyRevision || mstate()->size() != m_pointCount)) {
    // Tetrahedra removed: follow; any other change of the mesh: start again (allocates, as a
    // topological change does).
    if (!followRemovals()) m_ready = readMesh() && build(true);
  } else if (m_ready && parameterVersion() != m_parameterVersion) {
    build(false);  // an invalid change keeps the previous element matrices
  }
  return m_ready;
}

template <class Element>
void TetrahedralFiberReinforcementForceField::computeElements(const Element& element) {
  // Each element writes its own slot; the sums per point come after, in a fixed order, so
  // that results do not depend on the thread count.
  m_elementForces.resize(m_tetrahedra.size());
  auto range = [&element](std::size_t begin, std::size_t end) {
    for (std::size_t t = begin; t < end; ++t) element(t);
  };
  if (node())
    node()->threadPool().parallelFor(m_tetrahedra.size(), kGrain, range);
  else
    range(0, m_tetrahedra.size());
}

void TetrahedralFiberReinforcementForceField::addElementForces(VecDeriv& f) const {
  for (std::size_t t = 0; t < m_tetrahedra.size(); ++t)
    for (int i = 0; i < 4; ++i) f[m_tetrahedra[t][i]] += m_elementForces[t].col(i);
}

void TetrahedralFiberReinforcementForceField::addForce(const MechanicalParams&, VecDeriv& f,
                                                       const VecCoord& x, const VecDeriv&) {
  if (!mstate() || !refresh()) return;
  if (d_method.value() != FiberMethod::small) {
    addCorotationalForce(f, x);
    return;
  }
  // f_e = -Ke (x_e - X_e).
  computeElements([this, &x](std::size_t t) {
    const Tetrahedron& tet = m_tetrahedra[t];
    Vector12d u;
    for (int i = 0; i < 4; ++i) u.segment<3>(3 * i) = x[tet[i]] - m_restPositions[tet[i]];
    Eigen::Map<Vector12d>(m_elementForces[t].data()).noalias() = -m_stiffness[t] * u;
  });
  addElementForces(f);
}

void TetrahedralFiberReinforcementForceField::addDForce(const MechanicalParams& mp, VecDeriv& df,
                                                        const VecDeriv& dx) {
  if (!m_ready || mp.kFactor == 0) return;
  // df_e = -kFactor Ke dx_e (Ke: the tangent of the last addForce with method polar).
  const double factor = -mp.kFactor;
  computeElements([this, &dx, factor](std::size_t t) {
    const Tetrahedron& tet = m_tetrahedra[t];
    Vector12d d;
    for (int i = 0; i < 4; ++i) d.segment<3>(3 * i) = dx[tet[i]];
    Eigen::Map<Vector12d>(m_elementForces[t].data()).noalias() = factor * (m_stiffness[t] * d);
  });
  addElementForces(df);
}

void TetrahedralFiberReinforcementForceField::addKToMatrix(const MechanicalParams& mp,
                                                           MatrixAccumulator& matrix,
                                                           std::size_t offset) {
  if (!m_ready) return;
  for (std::size_t t = 0; t < m_tetrahedra.size(); ++t) {
    const Tetrahedron& tet = m_tetrahedra[t];
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j)
        matrix.addBlock(offset + 3 * tet[i], offset + 3 * tet[j],
                        -mp.kFactor * m_stiffness[t].block<3, 3>(3 * i, 3 * j));
  }
}

void TetrahedralFiberReinforcementForceField::addCorotationalForce(VecDeriv& f, const VecCoord& x) {
  // Forces and the tangent of each element at x (CorotationalReinforcement.h).
  m_elementInverted.resize(m_tetrahedra.size());
  computeElements([this, &x](std::size_t t) {
    const Tetrahedron& tet = m_tetrahedra[t];
    fem::TetrahedronVectors xe;
    for (int i = 0; i < 4; ++i) xe.col(i) = x[tet[i]];
    double energy = 0;
    m_elementInverted[t] = anisotropy::computeCorotationalReinforcement(
                               m_shapes[t], elasticity(t), xe, energy, m_elementForces[t],
                               &m_stiffness[t]) != anisotropy::CorotationalStatus::ok;
  });
  addElementForces(f);
  std::vector<std::size_t> inverted;
  for (std::size_t t = 0; t < m_tetrahedra.size(); ++t)
    if (m_elementInverted[t]) inverted.push_back(t);
  // An inverted element is a numerical outcome, not bad input: said once, with the elements.
  if (!inverted.empty() && m_invertedWarnings == 0) {
    ++m_invertedWarnings;
    msgWarning(std::to_string(inverted.size()) +
                   " tetrahedra are inverted (the polar rotation has no derivative there; their "
                   "tangent leaves it out): elements " +
                   describeElements(inverted),
               "method");
  }
}

double TetrahedralFiberReinforcementForceField::potentialEnergy(const MechanicalParams&,
                                                                const VecCoord& x) const {
  if (!m_ready || x.size() != m_pointCount) return 0;
  double energy = 0;
  if (d_method.value() != FiberMethod::small) {
    for (std::size_t t = 0; t < m_tetrahedra.size(); ++t) {
      fem::TetrahedronVectors xe, fe;
      for (int i = 0; i < 4; ++i) xe.col(i) = x[m_tetrahedra[t][i]];
      double element = 0;
      anisotropy::computeCorotationalReinforcement(m_shapes[t], elasticity(t), xe, element, fe,
                                                   nullptr);
      energy += element;
    }
    return energy;
  }
  for (std::size_t t = 0; t < m_tetrahedra.size(); ++t) {
    const Tetrahedron& tet = m_tetrahedra[t];
    Vector12d u;
    for (int i = 0; i < 4; ++i) u.segment<3>(3 * i) = x[tet[i]] - m_restPositions[tet[i]];
    energy += 0.5 * u.dot(m_stiffness[t] * u);
  }
  return energy;
}

}  // namespace stroma
