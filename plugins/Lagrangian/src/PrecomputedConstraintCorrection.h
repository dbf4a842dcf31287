// SPDX-License-Identifier: MIT
#pragma once

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "NodeRotations.h"
#include "Precomputed/kernels/DeformationBasis.h"
#include "core/Data.h"
#include "core/StateTypes.h"
#include "simulation/Constraints.h"
#include "simulation/MechanicalState.h"
#include "simulation/Timing.h"

namespace stroma {

class OdeSolver;

namespace precomputed {
class BasisSource;
}

/// SOFA's PrecomputedConstraintCorrection: the compliance C = A^-1 of the solver's system
/// (Constraints.h's ConstraintResponse: A = mFactor M + bFactor B + kFactor K, for implicit
/// Euler (1 + h rm) M - h (h + rs) K) is computed once, at the rest positions, for one Vec3d
/// state: the columns of the nodes constraint forces may act on (`basisIndices`, all nodes by
/// default), every row (3n x 3k, dense, kernels/DeformationBasis.h). Each step, with R_i the
/// rotation of node i's neighbourhood from rest (NodeRotations.h, when `rotations`), the
/// compliance and the correction are
///   W += positionFactor G C_tt G^T,   G = H R (the rows on the t touched nodes),
///   u_i = R_i (C G^T lambda)_i,   dx = positionFactor u,   dv = velocityFactor u.
/// A corotational body rotated rigidly has A = R A_0 R^T, so this is then exact; under
/// deformation it is the first-order approximation SOFA makes (the stiffness kept at rest,
/// turned per node). Per-node rotations rather than one for the whole body: a body held
/// somewhere bends rather than turns as a whole, and the constrained region's own rotation is
/// what turns its compliance.
///
/// Cached on disk (kernels/BasisCache.h) under a key hashing A (pattern and values: mesh,
/// material, masses, dt, the solver's factors), the rest positions, the fixed dofs, the basis
/// nodes and the factors: `fileCompliance`, else <fileDir or temp dir/stroma-precomputed>/
/// <key>.compliance. A file of another key (stale), corrupt or truncated is refused with a
/// warning and rewritten; a file that is not a Stroma cache (SOFA's own .comp) is left alone.
///
/// In the node of a solver that is its own compliance (PrecomputedLinearModel: the basis IS
/// K^-1 on the basis nodes, kernels/BasisSource.h), that basis is used as it is: no
/// precomputation, no rotation (the model is linear), positions move by K^-1 H^T lambda,
/// velocities stay zero.
class PrecomputedConstraintCorrection final : public BaseConstraintCorrection {
 public:
  Data<bool> d_rotations{this, "rotations", true,
                         "Turn the compliance with each node's rotation from rest (SOFA's "
                         "default is false; a rotated corotational body needs it)."};
  Data<bool> d_recompute{this, "recompute", false,
                         "Always compute the compliance, never read it from the cache file (it "
                         "is still written)."};
  Data<double> d_regularizationTerm{this,
                                    "regularizationTerm",
                                    0.0,
                                    "Added to the diagonal of W on the rows acting on this body.",
                                    {.unit = "m/N", .min = 0.0}};
  Data<std::string> d_fileCompliance{this, "fileCompliance", "",
                                     "Compliance cache file; empty: <fileDir>/<key>.compliance."};
  Data<std::string> d_fileDir{this, "fileDir", "",
                              "Folder of the cache file; empty: <temp dir>/stroma-precomputed."};
  Data<std::vector<unsigned>> d_basisIndices{
      this,
      "basisIndices",
      {},
      "Nodes that constraint forces may act on (the compliance's columns, 3 per node); empty: "
      "every node. Rows on other nodes are ignored with a warning."};

  Data<bool> d_loadedFromCache{this,
                               "loadedFromCache",
                               false,
                               "Whether the compliance was read from the cache file.",
                               {.output = true}};
  Data<double> d_precomputationTime{this,
                                    "precomputationTime",
                                    0.0,
                                    "Wall time of the assembly, factorisation and solves (0 "
                                    "when loaded).",
                                    {.unit = "s", .output = true}};
  Data<std::string> d_complianceKey{
      this, "complianceKey", "", "The cache key (16 hex digits) of the inputs.", {.output = true}};

  PrecomputedConstraintCorrection();
  ~PrecomputedConstraintCorrection() override;

  void bwdInit() override;
  void addCompliance(MechanicalOperations& mop, const ConstraintResponse& response,
                     const Eigen::SparseMatrix<double, Eigen::RowMajor>& H,
                     Eigen::MatrixXd& W) override;
  void applyCorrection(MechanicalOperations& mop, const ConstraintResponse& response,
                       const Eigen::SparseMatrix<double, Eigen::RowMajor>& H,
                       const Eigen::VectorXd& lambda) override;

  /// The compliance in use (the solver's basis for a BasisSource), null before bwdInit.
  const precomputed::DeformationBasis* compliance() const;

 private:
  bool findSolver();
  bool prepareRotations();
  bool precompute(MechanicalOperations& mop, const ConstraintResponse& response);
  std::string cachePath(std::uint64_t key) const;
  /// Gathers G = H R on the touched nodes; false when nothing of H acts on this body.
  void clearTouched();
  bool gatherRows(const precomputed::DeformationBasis& C,
                  const Eigen::SparseMatrix<double, Eigen::RowMajor>& H);

  OdeSolver* m_solver = nullptr;
  const precomputed::BasisSource* m_source = nullptr;
  MechanicalState<Vec3Types>* m_state = nullptr;
  std::unique_ptr<precomputed::DeformationBasis> m_compliance;
  std::array<double, 3> m_factors{};  // mFactor, bFactor, kFactor of the precomputation
  lagrangian::NodeRotations m_rotations;
  bool m_rotated = false;  // rotations in use this step
  Timing m_timing;         // for the operations of the precomputation
  bool m_warnedNode = false, m_warnedSize = false;

  // Step scratch: kept at their largest size (no allocation once warm).
  std::vector<int> m_slotOfNode;    // per node: index among the touched nodes, or -1
  std::vector<int> m_touched;       // touched nodes
  std::vector<int> m_touchedRows;   // W rows with an entry on this body (regularization)
  Eigen::MatrixXd m_G, m_Ctt, m_T;  // used as top-left blocks
  Eigen::VectorXd m_f, m_uRest, m_u;
  Eigen::Index m_rows = 0;
};

}  // namespace stroma
