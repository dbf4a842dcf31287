// SPDX-License-Identifier: MIT
#include "TriangularFEMForceField.h"

#include <cmath>

#include "FemTopology.h"
#include "core/Node.h"
#include "core/ThreadPool.h"

namespace stroma {

namespace {

// Rotation and force: about 0.1 us per triangle; a task of 10 to 100 us.
constexpr std::size_t kGrain = 256;

// The last topology of `node` with triangles, else the last with quads.
const Topology* lastWithTriangles(const Node& node) {
  const Topology* withTriangles = nullptr;
  const Topology* withQuads = nullptr;
  for (const Topology* topology : node.getAll<Topology>()) {
    if (!topology->triangles().empty()) withTriangles = topology;
    if (!topology->quads().empty()) withQuads = topology;
  }
  return withTriangles ? withTriangles : withQuads;
}

// "one value or one per triangle" of a material list: empty when it fits.
std::string checkCount(std::size_t count, std::size_t triangles) {
  if (count == 1 || (count == triangles && count > 0)) return {};
  return "expected one value or one per element (" + std::to_string(triangles) +
         " triangles), got " + std::to_string(count);
}

}  // namespace

void TriangularFEMForceField::init() {
  ForceField<Vec3Types>::init();
  m_ready = false;
  if (!mstate()) return setInvalid();
  // The topology: the link, else the nearest node from here up with triangles (or quads).
  m_topology = nullptr;
  if (l_topology) {
    if (l_topology->triangles().empty() && l_topology->quads().empty()) {
      msgError("the topology " + l_topology->path() + " has no triangles (nor quads)", "topology");
      return setInvalid();
    }
    m_topology = l_topology.get();
  } else {
    for (const Node* n = node(); n && !m_topology; n = n->parent())
      m_topology = lastWithTriangles(*n);
  }
  if (!m_topology) {
    msgError(
        "needs a topology with triangles (TriangleSetTopologyContainer, MeshTopology, ...) in "
        "its node or above, or a 'topology' link",
        "topology");
    return setInvalid();
  }
  if (!readTriangles() || !checkMaterial(true) || !computeConstants()) return setInvalid();
  m_ready = true;
}

bool TriangularFEMForceField::readTriangles() {
  m_topologyRevision = m_topology->revision();
  m_stateSize = mstate()->size();
  m_triangles = m_topology->triangles();
  if (m_triangles.empty())
    for (const Quad& q : m_topology->quads()) {
      m_triangles.push_back({q[0], q[1], q[2]});
      m_triangles.push_back({q[0], q[2], q[3]});
    }
  if (!checkElementIndices<3>(*this, "triangles", m_triangles, m_stateSize)) return false;
  m_constants.assign(m_triangles.size(), {});
  m_rotations.assign(m_triangles.size(), Eigen::Matrix3d::Identity());
  m_corners.assign(3 * m_triangles.size(), Vec3d::Zero());
  return true;
}

bool TriangularFEMForceField::checkMaterial(bool atInit) {
  const std::size_t n = m_triangles.size();
  auto report = [&](const std::string& text, const char* field) {
    if (atInit)
      msgError(text, field);
    else
      msgWarning(text + "; the previous material is kept", field);
    return false;
  };
  const std::vector<double>& young = d_youngModulus.value();
  const std::vector<double>& poisson = d_poissonRatio.value();
  if (std::string problem = checkCount(young.size(), n); !problem.empty())
    return report(problem, "youngModulus");
  for (double E : young)
    if (!(E > 0) || !std::isfinite(E))
      return report("expected values > 0, got " + std::to_string(E), "youngModulus");
  if (std::string problem = checkCount(poisson.size(), n); !problem.empty())
    return report(problem, "poissonRatio");
  for (double nu : poisson)
    if (!(nu > -1 && nu < 0.5))
      return report("expected -1 < poissonRatio < 0.5, got " + std::to_string(nu), "poissonRatio");
  if (!(d_thickness.value() > 0) || !std::isfinite(d_thickness.value()))
    return report("expected a thickness > 0, got " + std::to_string(d_thickness.value()),
                  "thickness");
  if (!(d_restScale.value() > 0) || !std::isfinite(d_restScale.value()))
    return report("expected a restScale > 0, got " + std::to_string(d_restScale.value()),
                  "restScale");
  return true;
}

bool TriangularFEMForceField::computeConstants() {
  m_materialVersions = {d_youngModulus.version(), d_poissonRatio.version(), d_thickness.version(),
                        d_planeStrain.version(), d_restScale.version()};
  const VecCoord& restState = mstate()->readCoord(VecId::restPosition());
  const VecCoord& rest =
      restState.size() == m_stateSize ? restState : mstate()->readCoord(VecId::position());
  const std::vector<double>& young = d_youngModulus.value();
  const std::vector<double>& poisson = d_poissonRatio.value();
  const auto law =
      d_planeStrain.value() ? fem::MembraneLaw::planeStrain : fem::MembraneLaw::planeStress;
  std::vector<Index> degenerate;
  for (std::size_t e = 0; e < m_triangles.size(); ++e) {
    const double E = young.size() == 1 ? young[0] : young[e];
    const double nu = poisson.size() == 1 ? poisson[0] : poisson[e];
    const Eigen::Matrix3d D = fem::computeMembraneElasticity(E, nu, law);
    if (fem::computeTriangleConstants(corners(rest, e), D, d_thickness.value(), d_restScale.value(),
                                      m_constants[e]) != fem::ElementStatus::ok)
      degenerate.push_back(static_cast<Index>(e));
    m_rotations[e] = m_constants[e].restFrame;
  }
  if (degenerate.empty()) return true;
  msgError(std::to_string(degenerate.size()) +
               " rest triangles are degenerate (collinear or coincident corners): elements " +
               describeIndices(degenerate),
           "topology");
  return false;
}

bool TriangularFEMForceField::refresh() {
  if (!m_topology) return false;
  // The elements or the state size changed: everything again (allocates).
  if (m_topology->revision() != m_topologyRevision || mstate()->size() != m_stateSize) {
    m_ready = readTriangles() && checkMaterial(false) && computeConstants();
    return m_ready;
  }
  if (!m_ready) return false;
  const std::array<std::uint64_t, 5> versions{d_youngModulus.version(), d_poissonRatio.version(),
                                              d_thickness.version(), d_planeStrain.version(),
                                              d_restScale.version()};
  if (versions != m_materialVersions) {
    if (checkMaterial(false))
      computeConstants();
    else
      m_materialVersions = versions;  // warned once; the previous constants stay
  }
  return true;
}

fem::TriangleVectors TriangularFEMForceField::corners(const VecCoord& x, std::size_t e) const {
  fem::TriangleVectors c;
  for (int i = 0; i < 3; ++i) c.col(i) = x[m_triangles[e][i]];
  return c;
}

void TriangularFEMForceField::sumCorners(VecDeriv& f) const {
  for (std::size_t e = 0; e < m_triangles.size(); ++e)
    for (int i = 0; i < 3; ++i) f[m_triangles[e][i]] += m_corners[3 * e + i];
}

void TriangularFEMForceField::addForce(const MechanicalParams&, VecDeriv& f, const VecCoord& x,
                                       const VecDeriv&) {
  if (!refresh()) return;
  node()->threadPool().parallelFor(
      m_triangles.size(), kGrain, [this, &x](std::size_t begin, std::size_t end) {
        const fem::TriangleMethod m = method();
        for (std::size_t e = begin; e < end; ++e) {
          const fem::TriangleVectors c = corners(x, e);
          m_rotations[e] = fem::computeTriangleRotation(m, m_constants[e], c, m_rotations[e]);
          const fem::TriangleVectors force =
              fem::computeTriangleForce(m_constants[e], m_rotations[e], c);
          for (int i = 0; i < 3; ++i) m_corners[3 * e + i] = force.col(i);
        }
      });
  sumCorners(f);
}

void TriangularFEMForceField::addDForce(const MechanicalParams& mp, VecDeriv& df,
                                        const VecDeriv& dx) {
  if (!m_ready || mp.kFactor == 0) return;
  m_kFactor = mp.kFactor;
  node()->threadPool().parallelFor(
      m_triangles.size(), 4 * kGrain, [this, &dx](std::size_t begin, std::size_t end) {
        for (std::size_t e = begin; e < end; ++e) {
          const fem::TriangleVectors d =
              fem::computeTriangleDForce(m_constants[e], m_rotations[e], corners(dx, e));
          for (int i = 0; i < 3; ++i) m_corners[3 * e + i] = m_kFactor * d.col(i);
        }
      });
  sumCorners(df);
}

void TriangularFEMForceField::addKToMatrix(const MechanicalParams& mp, MatrixAccumulator& matrix,
                                           std::size_t offset) {
  if (!m_ready || mp.kFactor == 0) return;
  std::array<std::size_t, 3> offsets{};
  for (std::size_t e = 0; e < m_triangles.size(); ++e) {
    for (int i = 0; i < 3; ++i) offsets[i] = offset + 3 * std::size_t{m_triangles[e][i]};
    const fem::Matrix9d K = fem::computeTriangleStiffness(m_constants[e], m_rotations[e]);
    matrix.addBlocks(offsets, K, -mp.kFactor);
  }
}

double TriangularFEMForceField::potentialEnergy(const MechanicalParams&, const VecCoord& x) const {
  if (!m_ready) return 0;
  double energy = 0;
  for (std::size_t e = 0; e < m_triangles.size(); ++e) {
    const fem::TriangleVectors c = corners(x, e);
    const Eigen::Matrix3d R =
        fem::computeTriangleRotation(method(), m_constants[e], c, m_rotations[e]);
    energy += fem::computeTriangleEnergy(m_constants[e], R, c);
  }
  return energy;
}

}  // namespace stroma
