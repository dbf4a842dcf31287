// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <vector>

#include "TensorMass/kernels/StVKTensorMass.h"
#include "TensorMass/kernels/TensorMassRemoval.h"
#include "TetrahedralMesh.h"
#include "simulation/ForceField.h"

namespace stroma {

/// St Venant-Kirchhoff elasticity on tetrahedra in the non-linear tensor-mass form of
/// Picinbono, Delingette, Ayache (seed 004, section 3.1; a Stroma name, SOFA has no such
/// component). At init the terms of the energy of every tetrahedron (eq. 13: tensors B,
/// vectors C, scalars D of eqs. 8 and 14) are accumulated on the vertices, edges, triangles
/// and tetrahedra of the topology (table 1; StVKTensorMass.h). Each step, with U = x - X:
///
///   f = -dW/dU (eq. 15), computed vertex by vertex, edge by edge, triangle by triangle, then
///   tetrahedron by tetrahedron; W the St Venant-Kirchhoff energy (eqs. 10 to 12);
///   df = -H dx, H = d2W/dU2 the exact tangent, computed at the positions of the last addForce
///   (once, when an implicit solver first asks for it) and stored, as the linear model's
///   stiffness, on the vertices and edges.
///
/// The same forces as StandardTetrahedralFEMForceField with materialName="StVenantKirchhoff";
/// rotation invariant. Bad input and run-time changes as TetrahedralTensorMassForceField.
class TetrahedralStVKTensorMassForceField final : public ForceField<Vec3Types> {
 public:
  Data<double> d_youngModulus{this,
                              "youngModulus",
                              1000.0,
                              "Young's modulus of the material, > 0.",
                              {.unit = "Pa", .min = 0.0}};
  Data<double> d_poissonRatio{
      this, "poissonRatio", 0.3, "Poisson's ratio, -1 < nu < 0.5.", {.min = -1.0, .max = 0.5}};
  Link<Topology> l_topology{this, "topology",
                            "Topology holding the tetrahedra (default: the node's or above)."};

  void init() override;
  void reinit() override { init(); }

  void addForce(const MechanicalParams& mp, VecDeriv& f, const VecCoord& x,
                const VecDeriv& v) override;
  void addDForce(const MechanicalParams& mp, VecDeriv& df, const VecDeriv& dx) override;
  void addKToMatrix(const MechanicalParams& mp, MatrixAccumulator& matrix,
                    std::size_t offset) override;
  double potentialEnergy(const MechanicalParams& mp, const VecCoord& x) const override;

  /// The terms on vertices, edges, triangles and tetrahedra (after init).
  const tensormass::StVKTensorMass& model() const { return m_model; }

 private:
  bool build(bool atInit);
  bool refresh();
  /// The Hessian at the displacements of the last addForce, computed once per addForce.
  const tensormass::VertexEdgeTensors& hessian();

  TetrahedralMesh m_mesh;
  tensormass::StVKTensorMass m_model;
  tensormass::VertexEdgeTensors m_hessian;
  bool m_hessianCurrent = false;
  std::vector<Vec3d> m_displacement;  // U = x - X of the last addForce
  tensormass::PrimitiveUses m_uses;   ///< edges (and triangles) by their vertices, for cutting
  fem::LameParameters m_lame{};       ///< the material the tensors were built with
  std::uint64_t m_youngModulusVersion = 0;
  std::uint64_t m_poissonRatioVersion = 0;
  bool m_ready = false;
};

}  // namespace stroma
