// SPDX-License-Identifier: MIT
#pragma once

#include "MeshMassKernels.h"
#include "core/StateTypes.h"
#include "simulation/Mass.h"
#include "topology/Topology.h"

namespace stroma {

/// The consistent mass matrix of linear elements (SOFA's MeshMatrixMass):
///   M_ij = rho * integral of N_i N_j      (times I3 for the three coordinates)
/// over the elements of the highest dimension of the topology (tetrahedra and hexahedra, else
/// triangles and quads, else edges; MeshMassKernels.h). The density is `massDensity`, or
/// `totalMass` over the total volume when totalMass > 0. With `lumping`, M is replaced by the
/// diagonal of its row sums (each point gets rho times the integral of its shape function);
/// only then isDiagonal() is true and explicit solvers can divide by it. Without lumping,
/// addMDx multiplies by the consistent matrix and addMToMatrix adds its 3x3 blocks. Gravity is
/// the consistent load integral rho N_i g, which is the row sum times g in both cases.
///
/// The unit-density matrix is computed at init (and again when the topology changes); the
/// density is read at every use, so changing massDensity or totalMass takes effect at the next
/// step. Changing `lumping` too. When tetrahedra are removed at run time (cutting,
/// Topology::removeTetrahedra), their element matrices are subtracted, on the points the matrix
/// was computed on (cost proportional to the removal; the sparsity pattern stays, with zeros);
/// a point left without elements has no mass.
class MeshMatrixMass final : public Mass<Vec3Types> {
 public:
  Data<double> d_massDensity{this,
                             "massDensity",
                             1.0,
                             "Mass per unit volume (per unit area for surfaces, per unit length "
                             "for edges).",
                             {.unit = "kg/m^3", .min = 0.0}};
  Data<double> d_totalMass{this,
                           "totalMass",
                           0.0,
                           "Total mass, spread by volume; 0 to use massDensity.",
                           {.unit = "kg", .min = 0.0}};
  Data<bool> d_lumping{this, "lumping", false,
                       "Use the diagonal of the row sums instead of the consistent matrix."};
  Data<bool> d_computeMassOnRest{this, "computeMassOnRest", false,
                                 "Compute the element integrals on the rest positions rather "
                                 "than the positions at init."};
  Data<bool> d_printMass{this, "printMass", false, "Report the total mass at init."};
  Data<bool> d_showGravityCenter{this, "showGravityCenter", false, "Viewers only."};
  Data<double> d_showAxisSizeFactor{this, "showAxisSizeFactor", 1.0, "Viewers only."};
  Link<Topology> l_topology{this, "topology",
                            "Topology whose elements carry the mass (default: the nearest one "
                            "from this node up)."};
  Link<Base> l_geometryState{this, "geometryState",
                             "State whose positions the elements are measured on (default: the "
                             "mass's own state)."};

  void init() override;
  void reinit() override { init(); }

  /// The density in use now (massDensity, or totalMass over the measure).
  double density() const;
  /// The mass matrix of unit density (scalar, nbPoints x nbPoints), up to date with the topology.
  const MeshMassMatrix& unitMass() {
    refresh();
    return m_mesh;
  }

  void addForce(const MechanicalParams& mp, VecDeriv& f, const VecCoord& x,
                const VecDeriv& v) override;
  void addDForce(const MechanicalParams&, VecDeriv&, const VecDeriv&) override {}
  void addKToMatrix(const MechanicalParams&, MatrixAccumulator&, std::size_t) override {}
  double potentialEnergy(const MechanicalParams& mp, const VecCoord& x) const override;

  void addMDx(VecDeriv& f, const VecDeriv& dx, double factor) override;
  void accFromF(VecDeriv& a, const VecDeriv& f) override;
  void addMToMatrix(MatrixAccumulator& matrix, std::size_t offset, double factor) override;
  double kineticEnergy(const VecDeriv& v) const override;
  bool isDiagonal() const override { return d_lumping.value(); }

 private:
  void refresh();
  bool compute();

  const Topology* m_topology = nullptr;
  std::uint64_t m_topologyRevision = 0;
  MeshMassMatrix m_mesh;
  std::vector<Vec3d> m_points;  ///< the points the matrix was computed on (tetrahedra only)
  bool m_reportedConsistentDivision = false;
};

}  // namespace stroma
