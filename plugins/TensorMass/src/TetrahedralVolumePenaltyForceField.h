// SPDX-License-Identifier: MIT
#pragma once

#include <vector>

#include "TensorMass/kernels/VolumePenalty.h"
#include "TetrahedralMesh.h"
#include "simulation/ForceField.h"

namespace stroma {

/// The incompressibility penalty of Picinbono, Delingette, Ayache (seed 004, section 3.2; a
/// Stroma name): on each vertex of each tetrahedron, a force along the normal of the opposite
/// face, of norm growing as the square of the relative volume variation s = (V - V0) / V0 and
/// restoring the volume (VolumePenalty.h):
///
///   f_p = -gamma sign(s) s^2 dV/dx_p,   W = gamma V0 |s|^3 / 3,   exact tangent -d2W/dx2,
///
/// with gamma = `stiffness` (Pa). Independent of the elastic model: put it beside any force
/// field on the same tetrahedra (TetrahedralStVKTensorMassForceField, as in the paper, or
/// TetrahedronFEMForceField, StandardTetrahedralFEMForceField...). Rest volumes are those of
/// the state's rest positions at init; flat or inverted rest tetrahedra are errors.
class TetrahedralVolumePenaltyForceField final : public ForceField<Vec3Types> {
 public:
  Data<double> d_stiffness{
      this,
      "stiffness",
      1000.0,
      "gamma: the penalty's stiffness, a pressure; a tetrahedron whose volume changed by the "
      "fraction s is pushed back by the pressure gamma s |s| on its faces.",
      {.unit = "Pa", .min = 0.0}};
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

 private:
  fem::TetrahedronVectors gather(const VecCoord& x, const Tetrahedron& t) const;

  TetrahedralMesh m_mesh;
  std::vector<double> m_restVolumes;
  std::vector<Vec3d> m_positions;  // of the last addForce, where the tangent is taken
  bool m_ready = false;
};

}  // namespace stroma
