// SPDX-License-Identifier: MIT
#include "HybridDomainDecompositionSolver.h"

#include <sstream>

#include "ConvergenceReport.h"
#include "core/Message.h"
#include "core/Node.h"
#include "simulation/MechanicalOperations.h"
#include "simulation/NodalForces.h"
#include "simulation/VecId.h"

namespace stroma {

using namespace domaindecomposition;

namespace {

const char* keyword(ZoneModel model) {
  return model == ZoneModel::precomputed ? "precomputed" : "tensorMass";
}

}  // namespace

void HybridDomainDecompositionSolver::init() {
  OdeSolver::init();
  m_ready = false;
  ElasticProblem problem;
  std::vector<int> zoneOfElement;
  std::vector<ZoneModel> models;
  Loads loads;
  int zoneCount = 0;
  if (!readProblem(problem) || !readPartition(problem, zoneOfElement, zoneCount) ||
      !readZoneModels(zoneCount, models) || !readLoads(loads)) {
    setInvalid();
    return;
  }
  DecompositionOptions options;
  options.iteration = d_interfaceIteration.value();
  options.tensorMassSolve = d_tensorMassSolve.value();
  options.relaxationSteps = d_relaxationSteps.value();
  options.relaxationDamping = d_relaxationDamping.value();
  std::string error;
  if (!m_hybrid.setup(problem, zoneOfElement, models, loads, options, error)) {
    msgError(error, "zoneModels");
    setInvalid();
    return;
  }
  m_revision = m_topology->revision();
  m_loadVersion = d_forces.version() + d_forceIndices.version() + d_imposedIndices.version() +
                  d_imposedDisplacements.version();
  d_storedTensors.setValue(static_cast<int>(m_hybrid.storedTensors()));
  publishZoneModels();
  m_ready = true;

  if (!d_convergenceReport.value().empty()) {
    ConvergenceStudy study{problem, zoneOfElement, models,
                           loads,   options,       d_reportIterations.value()};
    std::string summary;
    if (!writeConvergenceReport(study, d_convergenceReport.value(), summary, error))
      msgWarning("convergence report not written: " + error, "convergenceReport");
    else
      msgInfo(summary);
  }
}

bool HybridDomainDecompositionSolver::readProblem(ElasticProblem& problem) {
  m_topology = findTetrahedralTopology(*this, l_topology);
  if (!m_topology) return false;
  m_state = node() ? node()->template get<MechanicalState<Vec3Types>>() : nullptr;
  if (!m_state) {
    msgError("no Vec3d mechanical state in this node to move: add a MechanicalObject");
    return false;
  }
  m_rest = m_state->readCoord(VecId::restPosition());
  if (m_rest.size() < m_topology->nbPoints()) {
    msgError("the mechanical state has " + std::to_string(m_rest.size()) +
                 " points; the topology uses " + std::to_string(m_topology->nbPoints()),
             "topology");
    return false;
  }
  problem.points.assign(m_rest.begin(), m_rest.end());
  for (const Tetrahedron& t : m_topology->tetrahedra())
    problem.tetrahedra.push_back({t[0], t[1], t[2], t[3]});
  problem.youngModulus = d_youngModulus.value();
  problem.poissonRatio = d_poissonRatio.value();
  if (problem.youngModulus <= 0 || problem.poissonRatio <= -1 || problem.poissonRatio >= 0.5) {
    msgError("the material needs youngModulus > 0 and -1 < poissonRatio < 0.5",
             problem.youngModulus <= 0 ? "youngModulus" : "poissonRatio");
    return false;
  }
  for (unsigned p : d_fixedIndices.value()) {
    if (p >= m_rest.size()) {
      msgError("fixed node " + std::to_string(p) + " is out of range (" +
                   std::to_string(m_rest.size()) + " points)",
               "fixedIndices");
      return false;
    }
    problem.fixedNodes.push_back(static_cast<int>(p));
  }
  return true;
}

bool HybridDomainDecompositionSolver::readPartition(const ElasticProblem& problem,
                                                    std::vector<int>& zoneOfElement,
                                                    int& zoneCount) {
  std::string field;
  switch (d_partition.value()) {
    case ZonePartitionSource::list: {
      field = "elementZones";
      zoneOfElement = d_elementZones.value();
      zoneCount = 0;
      for (int z : zoneOfElement) zoneCount = std::max(zoneCount, z + 1);
      break;
    }
    case ZonePartitionSource::groups: {
      field = "elementGroups";
      const std::vector<int>& groups = d_elementGroups.value();
      if (groups.size() != problem.tetrahedra.size()) {
        msgError("expected one group per tetrahedron of " + m_topology->path() + " (" +
                     std::to_string(problem.tetrahedra.size()) + "), got " +
                     std::to_string(groups.size()),
                 field);
        return false;
      }
      zoneOfElement = zonesFromGroups(groups, zoneCount);
      break;
    }
    case ZonePartitionSource::boxes: {
      field = "zoneBoxes";
      std::vector<Box> boxes;
      for (const Vec6d& b : d_zoneBoxes.value()) boxes.push_back(b);
      zoneOfElement = partitionFromBoxes(problem.points, problem.tetrahedra, boxes);
      zoneCount = static_cast<int>(boxes.size());
      break;
    }
    case ZonePartitionSource::metis: {
      field = "zoneCount";
      zoneCount = d_zoneCount.value();
      std::string error;
      zoneOfElement =
          partitionWithMetis(problem.tetrahedra, problem.points.size(), zoneCount, error);
      if (zoneOfElement.empty()) {
        msgError(error, field);
        return false;
      }
      break;
    }
  }
  const std::string error = checkPartition(zoneOfElement, problem.tetrahedra.size(), zoneCount);
  if (!error.empty()) {
    msgError("the partition of " + m_topology->path() + ": " + error, field);
    return false;
  }
  return true;
}

bool HybridDomainDecompositionSolver::readZoneModels(int zoneCount,
                                                     std::vector<ZoneModel>& models) {
  std::istringstream words(d_zoneModels.value());
  std::string word;
  while (words >> word) {
    if (word == "precomputed")
      models.push_back(ZoneModel::precomputed);
    else if (word == "tensorMass")
      models.push_back(ZoneModel::tensorMass);
    else {
      msgError("unknown zone model '" + word + "': expected precomputed or tensorMass",
               "zoneModels");
      return false;
    }
  }
  if (models.size() == 1) models.assign(zoneCount, models.front());
  if (static_cast<int>(models.size()) != zoneCount) {
    msgError(std::to_string(models.size()) + " zone models for " + std::to_string(zoneCount) +
                 " zones: give one keyword for all, or one per zone",
             "zoneModels");
    return false;
  }
  return true;
}

bool HybridDomainDecompositionSolver::readLoads(Loads& loads) {
  if (d_forceIndices.value().size() != d_forces.value().size()) {
    msgError(std::to_string(d_forces.value().size()) + " forces for " +
                 std::to_string(d_forceIndices.value().size()) + " forceIndices",
             "forces");
    return false;
  }
  if (d_imposedIndices.value().size() != d_imposedDisplacements.value().size()) {
    msgError(std::to_string(d_imposedDisplacements.value().size()) + " displacements for " +
                 std::to_string(d_imposedIndices.value().size()) + " imposedIndices",
             "imposedDisplacements");
    return false;
  }
  for (unsigned p : d_forceIndices.value()) loads.forceNodes.push_back(static_cast<int>(p));
  for (unsigned p : d_imposedIndices.value()) loads.imposedNodes.push_back(static_cast<int>(p));
  loads.forces.assign(d_forces.value().begin(), d_forces.value().end());
  if (d_forceIndices.value().empty()) {
    loads.forceNodes = m_fieldForceNodes;
    loads.forces.assign(m_fieldForces.begin(), m_fieldForces.end());
  }
  loads.imposedDisplacements.assign(d_imposedDisplacements.value().begin(),
                                    d_imposedDisplacements.value().end());
  return true;
}

void HybridDomainDecompositionSolver::followCuts() {
  if (m_topology->revision() == m_revision) return;
  const auto changes = m_topology->changesSince(m_revision);
  m_revision = m_topology->revision();
  if (!changes) {
    msgWarning(
        "the topology changed in a way other than removals (or too many at once): the "
        "hybrid model stops following it",
        "topology");
    m_ready = false;
    return;
  }
  for (const TopologyChange& change : *changes) {
    std::vector<int> removed(change.tetrahedra.removed.begin(), change.tetrahedra.removed.end());
    std::vector<int> converted;
    std::string error;
    if (!m_hybrid.removeTetrahedra(removed, converted, error)) {
      msgWarning("after a cut: " + error + "; the hybrid model stops", "topology");
      m_ready = false;
      return;
    }
    for (int z : converted)
      msgInfo("zone " + std::to_string(z) + " was cut: precomputed -> tensor-mass");
  }
  d_storedTensors.setValue(static_cast<int>(m_hybrid.storedTensors()));
  publishZoneModels();
}

void HybridDomainDecompositionSolver::publishZoneModels() {
  std::string text;
  for (int z = 0; z < m_hybrid.zoneCount(); ++z)
    text += std::string(z ? " " : "") + keyword(m_hybrid.zoneModel(z));
  d_currentZoneModels.setValue(text);
}

bool HybridDomainDecompositionSolver::readFieldLoads(MechanicalOperations& mop, double dt) {
  NodalForces loads = readNodalForces(mop, *m_state, dt);
  const bool changed = loads.points != m_fieldForceNodes || loads.forces != m_fieldForces;
  m_fieldForceNodes = std::move(loads.points);
  m_fieldForces = std::move(loads.forces);
  return changed;
}

void HybridDomainDecompositionSolver::solve(MechanicalOperations& mop, double dt) {
  if (!m_ready) return;
  followCuts();
  if (!m_ready) return;
  // Without forceIndices the forces are those of the node's force fields (a ConstantForceField
  // on the tip, as for any solver), read at every step.
  const bool fieldLoads = d_forceIndices.value().empty() && readFieldLoads(mop, dt);
  const std::uint64_t loadVersion = d_forces.version() + d_forceIndices.version() +
                                    d_imposedIndices.version() + d_imposedDisplacements.version();
  if (loadVersion != m_loadVersion || fieldLoads) {
    m_loadVersion = loadVersion;
    Loads loads;
    std::string error;
    if (!readLoads(loads) || !m_hybrid.setLoads(loads, error)) {
      if (!error.empty()) msgWarning("new loads refused: " + error, "forces");
      m_ready = false;
      return;
    }
  }
  IterationReport report;
  for (int i = 0; i < d_iterationsPerStep.value(); ++i) report = m_hybrid.iterate();
  d_interfaceResidual.setValue(report.interfaceChange);
  d_forceResidual.setValue(report.forceResidual);
  if (d_printLog.value())
    msgInfo("interface residual " + formatNumber(report.interfaceChange) + " m, force residual " +
            formatNumber(report.forceResidual) + " N");

  // x = rest + u, at rest in the quasi-static sense.
  const Eigen::VectorXd& u = m_hybrid.displacement();
  std::vector<Vec3d>& x = m_state->writeCoord(VecId::position());
  for (std::size_t p = 0; p < x.size() && 3 * p + 2 < static_cast<std::size_t>(u.size()); ++p)
    x[p] = m_rest[p] + u.segment<3>(3 * p);
  std::vector<Vec3d>& v = m_state->writeDeriv(VecId::velocity());
  for (Vec3d& vp : v) vp.setZero();
}

}  // namespace stroma
