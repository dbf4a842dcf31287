// SPDX-License-Identifier: MIT
#include "DomainDecomposition/kernels/HybridDecomposition.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numeric>

#include "DomainDecomposition/kernels/CondensedInterface.h"
#include "DomainDecomposition/kernels/SingleDomainReference.h"
#include "Precomputed/kernels/LinearStiffnessAssembly.h"
#include "topology/TopologyChange.h"

namespace stroma::domaindecomposition {
namespace {

std::vector<int> sortedUnique(std::vector<int> values) {
  std::sort(values.begin(), values.end());
  values.erase(std::unique(values.begin(), values.end()), values.end());
  return values;
}

}  // namespace

HybridDecomposition::HybridDecomposition() = default;
HybridDecomposition::~HybridDecomposition() = default;

bool HybridDecomposition::setup(const ElasticProblem& problem,
                                const std::vector<int>& zoneOfElement,
                                const std::vector<ZoneModel>& models, const Loads& loads,
                                const DecompositionOptions& options, std::string& error) {
  m_problem = problem;
  m_options = options;
  m_tetrahedra = problem.tetrahedra;
  m_zoneOfElement = zoneOfElement;
  const std::size_t n = problem.points.size();
  const int zoneCount = static_cast<int>(models.size());
  error = checkPartition(zoneOfElement, m_tetrahedra.size(), zoneCount);
  if (!error.empty()) return false;
  m_fixed.assign(n, 0);
  for (int p : problem.fixedNodes) {
    if (p < 0 || static_cast<std::size_t>(p) >= n) {
      error = "fixed node " + std::to_string(p) + " is out of range [0, " + std::to_string(n) + ")";
      return false;
    }
    m_fixed[p] = 1;
  }
  assembleGlobal(error);
  if (!error.empty()) return false;

  const auto nodes = computeZoneNodes(m_tetrahedra, m_zoneOfElement, zoneCount, n);
  m_zones.clear();
  m_zones.resize(zoneCount);
  for (int z = 0; z < zoneCount; ++z) {
    m_zones[z].model = models[z];
    m_zones[z].nodes = nodes[z];
  }
  findInterfaces();
  m_u = Eigen::VectorXd::Zero(3 * n);
  if (!checkLoads(loads, error)) return false;
  m_loads = loads;
  m_f = Eigen::VectorXd::Zero(3 * n);
  for (std::size_t i = 0; i < loads.forceNodes.size(); ++i)
    m_f.segment<3>(3 * loads.forceNodes[i]) += loads.forces[i];
  m_imposed.assign(n, 0);
  m_imposedValue.assign(n, Vec3::Zero());
  for (std::size_t i = 0; i < loads.imposedNodes.size(); ++i) {
    m_imposed[loads.imposedNodes[i]] = 1;
    m_imposedValue[loads.imposedNodes[i]] = loads.imposedDisplacements[i];
  }
  if (!checkSingularGroups(error)) return false;
  m_condensed.reset();
  if (options.iteration == InterfaceIteration::schur) {
    for (int z = 0; z < zoneCount; ++z)
      if (models[z] != ZoneModel::precomputed) {
        error = "the condensed (schur) interface needs every zone precomputed; zone " +
                std::to_string(z) + " is tensor-mass (use gaussSeidel or jacobi)";
        return false;
      }
    if (!buildCondensed(error)) return false;
    applyImposed(m_u);
    return true;
  }
  for (int z = 0; z < zoneCount; ++z) {
    const bool built = m_zones[z].model == ZoneModel::precomputed ? buildPrecomputed(z, error)
                                                                  : buildTensorMass(z, error);
    if (!built) return false;
  }
  applyImposed(m_u);
  return true;
}

void HybridDecomposition::assembleGlobal(std::string& error) {
  SparseMatrix K;
  std::vector<precomputed::TetrahedronNodes> tetrahedra(m_tetrahedra.begin(), m_tetrahedra.end());
  if (!precomputed::assembleLinearStiffness(m_problem.points, tetrahedra, m_problem.youngModulus,
                                            m_problem.poissonRatio, K, error))
    return;
  m_K = K;
  m_active.assign(m_problem.points.size(), 0);
  for (const TetrahedronNodes& t : m_tetrahedra)
    for (std::uint32_t p : t) m_active[p] = 1;
}

void HybridDecomposition::findInterfaces() {
  const std::size_t n = m_problem.points.size();
  std::vector<int> zonesAtNode(n, 0);
  m_owner.assign(n, -1);
  for (int z = 0; z < zoneCount(); ++z)
    for (int p : m_zones[z].nodes) {
      ++zonesAtNode[p];
      if (m_owner[p] < 0) m_owner[p] = z;
    }
  m_allInterfaceNodes.clear();
  for (std::size_t p = 0; p < n; ++p)
    if (zonesAtNode[p] > 1) m_allInterfaceNodes.push_back(static_cast<int>(p));
  for (Zone& zone : m_zones) {
    // A converted zone's list is rebuilt; a precomputed zone keeps the one its basis was
    // computed for (its stored data is left as it is).
    if (zone.basis) continue;
    zone.interfaceNodes.clear();
    for (int p : zone.nodes)
      if (zonesAtNode[p] > 1) zone.interfaceNodes.push_back(p);
  }
}

bool HybridDecomposition::checkLoads(const Loads& loads, std::string& error) const {
  const std::size_t n = m_problem.points.size();
  if (loads.forceNodes.size() != loads.forces.size() ||
      loads.imposedNodes.size() != loads.imposedDisplacements.size()) {
    error = "each loaded node needs one force and each imposed node one displacement";
    return false;
  }
  for (const auto* list : {&loads.forceNodes, &loads.imposedNodes})
    for (int p : *list)
      if (p < 0 || static_cast<std::size_t>(p) >= n) {
        error =
            "loaded node " + std::to_string(p) + " is out of range [0, " + std::to_string(n) + ")";
        return false;
      }
  for (int p : loads.imposedNodes)
    if (m_fixed[p]) {
      error = "node " + std::to_string(p) + " is both fixed and given an imposed displacement";
      return false;
    }
  if (sortedUnique(loads.imposedNodes).size() != loads.imposedNodes.size()) {
    error = "a node is given two imposed displacements";
    return false;
  }
  return true;
}

bool HybridDecomposition::checkSingularGroups(std::string& error) const {
  // Zones connected through shared nodes form groups; each needs a node held in place.
  const int count = zoneCount();
  std::vector<int> group(count);
  std::iota(group.begin(), group.end(), 0);
  const auto root = [&group](int z) {
    while (group[z] != z) z = group[z] = group[group[z]];
    return z;
  };
  std::vector<int> zoneAtNode(m_problem.points.size(), -1);
  for (int z = 0; z < count; ++z)
    for (int p : m_zones[z].nodes) {
      if (zoneAtNode[p] >= 0) group[root(z)] = root(zoneAtNode[p]);
      zoneAtNode[p] = z;
    }
  std::vector<char> held(count, 0);
  for (int z = 0; z < count; ++z)
    for (int p : m_zones[z].nodes)
      if (m_fixed[p] || m_imposed[p]) held[root(z)] = 1;
  for (int r = 0; r < count; ++r) {
    if (root(r) != r || held[r]) continue;
    std::vector<int> members;
    for (int z = 0; z < count; ++z)
      if (root(z) == r) members.push_back(z);
    error = "zone" + std::string(members.size() > 1 ? "s " : " ") + describeList(members) +
            " (connected) have no fixed node and no imposed displacement, only forces: their "
            "stiffness is singular (fix nodes or impose a displacement there)";
    return false;
  }
  return true;
}

bool HybridDecomposition::buildPrecomputed(int z, std::string& error) {
  Zone& zone = m_zones[z];
  const std::size_t n = m_problem.points.size();
  std::vector<int> local(n, -1);
  for (std::size_t i = 0; i < zone.nodes.size(); ++i) local[zone.nodes[i]] = static_cast<int>(i);
  // Basis nodes: the interface (forces from the neighbours) and the loaded nodes of the zone.
  std::vector<int> basisNodes;
  for (int p : zone.interfaceNodes) basisNodes.push_back(local[p]);
  for (const auto* list : {&m_loads.forceNodes, &m_loads.imposedNodes})
    for (int p : *list)
      if (local[p] >= 0) basisNodes.push_back(local[p]);
  basisNodes = sortedUnique(basisNodes);
  // The block over N and the ring R of neighbour nodes coupled to it, R fixed: the basis of
  // K_F is then that of A = K[N, N] (DeformationBasis.h), restricted to the rows of N.
  std::vector<int> extended = zone.nodes;
  for (int p : zone.interfaceNodes)
    for (int c = 0; c < 3; ++c)
      for (RowMajorMatrix::InnerIterator it(m_K, 3 * p + c); it; ++it)
        if (local[it.col() / 3] < 0) {
          local[it.col() / 3] = static_cast<int>(extended.size());
          extended.push_back(static_cast<int>(it.col() / 3));
        }
  std::vector<int> fixedDofs;
  for (std::size_t i = 0; i < extended.size(); ++i)
    if (i >= zone.nodes.size() || m_fixed[extended[i]])
      for (int c = 0; c < 3; ++c) fixedDofs.push_back(static_cast<int>(3 * i) + c);
  const SparseMatrix K = extractNodeBlock(m_K, extended, n);
  std::vector<int> rows(zone.nodes.size());
  std::iota(rows.begin(), rows.end(), 0);
  std::string why;
  const auto full = precomputed::DeformationBasis::compute(K, fixedDofs, basisNodes, why);
  if (full) zone.basis = full->restrictedTo(rows, why);
  if (!full || !zone.basis) {
    error = "zone " + std::to_string(z) + " (precomputed): " + why;
    return false;
  }
  for (std::size_t i = zone.nodes.size(); i < extended.size(); ++i) local[extended[i]] = -1;
  // The interface rows of A as they are now, for the lagged correction after a cut.
  std::vector<Eigen::Triplet<double>> entries;
  for (std::size_t k = 0; k < zone.interfaceNodes.size(); ++k)
    for (int c = 0; c < 3; ++c)
      for (RowMajorMatrix::InnerIterator it(m_K, 3 * zone.interfaceNodes[k] + c); it; ++it) {
        const int j = local[it.col() / 3];
        if (j >= 0)
          entries.emplace_back(static_cast<int>(3 * k) + c, 3 * j + it.col() % 3, it.value());
      }
  zone.interfaceRows.resize(3 * zone.interfaceNodes.size(), 3 * zone.nodes.size());
  zone.interfaceRows.setFromTriplets(entries.begin(), entries.end());
  zone.interfaceRowOfBasisNode.assign(basisNodes.size(), -1);
  for (std::size_t b = 0; b < basisNodes.size(); ++b) {
    const int global = zone.nodes[basisNodes[b]];
    const auto it =
        std::lower_bound(zone.interfaceNodes.begin(), zone.interfaceNodes.end(), global);
    if (it != zone.interfaceNodes.end() && *it == global)
      zone.interfaceRowOfBasisNode[b] = static_cast<int>(it - zone.interfaceNodes.begin());
  }
  return true;
}

bool HybridDecomposition::buildTensorMass(int z, std::string& error) {
  Zone& zone = m_zones[z];
  zone.basis.reset();
  zone.interfaceRows.resize(0, 0);
  zone.freeNodes.clear();
  for (int p : zone.nodes)
    if (!m_fixed[p] && !m_imposed[p] && m_active[p]) zone.freeNodes.push_back(p);
  const SparseMatrix A = extractNodeBlock(m_K, zone.freeNodes, m_problem.points.size());
  if (m_options.tensorMassSolve == TensorMassSolve::direct) {
    zone.factor = std::make_unique<Eigen::SimplicialLDLT<SparseMatrix>>(A);
    if (zone.factor->info() != Eigen::Success || (zone.factor->vectorD().array() <= 0).any()) {
      error = "zone " + std::to_string(z) +
              " (tensor-mass): its stiffness is singular (a piece with no fixed node and no "
              "neighbour)";
      return false;
    }
    return true;
  }
  // Relaxation: lumped fictitious mass (unit density) and the largest stable step of the
  // damped explicit scheme, from Gershgorin's bound on the eigenvalues of M^-1 A.
  std::vector<double> mass(m_problem.points.size(), 0.0);
  for (const TetrahedronNodes& t : m_tetrahedra) {
    const Vec3& x0 = m_problem.points[t[0]];
    const double volume =
        std::abs((m_problem.points[t[1]] - x0)
                     .dot((m_problem.points[t[2]] - x0).cross(m_problem.points[t[3]] - x0))) /
        6.0;
    for (std::uint32_t p : t) mass[p] += volume / 4.0;
  }
  zone.inverseMass.resize(zone.freeNodes.size());
  double largest = 0;
  for (std::size_t i = 0; i < zone.freeNodes.size(); ++i) {
    zone.inverseMass[i] = 1.0 / mass[zone.freeNodes[i]];
    for (int c = 0; c < 3; ++c)
      largest = std::max(largest,
                         A.col(static_cast<int>(3 * i) + c).cwiseAbs().sum() * zone.inverseMass[i]);
  }
  zone.timeStep = largest > 0 ? 1.9 / std::sqrt(largest) : 0.0;
  zone.velocity = Eigen::VectorXd::Zero(3 * zone.freeNodes.size());
  return true;
}

bool HybridDecomposition::buildCondensed(std::string& error) {
  std::vector<std::vector<int>> nodes;
  for (const Zone& zone : m_zones) nodes.push_back(zone.nodes);
  m_condensed = std::make_unique<CondensedInterface>();
  return m_condensed->setup(m_K, nodes, m_fixed, m_loads.imposedNodes, m_loads.forceNodes, error);
}

bool HybridDecomposition::setLoads(const Loads& loads, std::string& error) {
  if (!checkLoads(loads, error)) return false;
  const std::size_t n = m_problem.points.size();
  std::vector<char> imposed(n, 0);
  for (int p : loads.imposedNodes) imposed[p] = 1;
  const bool imposedSetChanged = imposed != m_imposed;
  m_imposed = imposed;
  m_imposedValue.assign(n, Vec3::Zero());
  for (std::size_t i = 0; i < loads.imposedNodes.size(); ++i)
    m_imposedValue[loads.imposedNodes[i]] = loads.imposedDisplacements[i];
  if (!checkSingularGroups(error)) return false;
  m_loads = loads;
  m_f.setZero();
  for (std::size_t i = 0; i < loads.forceNodes.size(); ++i)
    m_f.segment<3>(3 * loads.forceNodes[i]) += loads.forces[i];
  if (m_condensed) {
    if (!buildCondensed(error)) return false;
    applyImposed(m_u);
    return true;
  }
  for (int z = 0; z < zoneCount(); ++z) {
    Zone& zone = m_zones[z];
    if (zone.model == ZoneModel::tensorMass) {
      if (imposedSetChanged && !buildTensorMass(z, error)) return false;
      continue;
    }
    bool missing = false;
    for (const auto* list : {&loads.forceNodes, &loads.imposedNodes})
      for (int p : *list)
        if (std::binary_search(zone.nodes.begin(), zone.nodes.end(), p) &&
            zone.basis->basisIndex(static_cast<int>(
                std::lower_bound(zone.nodes.begin(), zone.nodes.end(), p) - zone.nodes.begin())) <
                0)
          missing = true;
    if (missing && !buildPrecomputed(z, error)) return false;
  }
  applyImposed(m_u);
  return true;
}

void HybridDecomposition::resetDisplacement() {
  m_u.setZero();
  for (Zone& zone : m_zones)
    if (zone.velocity.size()) zone.velocity.setZero();
  applyImposed(m_u);
}

void HybridDecomposition::applyImposed(Eigen::VectorXd& u) const {
  for (std::size_t i = 0; i < m_loads.imposedNodes.size(); ++i)
    u.segment<3>(3 * m_loads.imposedNodes[i]) = m_loads.imposedDisplacements[i];
}

Vec3 HybridDecomposition::rowProduct(int node, const Eigen::VectorXd& u) const {
  Vec3 product;
  for (int c = 0; c < 3; ++c) product[c] = m_K.row(3 * node + c).dot(u);
  return product;
}

IterationReport HybridDecomposition::iterate() {
  m_before = m_u;
  const Eigen::VectorXd& before = m_before;
  if (m_condensed) {
    m_condensed->solve(m_f, m_u);
  } else if (m_options.iteration == InterfaceIteration::gaussSeidel) {
    for (int z = 0; z < zoneCount(); ++z) updateZone(z, m_u);
  } else {
    for (int z = 0; z < zoneCount(); ++z) {
      m_work = before;
      updateZone(z, m_work);
      for (int p : m_zones[z].nodes)
        if (m_owner[p] == z) m_u.segment<3>(3 * p) = m_work.segment<3>(3 * p);
    }
  }
  IterationReport report;
  const auto change = [&](int p) {
    return (m_u.segment<3>(3 * p) - before.segment<3>(3 * p)).norm();
  };
  if (m_allInterfaceNodes.empty()) {
    for (std::size_t p = 0; p < m_problem.points.size(); ++p)
      report.interfaceChange = std::max(report.interfaceChange, change(static_cast<int>(p)));
  } else {
    for (int p : m_allInterfaceNodes)
      report.interfaceChange = std::max(report.interfaceChange, change(p));
  }
  m_residual.noalias() = m_K * m_u;
  m_residual = m_f - m_residual;
  const Eigen::VectorXd& residual = m_residual;
  double sum = 0;
  for (std::size_t p = 0; p < m_problem.points.size(); ++p)
    if (!m_fixed[p] && !m_imposed[p] && m_active[p])
      sum += residual.segment<3>(3 * p).squaredNorm();
  report.forceResidual = std::sqrt(sum);
  return report;
}

void HybridDecomposition::updateZone(int z, Eigen::VectorXd& u) {
  Zone& zone = m_zones[z];
  if (zone.model == ZoneModel::precomputed)
    updatePrecomputed(zone, u);
  else
    updateTensorMass(zone, u);
}

void HybridDecomposition::updatePrecomputed(Zone& zone, Eigen::VectorXd& u) {
  const precomputed::DeformationBasis& basis = *zone.basis;
  // Forces on the basis nodes: the external ones; on the interface, those of the neighbours'
  // elements, f - K[i, R] u_R = f - (K u)_i + (A_stored u_N)_i (eq. 4.16, figure 4.12).
  Zone::Scratch& s = zone.scratch;
  s.uN.resize(3 * zone.nodes.size());
  for (std::size_t i = 0; i < zone.nodes.size(); ++i)
    s.uN.segment<3>(3 * i) = u.segment<3>(3 * zone.nodes[i]);
  s.stored.noalias() = zone.interfaceRows * s.uN;
  s.forceNodes.clear();
  s.imposedNodes.clear();
  s.forces.clear();
  s.imposed.clear();
  const std::vector<int>& basisNodes = basis.basisNodes();
  for (std::size_t b = 0; b < basisNodes.size(); ++b) {
    const int global = zone.nodes[basisNodes[b]];
    if (m_imposed[global]) {
      s.imposedNodes.push_back(basisNodes[b]);
      s.imposed.push_back(m_imposedValue[global]);  // not u's copy: no round-off drift
      continue;
    }
    Vec3 f = m_f.segment<3>(3 * global);
    const int row = zone.interfaceRowOfBasisNode[b];
    if (row >= 0) f += s.stored.segment<3>(3 * row) - rowProduct(global, u);
    s.forceNodes.push_back(basisNodes[b]);
    s.forces.push_back(f);
  }
  std::string error;
  const bool solved =
      s.imposedNodes.empty()
          ? basis.displacementFromForces(s.forceNodes, s.forces, s.local, error)
          : basis.displacementFromImposed(s.imposedNodes, s.imposed, s.local, s.reactions, error,
                                          s.forceNodes, s.forces);
  if (!solved) return;  // sizes are consistent by construction; nothing to update otherwise
  const std::vector<int>& rows = basis.rowNodes();
  for (std::size_t r = 0; r < rows.size(); ++r) {
    const int global = zone.nodes[rows[r]];
    if (!m_fixed[global] && m_active[global]) u.segment<3>(3 * global) = s.local.segment<3>(3 * r);
  }
}

void HybridDecomposition::updateTensorMass(Zone& zone, Eigen::VectorXd& u) {
  const std::size_t m = zone.freeNodes.size();
  Eigen::VectorXd& r = zone.scratch.residual;
  r.resize(3 * m);
  const auto computeResidual = [&] {
    for (std::size_t i = 0; i < m; ++i)
      r.segment<3>(3 * i) =
          m_f.segment<3>(3 * zone.freeNodes[i]) - rowProduct(zone.freeNodes[i], u);
  };
  if (m_options.tensorMassSolve == TensorMassSolve::direct) {
    computeResidual();
    Eigen::VectorXd& du = zone.scratch.correction;
    du = zone.factor->solve(r);
    for (std::size_t i = 0; i < m; ++i) u.segment<3>(3 * zone.freeNodes[i]) += du.segment<3>(3 * i);
    return;
  }
  // Damped explicit steps (symplectic Euler): v += dt M^-1 (f - K u) - damping v; u += dt v.
  const double dt = zone.timeStep;
  for (int step = 0; step < m_options.relaxationSteps; ++step) {
    computeResidual();
    for (std::size_t i = 0; i < m; ++i) {
      auto v = zone.velocity.segment<3>(3 * i);
      v = (1.0 - m_options.relaxationDamping) * v + dt * zone.inverseMass[i] * r.segment<3>(3 * i);
      u.segment<3>(3 * zone.freeNodes[i]) += dt * v;
    }
  }
}

bool HybridDecomposition::removeTetrahedra(const std::vector<int>& removed,
                                           std::vector<int>& converted, std::string& error) {
  converted.clear();
  if (m_condensed) {
    error = "the condensed (schur) interface does not follow cuts: use gaussSeidel or jacobi";
    return false;
  }
  std::vector<Index> indices;
  for (int e : removed) {
    if (e < 0 || indices.size() >= m_tetrahedra.size() ||
        static_cast<std::size_t>(e) >= m_tetrahedra.size() - indices.size()) {
      error = "removed tetrahedron " + std::to_string(e) + " is out of range";
      return false;
    }
    indices.push_back(static_cast<Index>(e));
  }
  // The zones that lose elements, read in the numbering of each removal.
  std::vector<int> zones = m_zoneOfElement;
  std::vector<int> touched;
  for (Index e : indices) {
    touched.push_back(zones[e]);
    applyRemoval(zones, std::span<const Index>(&e, 1));
  }
  applyRemoval(m_tetrahedra, std::span<const Index>(indices));
  m_zoneOfElement = std::move(zones);
  touched = sortedUnique(touched);
  assembleGlobal(error);
  if (!error.empty()) return false;
  const auto nodes =
      computeZoneNodes(m_tetrahedra, m_zoneOfElement, zoneCount(), m_problem.points.size());
  for (int z : touched) {
    Zone& zone = m_zones[z];
    if (zone.model == ZoneModel::precomputed) converted.push_back(z);
    // The zone goes on from the current displacement u: no jump in positions.
    zone.model = ZoneModel::tensorMass;
    zone.basis.reset();
    zone.nodes = nodes[z];
  }
  findInterfaces();
  for (int z : touched)
    if (!buildTensorMass(z, error)) return false;
  return true;
}

const precomputed::DeformationBasis* HybridDecomposition::basis(int zone) const {
  return m_zones[zone].basis ? &*m_zones[zone].basis : nullptr;
}

std::size_t HybridDecomposition::storedTensors() const {
  std::size_t count = m_condensed ? m_condensed->storedTensors() : 0;
  for (const Zone& zone : m_zones)
    if (zone.basis) count += zone.basis->rowNodes().size() * zone.basis->basisNodes().size();
  return count;
}

}  // namespace stroma::domaindecomposition
