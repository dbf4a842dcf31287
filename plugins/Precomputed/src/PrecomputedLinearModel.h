// SPDX-License-Identifier: MIT
#pragma once

#include <array>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "Precomputed/kernels/BasisSource.h"
#include "Precomputed/kernels/DeformationBasis.h"
#include "core/DataTraits.h"
#include "core/Link.h"
#include "core/StateTypes.h"
#include "simulation/NodalForces.h"
#include "simulation/MechanicalState.h"
#include "simulation/Solvers.h"
#include "topology/Topology.h"

namespace stroma {

/// Which nodes the model moves at each step.
enum class DeformedRegion { all, surface };

template <>
struct EnumKeywords<DeformedRegion> {
  static constexpr std::array<std::string_view, 2> names{"all", "surface"};
};

/// The precomputed quasi-static linear model of Cotin, Delingette and Ayache (1999; seed 000,
/// chapter 2 section 2.1): small-strain linear elasticity K u = f on the node's tetrahedra,
/// solved once for a unit force on every dof of the basis nodes (the surface by default), then
/// at each step by superposition (kernels/DeformationBasis.h). It takes the place of the ODE
/// solver in its node: each step sets positions = rest + u and velocities = 0. No FEM force
/// field belongs in the node: the model is its own elasticity.
///
/// Loads: the forces of the node's force fields at the step (ConstantForceField, ...), on basis
/// nodes; a force on another node is ignored with a warning. Imposed displacements: the
/// attribute pair imposedIndices / imposedDisplacements (basis nodes), constant or interpolated
/// linearly between keyTimes; `reactionForces` gives the force each imposed node needs.
/// Fixed nodes: `fixedIndices`, or by default the rows fixed by the node's projective
/// constraints on this state (FixedProjectiveConstraint, ...).
///
/// The basis is cached on disk (kernels/BasisCache.h), keyed by a hash of the rest positions,
/// elements, material, fixed dofs, basis and row nodes: `cacheFile`, by default
/// <temp dir>/stroma-precomputed/<key>.basis. A second run loads it; a corrupt, truncated or
/// foreign file is reported, recomputed and rewritten.
///
/// Constraints (FreeMotionAnimationLoop): the model is static, so a constraint force f moves
/// the positions by K^-1 f and leaves the velocities at zero (constraintResponse); the basis IS
/// K^-1 on the basis nodes, and a PrecomputedConstraintCorrection in the node takes its
/// compliance from it (BasisSource) with no other factorisation. Constraint forces are not
/// remembered: each step starts again from rest plus the loads, and the constraints are solved
/// anew from there.
class PrecomputedLinearModel final : public OdeSolver, public precomputed::BasisSource {
 public:
  Data<double> d_youngModulus{this,
                              "youngModulus",
                              5000.0,
                              "Young's modulus of the linear small-strain material.",
                              {.unit = "Pa", .min = 0.0}};
  Data<double> d_poissonRatio{
      this, "poissonRatio", 0.45, "Poisson's ratio, in (-1, 0.5).", {.min = -1.0, .max = 0.5}};
  Data<std::vector<unsigned>> d_fixedIndices{
      this,
      "fixedIndices",
      {},
      "Clamped nodes (u = 0); empty: the rows fixed by the node's projective constraints."};
  Data<std::vector<unsigned>> d_basisIndices{
      this,
      "basisIndices",
      {},
      "Nodes that can take forces and imposed displacements; empty: the surface nodes (of "
      "the tetrahedra's boundary triangles) that are not fully fixed."};
  Data<std::vector<unsigned>> d_imposedIndices{
      this, "imposedIndices", {}, "Basis nodes moved by imposedDisplacements (nbImposed)."};
  Data<std::vector<Vec3d>> d_imposedDisplacements{
      this,
      "imposedDisplacements",
      {},
      "Displacement of each imposed node from its rest position: nbImposed x 3, or with "
      "keyTimes nbKeys blocks of nbImposed x 3 (linear in between, the end values kept "
      "outside).",
      {.unit = "m"}};
  Data<std::vector<double>> d_keyTimes{this,
                                       "keyTimes",
                                       {},
                                       "Key times of imposedDisplacements, increasing (nbKeys).",
                                       {.unit = "s"}};
  Data<DeformedRegion> d_deformedRegion{
      this, "deformedRegion", DeformedRegion::all,
      "Nodes moved at each step: all, or surface (the basis and surface nodes; interior "
      "nodes stay at rest, and the basis stores only the surface rows)."};
  Data<std::string> d_cacheFile{
      this, "cacheFile", "", "Basis cache file; empty: <temp dir>/stroma-precomputed/<key>.basis."};
  Data<bool> d_useCache{this, "useCache", true,
                        "Load the basis from cacheFile when it matches, and write it there."};
  Link<Topology> l_topology{
      this, "topology",
      "Topology holding the tetrahedra (default: the node's last one with tetrahedra)."};

  Data<std::vector<Vec3d>> d_reactionForces{this,
                                            "reactionForces",
                                            {},
                                            "Force each imposed node receives at the last "
                                            "step (nbImposed x 3).",
                                            {.unit = "N", .output = true}};
  Data<bool> d_loadedFromCache{this,
                               "loadedFromCache",
                               false,
                               "Whether the basis was read from the cache file.",
                               {.output = true}};
  Data<double> d_precomputationTime{this,
                                    "precomputationTime",
                                    0.0,
                                    "Wall time of the assembly, factorisation and basis "
                                    "solves (0 when loaded).",
                                    {.unit = "s", .output = true}};
  Data<double> d_storedBytes{this,
                             "storedBytes",
                             0.0,
                             "Size of the basis as stored in the cache file.",
                             {.unit = "byte", .output = true}};

  void init() override;
  void bwdInit() override;
  void solve(MechanicalOperations& mop, double dt) override;
  /// Static: A = -K (mFactor 0, kFactor -1), dx = K^-1 f, no velocity.
  bool constraintResponse(double dt, ConstraintResponse& response) const override;

  /// The basis in use (null until bwdInit succeeded).
  const precomputed::DeformationBasis* basis() const { return m_basis.get(); }
  const precomputed::DeformationBasis* deformationBasis() const override { return m_basis.get(); }

 private:
  bool findTopology();
  bool collectFixedDofs(std::vector<int>& fixedDofs);
  bool collectBasisNodes(std::vector<int>& basisNodes);
  bool checkImposed();
  void buildBasis(const std::vector<int>& fixedDofs, const std::vector<int>& basisNodes);
  void imposedAt(double t);

  MechanicalState<Vec3Types>* m_state = nullptr;
  std::unique_ptr<precomputed::DeformationBasis> m_basis;
  std::vector<char> m_fixedNode;  ///< per node: 1 when all its dofs are fixed
  // Scratch of the step (sized once).
  precomputed::VectorXd m_u;
  NodalForces m_loads;  // the forces read this step (storage kept)
  std::vector<int> m_forceNodes, m_imposedNodes;
  std::vector<precomputed::Vec3> m_forces, m_imposed, m_reactions;
  bool m_warnedForce = false, m_warnedSolve = false;
};

}  // namespace stroma
