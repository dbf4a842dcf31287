// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "AveragedNodalPressure.h"
#include "CorotationalFemModel.h"
#include "FemMethod.h"
#include "VolumetricIntegration.h"
#include "core/StateTypes.h"
#include "simulation/StressField.h"
#include "simulation/ForceField.h"
#include "topology/Topology.h"

namespace stroma {

/// Linear elasticity on tetrahedra, corotational (SOFA's TetrahedronFEMForceField; also
/// answers to TetrahedralCorotationalFEMForceField and FastTetrahedralCorotationalForceField,
/// the same model). Per element, with rest positions X, Ke = |V| B^T C B and the element
/// rotation R of `method` (CorotationalTetrahedron.h):
///
///   f = -R Ke (R^T x - X),   K = df/dx = -R Ke R^T (dR/dx ignored),   E = 1/2 u^T Ke u.
///
/// The tetrahedra come from the node's topology (or `topology`); a topology with only
/// hexahedra is split into 6 tetrahedra each (as SOFA). Rest positions are the state's
/// rest_position at init. Element constants are computed at init into contiguous arrays and
/// again at the first step after youngModulus or poissonRatio changed.
///
/// With volumetricIntegration="nodal" the elements keep the deviatoric part of C only and
/// AveragedNodalPressure adds the volumetric part, one volumetric strain per vertex (Bonet and
/// Burton 1998): no volumetric locking as nu -> 1/2; E then includes its energy.
///
/// Rest shape: a degenerate (flat) tetrahedron is an error naming it; an inverted one (vertex
/// order not SOFA's, negative volume) is a warning: it works, with |V|.
///
/// Elements are computed in parallel on the scene's threads, each writing its own results,
/// then summed per vertex in a fixed order: results do not depend on the thread count.
class TetrahedronFEMForceField final : public ForceField<Vec3Types>, public StressField {
 public:
  Data<std::vector<double>> d_youngModulus{
      this,
      "youngModulus",
      {5000.0},
      "Young's modulus: one value, or one per tetrahedron (nbTetrahedra).",
      {.unit = "Pa", .min = 0.0}};
  Data<double> d_poissonRatio{this,
                              "poissonRatio",
                              0.45,
                              "Poisson's ratio, -1 < nu < 0.5 (0.5: incompressible, refused).",
                              {.min = -1.0, .max = 0.5}};
  Data<FemMethod> d_method{
      this, "method", FemMethod::large,
      "Rotation of each element: small (none: linear elasticity), large (Gram-Schmidt frame of "
      "edges 0-1, 0-2), polar (polar decomposition of F), svd (SVD of F, handles inverted "
      "elements); qr and polar2 (FastTetrahedralCorotationalForceField's names) are large and "
      "polar."};
  Link<Topology> l_topology{this, "topology",
                            "Topology holding the tetrahedra (default: the node's or above)."};
  Data<TetrahedronVolumetricIntegration> d_volumetricIntegration{
      this, "volumetricIntegration", TetrahedronVolumetricIntegration::full,
      "Where the volumetric energy kappa (tr eps)^2 / 2 is integrated: full (in each "
      "tetrahedron: locks as poissonRatio nears 0.5) or nodal (one volumetric strain per "
      "vertex, the volume-weighted mean of the tetrahedra around it: Bonet and Burton's "
      "averaged nodal pressure, locking-free; any method). Read at init."};

  // SOFA's options about how K is applied: Stroma assembles K exactly when the solver asks for
  // a matrix, and recomputes the element constants when the material changes. A matrix-free
  // solve that applies K several times at one point goes through K's 3 x 3 blocks, refilled
  // once per point (CorotationalElements.h), whatever computeGlobalMatrix says.
  Data<bool> d_computeGlobalMatrix{this, "computeGlobalMatrix", false,
                                   "SOFA option, accepted: K is assembled when the linear "
                                   "solver asks for a matrix, and applied matrix-free "
                                   "otherwise (through its 3 x 3 blocks, refilled once per "
                                   "step, when a solve applies it several times)."};
  Data<bool> d_assembling{this, "assembling", false,
                          "SOFA's older name of computeGlobalMatrix; accepted, as it."};
  Data<bool> d_updateStiffnessMatrix{
      this, "updateStiffnessMatrix", false,
      "SOFA option, accepted: the element stiffness is recomputed whenever youngModulus or "
      "poissonRatio change, whatever its value."};
  Data<bool> d_updateStiffness{this, "updateStiffness", false,
                               "SOFA option, accepted: as updateStiffnessMatrix."};

  // Plasticity of SOFA's TetrahedronFEMForceField: not implemented (a warning when enabled).
  Data<double> d_plasticYieldThreshold{
      this,
      "plasticYieldThreshold",
      0.0,
      "SOFA's plastic yield strain; plasticity is not implemented: a value > 0 gives a "
      "warning and the material stays elastic.",
      {.min = 0.0}};
  Data<double> d_plasticMaxThreshold{this,
                                     "plasticMaxThreshold",
                                     0.0,
                                     "SOFA's maximum plastic strain (see plasticYieldThreshold).",
                                     {.min = 0.0}};
  Data<double> d_plasticCreep{this,
                              "plasticCreep",
                              0.0,
                              "SOFA's plastic creep factor (see plasticYieldThreshold).",
                              {.min = 0.0}};

  // Output and drawing options of SOFA's component: accepted, without effect on the mechanics.
  Data<int> d_computeVonMisesStress{
      this,
      "computeVonMisesStress",
      0,
      "SOFA's switch of its von Mises output (0 none, 1 from the corotational strain, 2 from "
      "the Green strain); accepted: Stroma computes the stress on demand only (exports, "
      "pictures), from the corotational strain, whatever this says.",
      {.min = 0.0, .max = 2.0}};
  Data<bool> d_showVonMisesStressPerElement{this, "showVonMisesStressPerElement", false,
                                            "Viewers only."};
  Data<bool> d_showVonMisesStressPerNode{this, "showVonMisesStressPerNode", false, "Viewers only."};
  Data<bool> d_showVonMisesStressPerNodeColorMap{this, "showVonMisesStressPerNodeColorMap", false,
                                                 "Viewers only."};
  Data<std::string> d_showStressColorMap{this, "showStressColorMap", "",
                                         "Viewers only (color map name)."};
  Data<double> d_showStressAlpha{this, "showStressAlpha", 1.0, "Viewers only."};
  Data<double> d_showElementGapScale{this, "showElementGapScale", 0.333, "Viewers only."};
  Data<bool> d_drawHeterogeneousTetra{this, "drawHeterogeneousTetra", false, "Viewers only."};
  Data<bool> d_drawing{this, "drawing", true, "Viewers only."};
  Data<std::string> d_gatherPt{this, "gatherPt", "",
                               "SOFA option of a removed parallel gather; accepted, unused."};
  Data<std::string> d_gatherBsize{this, "gatherBsize", "",
                                  "SOFA option of a removed parallel gather; accepted, unused."};
  Data<std::vector<unsigned>> d_indices{
      this,
      "indices",
      {},
      "Accepted and ignored, for SOFA scenes that write it (Demos/oneTetrahedron.scn): SOFA's "
      "component has no such field either; every tetrahedron is computed."};

  void init() override;
  void reinit() override { init(); }

  void addForce(const MechanicalParams& mp, VecDeriv& f, const VecCoord& x,
                const VecDeriv& v) override;
  void addDForce(const MechanicalParams& mp, VecDeriv& df, const VecDeriv& dx) override;
  void addKToMatrix(const MechanicalParams& mp, MatrixAccumulator& matrix,
                    std::size_t offset) override;
  double potentialEnergy(const MechanicalParams& mp, const VecCoord& x) const override;

  // StressField: the von Mises stress at the current positions, on demand (CorotationalStress.h).
  const BaseMechanicalState* stressState() const override { return mstate(); }
  bool vonMisesPerElement(std::vector<double>& stress) const override;
  bool vonMisesPerPoint(std::vector<double>& stress) const override;

  /// The elements, their constants and the rotations of the last addForce (for tests).
  const CorotationalElements<fem::CorotationalTetrahedron>& elements() const {
    return m_model.elements();
  }
  /// The topology the tetrahedra come from (after init).
  const Topology* topology() const { return m_model.topology(); }
  /// The nodal pressures p_a (Pa) of the last addForce with volumetricIntegration="nodal"
  /// (empty otherwise).
  std::span<const double> nodalPressure() const {
    return usesNodalPressure() ? m_pressure.nodalPressure() : std::span<const double>{};
  }

 private:
  fem::RotationMethod rotationMethod() const { return toRotationMethod(d_method.value()); }
  bool usesNodalPressure() const {
    return d_volumetricIntegration.value() == TetrahedronVolumetricIntegration::nodal;
  }
  /// Sets the nodal pressure up again when the elements or the material changed (after
  /// m_model.refresh, which applies only a valid material).
  void refreshNodalPressure();

  CorotationalFemModel<fem::CorotationalTetrahedron> m_model{*this, d_youngModulus, d_poissonRatio,
                                                             l_topology};
  // volumetricIntegration="nodal": the volumetric part, and what it was set up from.
  AveragedNodalPressure m_pressure;
  std::uint64_t m_pressureElementsRevision = 0;
  std::uint64_t m_pressureYoungModulusVersion = 0;
  std::uint64_t m_pressurePoissonRatioVersion = 0;
};

}  // namespace stroma
