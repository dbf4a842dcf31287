// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <vector>

#include "TensorMass/kernels/TensorMassRemoval.h"
#include "TensorMass/kernels/VertexEdgeTensors.h"
#include "TetrahedralMesh.h"
#include "simulation/ForceField.h"

namespace stroma {

/// Linear elasticity on tetrahedra, tensor-mass form (SOFA's TetrahedralTensorMassForceField;
/// Cotin, Delingette, Ayache, seed 000 eqs. 1.9 to 1.12; Picinbono et al., seed 004 eqs. 8
/// and 16). At init the stiffness tensors of every tetrahedron are accumulated on the vertices
/// (K^pp) and on the edges (K^pj) of the topology's edge list (LinearTensorMass.h); then, with
/// U = x - X (X: the state's rest positions at init),
///
///   f_p = -(K^pp U_p + sum_{edges (p, j)} K^pj U_j),   E = 1/2 U^T K U,   df = -K dx,
///
/// computed edge by edge, then vertex by vertex (seed 000 section 3.3). The same forces as
/// TetrahedronFEMForceField with method="small", with 6 + 1 tensors per edge and vertex
/// instead of a 12 x 12 matrix per element. Not rotation invariant (seed 004 section 2.2).
///
/// Bad input (errors naming the field): no tetrahedra, flat or inverted rest tetrahedra,
/// youngModulus <= 0, poissonRatio outside (-1, 0.5). Changes of youngModulus or poissonRatio
/// while running take effect at the next addForce; a change of the topology's elements or of
/// the state's size rebuilds everything.
class TetrahedralTensorMassForceField final : public ForceField<Vec3Types> {
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

  /// K^pp and K^pj (after init).
  const tensormass::VertexEdgeTensors& tensors() const { return m_tensors; }

 private:
  bool build(bool atInit);
  bool refresh();

  TetrahedralMesh m_mesh;
  tensormass::VertexEdgeTensors m_tensors;
  std::vector<Vec3d> m_displacement;  // scratch: U = x - X
  tensormass::PrimitiveUses m_uses;   ///< edges (and triangles) by their vertices, for cutting
  fem::LameParameters m_lame{};       ///< the material the tensors were built with
  std::uint64_t m_youngModulusVersion = 0;
  std::uint64_t m_poissonRatioVersion = 0;
  bool m_ready = false;
};

}  // namespace stroma
