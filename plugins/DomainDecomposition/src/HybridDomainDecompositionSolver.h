// SPDX-License-Identifier: MIT
#pragma once

#include <string>
#include <vector>

#include "DomainDecomposition/kernels/HybridDecomposition.h"
#include "core/DataTraits.h"
#include "core/Link.h"
#include "core/StateTypes.h"
#include "simulation/MechanicalState.h"
#include "simulation/Solvers.h"
#include "topology/Topology.h"

namespace stroma {

/// Where the zones come from (the keywords of `partition`).
enum class ZonePartitionSource { list, groups, boxes, metis };
template <>
struct EnumKeywords<ZonePartitionSource> {
  static constexpr std::array<std::string_view, 4> names{"list", "groups", "boxes", "metis"};
};
template <>
struct EnumKeywords<domaindecomposition::InterfaceIteration> {
  static constexpr std::array<std::string_view, 3> names{"gaussSeidel", "jacobi", "schur"};
};
template <>
struct EnumKeywords<domaindecomposition::TensorMassSolve> {
  static constexpr std::array<std::string_view, 2> names{"direct", "relaxation"};
};

/// The hybrid model of seed 000 (chapter 4): the quasi-static linear elastic deformation of the
/// tetrahedra of its node's topology, split into zones that are each precomputed (deformation
/// basis) or tensor-mass, solved zone by zone with `iterationsPerStep` interface iterations per
/// time step (kernels/HybridDecomposition.h has the equations). It moves the node's Vec3d
/// mechanical state to rest + u (velocities zero) and reports how far the interface is from
/// convergence (`interfaceResidual`, `forceResidual`). When the topology loses tetrahedra
/// (TetrahedraRemover), the precomputed zones they belong to become tensor-mass zones from the
/// current state; the other zones keep their bases.
///
/// With `convergenceReport` set, init() also writes the error to the single-domain solution
/// against the iteration count and the wall time, for this decomposition, precomputed alone and
/// tensor-mass alone (ConvergenceReport.h).
class HybridDomainDecompositionSolver final : public OdeSolver {
 public:
  Data<double> d_youngModulus{
      this, "youngModulus", 5000.0, "Young's modulus of the mesh.", {.unit = "Pa", .min = 0.0}};
  Data<double> d_poissonRatio{
      this, "poissonRatio", 0.3, "Poisson's ratio of the mesh.", {.min = -1.0, .max = 0.5}};
  Data<ZonePartitionSource> d_partition{
      this, "partition", ZonePartitionSource::boxes,
      "Where the zones come from: list (elementZones), groups (elementGroups: one zone per "
      "group of the mesh file), boxes (zoneBoxes), metis (zoneCount zones by "
      "METIS_PartMeshDual)."};
  Data<std::vector<int>> d_elementZones{
      this, "elementZones", {}, "Zone of each tetrahedron (nbTetrahedra), partition=\"list\"."};
  Data<std::vector<int>> d_elementGroups{
      this,
      "elementGroups",
      {},
      "Group of each tetrahedron (nbTetrahedra), partition=\"groups\": typically "
      "@loader.tetrahedraPhysicalGroups of a MeshGmshLoader. Each distinct group > 0 is a zone, "
      "in increasing order of the group numbers; 0 means no group (an error)."};
  Data<std::vector<Vec6d>> d_zoneBoxes{
      this,
      "zoneBoxes",
      {},
      "Boxes 'xmin ymin zmin xmax ymax zmax' (nbZones x 6), partition=\"boxes\": a tetrahedron "
      "belongs to the zone of the first box holding its barycentre.",
      {.unit = "m"}};
  Data<int> d_zoneCount{
      this, "zoneCount", 2, "Number of zones, partition=\"metis\".", {.min = 1.0, .max = 1000.0}};
  Data<std::string> d_zoneModels{
      this, "zoneModels", "precomputed",
      "Model of each zone, 'precomputed' or 'tensorMass': one keyword for every zone, or one "
      "per zone separated by spaces (nbZones)."};
  Data<std::vector<unsigned>> d_fixedIndices{
      this, "fixedIndices", {}, "Nodes held at their rest position."};
  Data<std::vector<unsigned>> d_forceIndices{
      this, "forceIndices", {},
      "Nodes loaded by `forces`; empty: the forces of the node's force fields (a "
      "ConstantForceField...), read at every step."};
  Data<std::vector<Vec3d>> d_forces{
      this, "forces", {}, "Force on each of forceIndices (nbForceIndices x 3).", {.unit = "N"}};
  Data<std::vector<unsigned>> d_imposedIndices{
      this, "imposedIndices", {}, "Nodes moved by `imposedDisplacements`."};
  Data<std::vector<Vec3d>> d_imposedDisplacements{
      this,
      "imposedDisplacements",
      {},
      "Displacement of each of imposedIndices from its rest position (nbImposedIndices x 3).",
      {.unit = "m"}};
  Data<domaindecomposition::InterfaceIteration> d_interfaceIteration{
      this, "interfaceIteration", domaindecomposition::InterfaceIteration::gaussSeidel,
      "gaussSeidel (zones in turn, each with its neighbours' newest values; eq. 4.16) or "
      "jacobi (all zones from the previous iterate; eq. 4.2 with nu = 0), or schur (the "
      "condensed interface of eqs. 4.6 and 4.7, every zone precomputed: exact in one "
      "iteration; no cuts)."};
  Data<int> d_iterationsPerStep{this,
                                "iterationsPerStep",
                                10,
                                "Interface iterations per time step: refresh rate against "
                                "convergence.",
                                {.min = 1.0, .max = 1000000.0}};
  Data<domaindecomposition::TensorMassSolve> d_tensorMassSolve{
      this, "tensorMassSolve", domaindecomposition::TensorMassSolve::direct,
      "How a tensor-mass zone solves its block: direct (sparse LDL^T of the zone) or "
      "relaxation (damped explicit steps, the dynamic model used as a solver)."};
  Data<int> d_relaxationSteps{this,
                              "relaxationSteps",
                              1,
                              "Explicit steps of a relaxed tensor-mass zone per interface "
                              "iteration.",
                              {.min = 1.0, .max = 100000.0}};
  Data<double> d_relaxationDamping{this,
                                   "relaxationDamping",
                                   0.02,
                                   "Fraction of the velocity a relaxation step removes (0.02: "
                                   "the fastest of 0.01, 0.02, 0.03 and 0.1 on the bar).",
                                   {.min = 0.0, .max = 0.999}};
  Data<std::string> d_convergenceReport{
      this, "convergenceReport", "",
      "File prefix: at init, write <prefix>_iterations.csv/.png and <prefix>_time.csv/.png, the "
      "error to the single-domain solution against iterations and wall time, for this "
      "decomposition, precomputed alone and tensor-mass alone (empty: no report)."};
  Data<int> d_reportIterations{this,
                               "reportIterations",
                               200,
                               "Interface iterations of the convergence report.",
                               {.min = 1.0, .max = 1000000.0}};
  Data<double> d_interfaceResidual{
      this,
      "interfaceResidual",
      0.0,
      "Largest change of an interface node's displacement in the last iteration.",
      {.unit = "m", .output = true}};
  Data<double> d_forceResidual{this,
                               "forceResidual",
                               0.0,
                               "|f - K u| over the free nodes after the last iteration.",
                               {.unit = "N", .output = true}};
  Data<std::string> d_currentZoneModels{this,
                                        "currentZoneModels",
                                        "",
                                        "Model of each zone now (cuts convert zones).",
                                        {.output = true}};
  Data<int> d_storedTensors{
      this, "storedTensors", 0, "3x3 blocks stored by the precomputed zones.", {.output = true}};
  Link<Topology> l_topology{this, "topology",
                            "Tetrahedral topology (default: the node's, or above)."};

  void init() override;
  void solve(MechanicalOperations& mop, double dt) override;

  /// The decomposition (for tests and reports).
  const domaindecomposition::HybridDecomposition& decomposition() const { return m_hybrid; }

 private:
  bool readProblem(domaindecomposition::ElasticProblem& problem);
  bool readPartition(const domaindecomposition::ElasticProblem& problem,
                     std::vector<int>& zoneOfElement, int& zoneCount);
  bool readZoneModels(int zoneCount, std::vector<domaindecomposition::ZoneModel>& models);
  bool readLoads(domaindecomposition::Loads& loads);
  /// The forces of the node's force fields now (m_fieldForce*); true when they changed.
  bool readFieldLoads(MechanicalOperations& mop, double dt);
  void followCuts();
  void publishZoneModels();

  domaindecomposition::HybridDecomposition m_hybrid;
  const Topology* m_topology = nullptr;
  MechanicalState<Vec3Types>* m_state = nullptr;
  std::vector<Vec3d> m_rest;
  std::uint64_t m_revision = 0;
  std::uint64_t m_loadVersion = 0;
  std::vector<int> m_fieldForceNodes;  // loads from the force fields (forceIndices empty)
  std::vector<Vec3d> m_fieldForces;
  bool m_ready = false;
};

}  // namespace stroma
