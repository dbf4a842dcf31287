// SPDX-License-Identifier: MIT
#pragma once

#include <string>
#include <vector>

#include "CorotationalFemModel.h"
#include "FemMethod.h"
#include "VolumetricIntegration.h"
#include "core/StateTypes.h"
#include "simulation/StressField.h"
#include "simulation/ForceField.h"
#include "topology/Topology.h"

namespace stroma {

/// Linear elasticity on trilinear hexahedra, corotational (SOFA's HexahedronFEMForceField),
/// on a RegularGridTopology or any hexahedral mesh (vertex order of TopologyTypes.h). Per
/// element, Ke is integrated by 2 x 2 x 2 Gauss points on the rest shape (TrilinearHexahedron.h)
/// and R is found by `method` (CorotationalHexahedron.h, Nesme thesis, seed 001, ch. 4 sec. 2):
///
///   f = -R Ke (R^T x - X),   K = df/dx = -R Ke R^T (dR/dx ignored),   E = 1/2 u^T Ke u.
///
/// With a rotating method the force is only approximately -dE/dx (CorotationalElement.h):
/// the energy reported is then approximate.
///
/// With volumetricIntegration="reduced", Ke = integral B^T C_dev B (2 x 2 x 2 points) +
/// kappa V bbar bbar^T, the volumetric part on the element's mean dilatation (B-bar,
/// VolumetricSplit.h): no volumetric locking as nu -> 1/2, no hourglass mode.
///
/// Same rest-shape checks, run-time material changes and deterministic parallel loops as
/// TetrahedronFEMForceField.
class HexahedronFEMForceField final : public ForceField<Vec3Types>, public StressField {
 public:
  Data<std::vector<double>> d_youngModulus{
      this,
      "youngModulus",
      {5000.0},
      "Young's modulus: one value, or one per hexahedron (nbHexahedra).",
      {.unit = "Pa", .min = 0.0}};
  Data<double> d_poissonRatio{this,
                              "poissonRatio",
                              0.45,
                              "Poisson's ratio, -1 < nu < 0.5 (0.5: incompressible, refused).",
                              {.min = -1.0, .max = 0.5}};
  Data<FemMethod> d_method{
      this, "method", FemMethod::large,
      "Rotation of each element: small (none: linear elasticity), large (Gram-Schmidt frame of "
      "the averaged edges), polar (polar decomposition of F at the centre, the large frame "
      "when inverted), svd (SVD of F at the centre; not in SOFA); qr is large, polar2 polar."};
  Link<Topology> l_topology{this, "topology",
                            "Topology holding the hexahedra (default: the node's or above)."};
  Data<HexahedronVolumetricIntegration> d_volumetricIntegration{
      this, "volumetricIntegration", HexahedronVolumetricIntegration::full,
      "Where the volumetric energy kappa (tr eps)^2 / 2 is integrated: full (2 x 2 x 2 Gauss "
      "points: locks as poissonRatio nears 0.5) or reduced (one volumetric strain per "
      "element, its mean dilatation, with the deviatoric part at 2 x 2 x 2 points: selective "
      "reduced integration in B-bar form, locking-free; any method). Read at init."};
  Data<bool> d_updateStiffnessMatrix{
      this, "updateStiffnessMatrix", false,
      "SOFA option, accepted: the element stiffness is recomputed whenever youngModulus or "
      "poissonRatio change, whatever its value."};
  Data<bool> d_assembling{this, "assembling", false,
                          "SOFA option, accepted: K is assembled when the linear solver asks "
                          "for a matrix."};
  Data<bool> d_drawing{this, "drawing", true, "Viewers only."};
  Data<double> d_drawPercentageOffset{this, "drawPercentageOffset", 0.15, "Viewers only."};
  Data<std::string> d_gatherPt{this, "gatherPt", "",
                               "SOFA option of a removed parallel gather; accepted, unused."};
  Data<std::string> d_gatherBsize{this, "gatherBsize", "",
                                  "SOFA option of a removed parallel gather; accepted, unused."};

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
  const CorotationalElements<fem::CorotationalHexahedron>& elements() const {
    return m_model.elements();
  }

 private:
  fem::RotationMethod rotationMethod() const { return toRotationMethod(d_method.value()); }

  CorotationalFemModel<fem::CorotationalHexahedron> m_model{*this, d_youngModulus, d_poissonRatio,
                                                            l_topology};
};

}  // namespace stroma
