// SPDX-License-Identifier: MIT
#include "PrecomputedLinearModel.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>

#include "core/IndexChecks.h"
#include "Precomputed/kernels/BasisCache.h"
#include "Precomputed/kernels/LinearStiffnessAssembly.h"
#include "SolidMechanics/kernels/IsotropicMaterial.h"
#include "core/Message.h"
#include "core/Node.h"
#include "simulation/Constraints.h"
#include "simulation/MechanicalOperations.h"
#include "simulation/NodalForces.h"
#include "simulation/ProjectiveConstraint.h"

namespace stroma {

namespace {

std::string defaultCachePath(std::uint64_t key) {
  char name[40];
  std::snprintf(name, sizeof name, "%016llx.basis", static_cast<unsigned long long>(key));
  std::error_code ec;
  std::filesystem::path dir = std::filesystem::temp_directory_path(ec);
  if (ec) dir = ".";
  return (dir / "stroma-precomputed" / name).string();
}

}  // namespace

void PrecomputedLinearModel::init() {
  if (!node()) return;
  m_state = node()->template get<MechanicalState<Vec3Types>>();
  if (!m_state) {
    msgError("needs a MechanicalObject (Vec3d) in its node");
    return;
  }
  if (!fem::isValidIsotropicMaterial(d_youngModulus.value(), d_poissonRatio.value())) {
    msgError("youngModulus = " + formatNumber(d_youngModulus.value()) +
                 " Pa and poissonRatio = " + formatNumber(d_poissonRatio.value()) +
                 " are not a valid material: expected youngModulus > 0 and -1 < poissonRatio "
                 "< 0.5",
             d_poissonRatio.value() >= 0.5 || d_poissonRatio.value() <= -1 ? "poissonRatio"
                                                                           : "youngModulus");
    return;
  }
  checkImposed();
}

bool PrecomputedLinearModel::checkImposed() {
  const size_t m = d_imposedIndices.value().size();
  const size_t keys = d_keyTimes.value().size();
  const size_t given = d_imposedDisplacements.value().size();
  const size_t expected = keys == 0 ? m : keys * m;
  if (given != expected) {
    msgError(std::to_string(given) + " imposed displacements for " + std::to_string(m) +
                 " imposedIndices and " + std::to_string(keys) + " keyTimes: expected " +
                 std::to_string(expected),
             "imposedDisplacements");
    return false;
  }
  const auto& times = d_keyTimes.value();
  for (size_t i = 1; i < times.size(); ++i)
    if (!(times[i] > times[i - 1])) {
      msgError("keyTimes must increase (key " + std::to_string(i) + ": " + formatNumber(times[i]) +
                   " after " + formatNumber(times[i - 1]) + ")",
               "keyTimes");
      return false;
    }
  return true;
}

bool PrecomputedLinearModel::collectFixedDofs(std::vector<int>& fixedDofs) {
  const auto n = m_state->size();
  if (!d_fixedIndices.value().empty()) {
    if (!reportIndicesOutOfRange(*this, d_fixedIndices.value(), n, "fixedIndices")) return false;
    for (unsigned i : d_fixedIndices.value())
      for (int c = 0; c < 3; ++c) fixedDofs.push_back(3 * int(i) + c);
  } else {
    std::vector<std::size_t> rows;
    for (BaseProjectiveConstraint* constraint : node()->template getAll<BaseProjectiveConstraint>())
      if (constraint->state() == m_state) constraint->fixedRows(rows);
    for (std::size_t row : rows)
      if (row < 3 * n) fixedDofs.push_back(int(row));
  }
  std::sort(fixedDofs.begin(), fixedDofs.end());
  fixedDofs.erase(std::unique(fixedDofs.begin(), fixedDofs.end()), fixedDofs.end());
  if (fixedDofs.empty()) {
    msgError(
        "no fixed node: the stiffness is singular (free rigid motions); give "
        "fixedIndices or a FixedProjectiveConstraint in the node",
        "fixedIndices");
    return false;
  }
  m_fixedNode.assign(n, 0);
  std::vector<int> count(n, 0);
  for (int dof : fixedDofs)
    if (++count[size_t(dof / 3)] == 3) m_fixedNode[size_t(dof / 3)] = 1;
  return true;
}

bool PrecomputedLinearModel::collectBasisNodes(std::vector<int>& basisNodes) {
  const auto n = m_state->size();
  if (!d_basisIndices.value().empty()) {
    if (!reportIndicesOutOfRange(*this, d_basisIndices.value(), n, "basisIndices")) return false;
    basisNodes.assign(d_basisIndices.value().begin(), d_basisIndices.value().end());
  } else {
    for (const Triangle& t : l_topology->boundaryTriangles())
      for (Index i : t)
        if (i < n && !m_fixedNode[i]) basisNodes.push_back(int(i));
  }
  std::sort(basisNodes.begin(), basisNodes.end());
  basisNodes.erase(std::unique(basisNodes.begin(), basisNodes.end()), basisNodes.end());
  for (unsigned i : d_imposedIndices.value())
    if (!std::binary_search(basisNodes.begin(), basisNodes.end(), int(i))) {
      msgError("imposed node " + std::to_string(i) +
                   " is not a basis node (an interior or fully fixed node, or one missing "
                   "from basisIndices)",
               "imposedIndices");
      return false;
    }
  return true;
}

bool PrecomputedLinearModel::findTopology() {
  // The last topology of the node holding tetrahedra: a grid split by Hexa2TetraTopologicalMapping
  // fills its tetrahedra container at the mapping's init, which is why this waits for bwdInit.
  if (!l_topology)
    for (Topology* topology : node()->template getAll<Topology>())
      if (!topology->tetrahedra().empty()) l_topology.set(topology);
  if (!l_topology || l_topology->tetrahedra().empty()) {
    msgError("needs a topology with tetrahedra in its node, or a 'topology' link", "topology");
    return false;
  }
  return true;
}

void PrecomputedLinearModel::bwdInit() {
  if (!isValid() || !m_state || !findTopology()) return;
  std::vector<int> fixedDofs, basisNodes;
  if (!collectFixedDofs(fixedDofs) || !collectBasisNodes(basisNodes)) return;
  buildBasis(fixedDofs, basisNodes);
  if (!m_basis) return;
  // Step scratch, sized once.
  m_u.resize(m_basis->columns().rows());
  m_imposedNodes.clear();
  for (unsigned i : d_imposedIndices.value()) m_imposedNodes.push_back(int(i));
  m_imposed.resize(m_imposedNodes.size());
  m_reactions.reserve(m_imposedNodes.size());
  m_forceNodes.reserve(m_basis->basisNodes().size());
  m_forces.reserve(m_basis->basisNodes().size());
}

void PrecomputedLinearModel::buildBasis(const std::vector<int>& fixedDofs,
                                        const std::vector<int>& basisNodes) {
  const auto& rest = m_state->readCoord(VecId::restPosition());
  const auto& tetrahedra = l_topology->tetrahedra();
  // Rows kept: every node, or the surface (and basis) nodes only.
  std::vector<int> rowNodes;
  if (d_deformedRegion.value() == DeformedRegion::all) {
    for (int i = 0; i < int(rest.size()); ++i) rowNodes.push_back(i);
  } else {
    rowNodes = basisNodes;
    for (const Triangle& t : l_topology->boundaryTriangles())
      for (Index i : t)
        if (i < rest.size()) rowNodes.push_back(int(i));
    std::sort(rowNodes.begin(), rowNodes.end());
    rowNodes.erase(std::unique(rowNodes.begin(), rowNodes.end()), rowNodes.end());
  }
  const double E = d_youngModulus.value(), nu = d_poissonRatio.value();
  const std::uint64_t key =
      precomputed::computeBasisKey(rest, tetrahedra, E, nu, fixedDofs, basisNodes, rowNodes);
  const std::string path =
      d_cacheFile.value().empty() ? defaultCachePath(key) : d_cacheFile.value();

  std::string error;
  if (d_useCache.value()) {
    if (auto loaded = precomputed::readBasisCache(path, key, error)) {
      m_basis = std::make_unique<precomputed::DeformationBasis>(std::move(*loaded));
      d_loadedFromCache.setValue(true);
      d_storedBytes.setValue(double(precomputed::basisCacheBytes(*m_basis)));
      msgInfo("deformation basis loaded from '" + path + "' (" +
              std::to_string(m_basis->basisNodes().size()) + " basis nodes)");
      return;
    }
    // A missing file is the normal first run; anything else is worth a warning.
    if (std::filesystem::exists(path))
      msgWarning("cache not used: " + error + "; the basis is recomputed and rewritten",
                 "cacheFile");
  }

  const auto start = std::chrono::steady_clock::now();
  precomputed::SparseMatrix K;
  if (!precomputed::assembleLinearStiffness(rest, tetrahedra, E, nu, K, error)) {
    msgError(error, "topology");
    return;
  }
  auto basis = precomputed::DeformationBasis::compute(K, fixedDofs, basisNodes, error);
  if (basis && d_deformedRegion.value() == DeformedRegion::surface)
    basis = basis->restrictedTo(rowNodes, error);
  if (!basis) {
    msgError(error, "fixedIndices");
    return;
  }
  m_basis = std::make_unique<precomputed::DeformationBasis>(std::move(*basis));
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  d_loadedFromCache.setValue(false);
  d_precomputationTime.setValue(seconds);
  d_storedBytes.setValue(double(precomputed::basisCacheBytes(*m_basis)));
  std::string where = "not cached";
  if (d_useCache.value()) {
    if (precomputed::writeBasisCache(path, key, *m_basis, error))
      where = "written to '" + path + "'";
    else
      msgWarning("the basis could not be cached: " + error, "cacheFile");
  }
  msgInfo("deformation basis computed in " + formatNumber(seconds) + " s (" +
          std::to_string(m_basis->basisNodes().size()) + " basis nodes, " +
          formatNumber(d_storedBytes.value() / 1e6) + " MB), " + where);
}

void PrecomputedLinearModel::imposedAt(double t) {
  const auto& values = d_imposedDisplacements.value();
  const auto& times = d_keyTimes.value();
  const size_t m = m_imposedNodes.size();
  if (times.empty()) {
    std::copy(values.begin(), values.end(), m_imposed.begin());
    return;
  }
  // Linear between the two key times around t; the end values outside.
  size_t key = 0;
  while (key + 1 < times.size() && times[key + 1] <= t) ++key;
  if (t <= times.front() || key + 1 == times.size()) {
    std::copy_n(values.begin() + long(key * m), m, m_imposed.begin());
    return;
  }
  const double s = (t - times[key]) / (times[key + 1] - times[key]);
  for (size_t i = 0; i < m; ++i)
    m_imposed[i] = (1 - s) * values[key * m + i] + s * values[(key + 1) * m + i];
}

void PrecomputedLinearModel::solve(MechanicalOperations& mop, double dt) {
  if (!m_basis || !m_state) return;
  // The basis belongs to the mesh it was computed on: a state that changed size (a topology
  // change) cannot use it.
  if (m_state->size() != static_cast<std::size_t>(m_basis->nodeCount())) {
    if (!m_warnedSolve)
      msgWarning("the state has " + std::to_string(m_state->size()) + " points, the basis " +
                 std::to_string(m_basis->nodeCount()) + ": positions left unchanged");
    m_warnedSolve = true;
    return;
  }
  // Loads: the forces of the node's force fields now, kept where they fall on basis nodes.
  NodalForces& loads = m_loads;
  readNodalForces(mop, *m_state, dt, loads);
  m_forceNodes.clear();
  m_forces.clear();
  for (std::size_t k = 0; k < loads.points.size(); ++k) {
    const int i = loads.points[k];
    if (m_basis->basisIndex(i) >= 0) {
      m_forceNodes.push_back(i);
      m_forces.push_back(loads.forces[k]);
    } else if (!m_fixedNode[std::size_t(i)] && !m_warnedForce) {
      m_warnedForce = true;
      msgWarning("a force on node " + std::to_string(i) +
                     ", not a basis node, is ignored (and any other such force): add the node "
                     "to basisIndices",
                 "basisIndices");
    }
  }

  // The imposed set may change while running (a tool grasping other nodes): the kernel
  // refactorises the imposed compliance when it does.
  const auto& indices = d_imposedIndices.value();
  if (!std::equal(indices.begin(), indices.end(), m_imposedNodes.begin(), m_imposedNodes.end())) {
    m_imposedNodes.assign(indices.begin(), indices.end());
    m_imposed.resize(m_imposedNodes.size());
  }
  const size_t keys = std::max<size_t>(1, d_keyTimes.value().size());
  if (d_imposedDisplacements.value().size() != keys * m_imposedNodes.size()) {
    if (!m_warnedSolve)
      msgWarning("step not solved, positions unchanged: " +
                     std::to_string(d_imposedDisplacements.value().size()) +
                     " imposed displacements for " + std::to_string(m_imposedNodes.size()) +
                     " imposedIndices and " + std::to_string(d_keyTimes.value().size()) +
                     " keyTimes",
                 "imposedDisplacements");
    m_warnedSolve = true;
    return;
  }

  // u by superposition, through the imposed nodes' compliance when there are some.
  std::string error;
  bool solved;
  if (m_imposedNodes.empty()) {
    solved = m_basis->displacementFromForces(m_forceNodes, m_forces, m_u, error);
  } else {
    imposedAt(mop.endTime());
    solved = m_basis->displacementFromImposed(m_imposedNodes, m_imposed, m_u, m_reactions, error,
                                              m_forceNodes, m_forces);
  }
  if (!solved) {
    if (!m_warnedSolve) msgWarning("step not solved, positions unchanged: " + error);
    m_warnedSolve = true;
    return;
  }

  // x = rest + u on the row nodes; the others stay at rest. Static: no velocity.
  const auto& rest = m_state->readCoord(VecId::restPosition());
  auto& x = m_state->writeCoord(VecId::position());
  const auto& rows = m_basis->rowNodes();
  for (size_t r = 0; r < rows.size(); ++r)
    x[size_t(rows[r])] = rest[size_t(rows[r])] + m_u.segment<3>(3 * Eigen::Index(r));
  for (auto& v : m_state->writeDeriv(VecId::velocity())) v.setZero();
  if (!m_imposedNodes.empty()) d_reactionForces.setValue(m_reactions);
  mop.propagate(VecId::position(), VecId::velocity());
}

bool PrecomputedLinearModel::constraintResponse(double dt, ConstraintResponse& response) const {
  // Quasi-static: K dx = f_c, the positions take the whole response at once, no velocity.
  response.matrix = MechanicalParams{};
  response.matrix.dt = dt;
  response.matrix.mFactor = 0.0;
  response.matrix.kFactor = -1.0;
  response.positionFactor = 1.0;
  response.velocityFactor = 0.0;
  return true;
}

}  // namespace stroma
