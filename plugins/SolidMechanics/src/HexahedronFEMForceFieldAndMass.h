// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "CorotationalFemModel.h"
#include "FemMethod.h"
#include "SolidMechanics/kernels/TrilinearHexahedron.h"
#include "core/StateTypes.h"
#include "simulation/StressField.h"
#include "simulation/Mass.h"
#include "topology/Topology.h"

namespace stroma {

/// HexahedronFEMForceField and the mass of the same hexahedra in one component (SOFA's
/// HexahedronFEMForceFieldAndMass). Elastic forces, stiffness and energy are those of
/// HexahedronFEMForceField. The mass of element e, for a density rho (TrilinearHexahedron.h,
/// 3 x 3 x 3 Gauss, exact for any trilinear shape):
///
///   consistent:  M_e = (rho integral N_i N_j dV) (x) I_3    (the default, as SOFA)
///   lumped:      m_i = sum_j (M_e)_ij, summed per vertex over its hexahedra  (lumpedMass)
///
/// Gravity (the node's g) is the force m_i g at each vertex with the lumped masses, which is
/// exactly M (1 (x) g) for the consistent mass too. Explicit solvers need a diagonal mass:
/// isDiagonal() is true only with lumpedMass.
class HexahedronFEMForceFieldAndMass final : public Mass<Vec3Types>, public StressField {
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
      "Rotation of each element: small, large, polar or svd (see HexahedronFEMForceField)."};
  Data<double> d_density{
      this, "density", 1.0, "Mass density of the material (> 0).", {.unit = "kg/m^3", .min = 0.0}};
  Data<bool> d_lumpedMass{this, "lumpedMass", false,
                          "Lump the mass on the vertices (row sums): a diagonal mass, as "
                          "explicit solvers need; otherwise the consistent mass matrix."};
  Link<Topology> l_topology{this, "topology",
                            "Topology holding the hexahedra (default: the node's or above)."};
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

  void addMDx(VecDeriv& f, const VecDeriv& dx, double factor) override;
  void accFromF(VecDeriv& a, const VecDeriv& f) override;
  void addMToMatrix(MatrixAccumulator& matrix, std::size_t offset, double factor) override;
  double kineticEnergy(const VecDeriv& v) const override;
  bool isDiagonal() const override { return d_lumpedMass.value(); }

  // StressField: the von Mises stress at the current positions, on demand (CorotationalStress.h).
  const BaseMechanicalState* stressState() const override { return mstate(); }
  bool vonMisesPerElement(std::vector<double>& stress) const override;
  bool vonMisesPerPoint(std::vector<double>& stress) const override;

  /// Lumped mass of each vertex (kg).
  const std::vector<double>& vertexMasses() const { return m_vertexMasses; }

 private:
  fem::RotationMethod rotationMethod() const { return toRotationMethod(d_method.value()); }
  /// Recomputes the masses when the density or the elements changed.
  void refreshMass();
  void computeMass();

  CorotationalFemModel<fem::CorotationalHexahedron> m_model{*this, d_youngModulus, d_poissonRatio,
                                                            l_topology};
  std::vector<fem::Matrix8d> m_elementMasses;  // (nbHexahedra) consistent, unit (I_3 implied)
  std::vector<double> m_vertexMasses;          // (nbPoints) lumped
  std::uint64_t m_densityVersion = 0;
  std::uint64_t m_elementsRevision = 0;  // m_model.elementsRevision() of the masses
};

}  // namespace stroma
