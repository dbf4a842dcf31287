// SPDX-License-Identifier: MIT
// The hybrid model by domain decomposition (seed 000, chapter 4): the static linear elastic
// problem K u = f of a whole tetrahedral mesh, solved zone by zone on an element-based
// partition (interface nodes shared, figure 4.2 b), each zone precomputed (Cotin's deformation
// basis) or tensor-mass (a solve of its own, direct or by dynamic relaxation).
//
// Block iteration with a one-node overlap (eq. 4.16; section 4.3.2.3). Zone z owns the nodes N
// of its elements; its block is the rows and columns of N in the global K, A = K[N, N]: the
// interface rows hold the stiffness of every element around the interface node, so the nodes R
// of the neighbours next to the interface are the zone's Dirichlet boundary, and A is never
// singular while the zone touches a neighbour or a fixed node. One zone update is
//
//   A u_N = f_N - K[N, R] u_R,                                              (eq. 4.16)
//
// where -K[N, R] u_R, non-zero on the interface nodes only, is the force the neighbours'
// elements exert on the interface from their side (figure 4.12): forces go into a zone,
// displacements of its interface come out and are read by the neighbours at their next update.
// A precomputed zone applies its deformation basis B = A^-1 restricted to the interface and
// loaded nodes (Precomputed/kernels/DeformationBasis.h, seed 000 section 4.4.2: the basis holds
// every node of the zone); an imposed displacement on one of its nodes goes through the small
// system of Cotin's method (the reaction is the force the tool feels). A tensor-mass zone
// solves A du = (f - K u)_N exactly (`direct`, a sparse LDL^T) or runs damped explicit steps of
// M dv/dt = f - K u on its nodes (`relaxation`, the dynamic model of seed 000 chapter 3 used as
// an iterative solver; fictitious lumped mass, unit density).
//
// Gauss-Seidel updates the zones in turn, each reading its neighbours' newest values (eq. 4.2,
// nu = 1: a multiplicative Schwarz method, convergent for any partition since K is symmetric
// positive definite); Jacobi updates them all from the previous iterate (nu = 0) and keeps, on
// a node shared by several zones, the value of the zone of lowest index (restricted additive
// Schwarz). The iterates converge to the single-domain solution; `iterate` reports how far.
//
// With `schur`, every zone precomputed, one iteration solves the condensed interface system
// exactly (CondensedInterface.h; cuts are then refused: they need a block iteration).
//
// Cutting: removing tetrahedra converts the precomputed zones they belong to into tensor-mass
// zones from the current displacement (no jump), and leaves the other zones' stored bases as
// they are: a precomputed neighbour whose interface rows lost some of the removed elements keeps
// its basis and gets the difference (K_now - A_stored) u on its interface as a lagged force,
// so the iteration still converges to the solution of the cut mesh.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "DomainDecomposition/kernels/ZonePartition.h"
#include "Precomputed/kernels/DeformationBasis.h"

namespace stroma::domaindecomposition {

using Vec3 = Eigen::Vector3d;
using SparseMatrix = Eigen::SparseMatrix<double>;
using RowMajorMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;

/// How a zone solves its block (the XML keywords of `zoneModels`).
enum class ZoneModel { precomputed, tensorMass };
/// The interface iteration (eq. 4.2: nu = 1 Gauss-Seidel, nu = 0 Jacobi), or the condensed
/// Schur-complement form (eqs. 4.6, 4.7; every zone precomputed; CondensedInterface.h).
enum class InterfaceIteration { gaussSeidel, jacobi, schur };
/// How a tensor-mass zone solves its block.
enum class TensorMassSolve { direct, relaxation };

/// The mesh, its material and its fixed nodes (u = 0).
struct ElasticProblem {
  std::vector<Vec3> points;  ///< rest positions (m)
  std::vector<TetrahedronNodes> tetrahedra;
  double youngModulus = 0;  ///< Pa
  double poissonRatio = 0;
  std::vector<int> fixedNodes;
};

/// Forces (N) on nodes, and imposed displacements (m) on nodes (a grasping tool).
struct Loads {
  std::vector<int> forceNodes;
  std::vector<Vec3> forces;
  std::vector<int> imposedNodes;
  std::vector<Vec3> imposedDisplacements;
};

struct DecompositionOptions {
  InterfaceIteration iteration = InterfaceIteration::gaussSeidel;
  TensorMassSolve tensorMassSolve = TensorMassSolve::direct;
  int relaxationSteps = 1;          ///< explicit steps per interface iteration (relaxation)
  double relaxationDamping = 0.02;  ///< fraction of the velocity removed at each step, in [0, 1)
};

/// How far an iterate is from convergence.
struct IterationReport {
  /// Largest change of an interface node's displacement in this iteration (m); over every node
  /// when there is no interface (a single zone).
  double interfaceChange = 0;
  /// |f - K u| over the free degrees of freedom (N): zero at the solution.
  double forceResidual = 0;
};

class CondensedInterface;

class HybridDecomposition {
 public:
  HybridDecomposition();
  ~HybridDecomposition();

  /// Builds the zones (bases of the precomputed ones, factorizations or masses of the
  /// tensor-mass ones) for the partition `zoneOfElement` (checked: every element in one zone)
  /// with one model per zone. False and `error` on bad input: a partition leaving elements out,
  /// a node index out of range, a group of zones with no fixed node and no imposed displacement
  /// (singular stiffness), a singular zone.
  bool setup(const ElasticProblem& problem, const std::vector<int>& zoneOfElement,
             const std::vector<ZoneModel>& models, const Loads& loads,
             const DecompositionOptions& options, std::string& error);

  /// New loads. A precomputed zone whose basis lacks a newly loaded node of its own computes
  /// it again (that zone only). False and `error` as setup for bad indices or a singular case.
  bool setLoads(const Loads& loads, std::string& error);

  /// One interface iteration over every zone.
  IterationReport iterate();

  /// Removes tetrahedra (indices in decreasing order, each removal moving the last element into
  /// the freed slot: TopologyChange.h's `removed`). The precomputed zones that lose elements
  /// become tensor-mass zones; they are listed in `converted`. False and `error` when an index
  /// is out of range or a converted zone is singular (a piece cut loose with no fixed node).
  bool removeTetrahedra(const std::vector<int>& removed, std::vector<int>& converted,
                        std::string& error);

  /// Starts again from u = 0 (with the imposed displacements in place).
  void resetDisplacement();

  /// Displacements, node-major (3 n, m).
  const Eigen::VectorXd& displacement() const { return m_u; }
  int zoneCount() const { return static_cast<int>(m_zones.size()); }
  ZoneModel zoneModel(int zone) const { return m_zones[zone].model; }
  const std::vector<int>& zoneNodes(int zone) const { return m_zones[zone].nodes; }
  const std::vector<int>& interfaceNodes(int zone) const { return m_zones[zone].interfaceNodes; }
  /// The deformation basis of a precomputed zone (null for a tensor-mass zone).
  const precomputed::DeformationBasis* basis(int zone) const;
  /// 3x3 blocks stored by the precomputed zones (rows x basis nodes; seed 000 section 4.4.2.1).
  std::size_t storedTensors() const;
  /// The current tetrahedra and their zones (after cuts).
  const std::vector<TetrahedronNodes>& tetrahedra() const { return m_tetrahedra; }
  const std::vector<int>& zoneOfElement() const { return m_zoneOfElement; }

 private:
  struct Zone {
    ZoneModel model = ZoneModel::precomputed;
    std::vector<int> nodes;           ///< global indices, sorted (N)
    std::vector<int> interfaceNodes;  ///< nodes shared with another zone, sorted
    // Precomputed: B over the local nodes (N first), and the interface rows of A as stored
    // (3 |interface| x 3 |N|, local columns) for the lagged correction after a cut.
    std::optional<precomputed::DeformationBasis> basis;
    RowMajorMatrix interfaceRows;
    std::vector<int> interfaceRowOfBasisNode;  ///< per basis node: row block, or -1
    // Tensor-mass: the free nodes (not fixed, not imposed, with an element), their block.
    std::vector<int> freeNodes;
    std::unique_ptr<Eigen::SimplicialLDLT<SparseMatrix>> factor;  ///< direct
    std::vector<double> inverseMass;
    Eigen::VectorXd velocity;
    double timeStep = 0;
    /// Kept between iterations so that an iteration does not allocate.
    struct Scratch {
      Eigen::VectorXd uN, stored, local, residual, correction;
      std::vector<int> forceNodes, imposedNodes;
      std::vector<Vec3> forces, imposed, reactions;
    } scratch;
  };

  bool checkLoads(const Loads& loads, std::string& error) const;
  bool checkSingularGroups(std::string& error) const;
  void assembleGlobal(std::string& error);
  void findInterfaces();
  bool buildPrecomputed(int zone, std::string& error);
  bool buildTensorMass(int zone, std::string& error);
  bool buildCondensed(std::string& error);
  void updateZone(int zone, Eigen::VectorXd& u);
  void updatePrecomputed(Zone& zone, Eigen::VectorXd& u);
  void updateTensorMass(Zone& zone, Eigen::VectorXd& u);
  Vec3 rowProduct(int node, const Eigen::VectorXd& u) const;  ///< (K u) at node
  void applyImposed(Eigen::VectorXd& u) const;

  ElasticProblem m_problem;
  DecompositionOptions m_options;
  std::vector<TetrahedronNodes> m_tetrahedra;
  std::vector<int> m_zoneOfElement;
  std::vector<Zone> m_zones;
  RowMajorMatrix m_K;                              ///< stiffness of the current mesh
  Eigen::VectorXd m_f;                             ///< external forces (3 n)
  Eigen::VectorXd m_u, m_work;                     ///< iterate; scratch of the Jacobi updates
  Eigen::VectorXd m_before, m_residual;            ///< scratch of iterate()
  std::vector<char> m_fixed, m_imposed, m_active;  ///< per node
  std::vector<Vec3> m_imposedValue;                ///< per node (m)
  std::vector<int> m_owner;                        ///< per node: lowest zone holding it (Jacobi)
  std::vector<int> m_allInterfaceNodes;
  Loads m_loads;
  std::unique_ptr<CondensedInterface> m_condensed;  ///< interfaceIteration schur
};

}  // namespace stroma::domaindecomposition
