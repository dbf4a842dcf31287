// SPDX-License-Identifier: MIT
#pragma once

#include "MeshMassKernels.h"
#include "core/StateTypes.h"
#include "simulation/Mass.h"
#include "topology/Topology.h"

namespace stroma {

/// A lumped mass computed from the elements of the topology (SOFA's DiagonalMass): each point
/// gets the density times the integral of its shape function over the elements around it,
/// V/4 per tetrahedron, V/8 per vertex of a parallelepiped, A/3 per triangle, L/2 per edge
/// (MeshMassKernels.h). The elements are those of the highest dimension present. The density
/// is `massDensity`, or `totalMass` over the total volume when totalMass > 0; `vertexMass`
/// (one per point) gives the masses directly. M is diagonal. Gravity: m_i g at each point.
///
/// The element integrals are computed at init (and again, on the points of init, when the
/// topology changes in a way it does not log, such as Topology::removeTriangles); the
/// density is read at every use, so changing massDensity or totalMass takes effect at the
/// next step. When tetrahedra are removed at run time (cutting, Topology::removeTetrahedra),
/// the removed tetrahedra's V/4 are subtracted from their points, on the points the masses were
/// computed on (cost proportional to the removal); a point left without elements has no mass.
/// With totalMass the density follows the remaining volume, as a rebuild would.
class DiagonalMass final : public Mass<Vec3Types> {
 public:
  Data<std::vector<double>> d_vertexMass{this,
                                         "vertexMass",
                                         {},
                                         "Mass of each point (nbPoints); when given, massDensity "
                                         "and totalMass are not used.",
                                         {.unit = "kg", .min = 0.0}};
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
  Data<bool> d_computeMassOnRest{this, "computeMassOnRest", false,
                                 "Compute the element volumes on the rest positions rather "
                                 "than the positions at init."};
  Data<FileName> d_filename{this,
                            "filename",
                            {},
                            "SOFA's mass files: not supported (an error when given).",
                            {.mustExist = false}};
  Data<bool> d_printMass{this, "printMass", false, "Report the total mass at init."};
  Data<bool> d_showGravityCenter{this, "showGravityCenter", false, "Viewers only."};
  Data<double> d_showAxisSizeFactor{this, "showAxisSizeFactor", 1.0, "Viewers only."};
  Link<Topology> l_topology{this, "topology",
                            "Topology whose elements carry the mass (default: the nearest one "
                            "from this node up)."};

  void init() override;
  void reinit() override { init(); }

  /// The mass of point i now.
  double pointMass(std::size_t i) const;
  /// The sum of the point masses now.
  double totalMass() const;

  void addForce(const MechanicalParams& mp, VecDeriv& f, const VecCoord& x,
                const VecDeriv& v) override;
  void addDForce(const MechanicalParams&, VecDeriv&, const VecDeriv&) override {}
  void addKToMatrix(const MechanicalParams&, MatrixAccumulator&, std::size_t) override {}
  double potentialEnergy(const MechanicalParams& mp, const VecCoord& x) const override;

  void addMDx(VecDeriv& f, const VecDeriv& dx, double factor) override;
  void accFromF(VecDeriv& a, const VecDeriv& f) override;
  void addMToMatrix(MatrixAccumulator& matrix, std::size_t offset, double factor) override;
  double kineticEnergy(const VecDeriv& v) const override;
  bool isDiagonal() const override { return true; }

 private:
  /// Recomputes the element integrals when the topology changed.
  void refresh();
  bool compute(bool again = false);
  /// f(i, mass of point i) for the points i < n.
  template <class F>
  void forEachMass(std::size_t n, F&& f) const;

  const Topology* m_topology = nullptr;
  std::uint64_t m_topologyRevision = 0;
  Eigen::VectorXd m_lumped;  ///< integral of each point's shape function (unit density)
  double m_measure = 0;
  bool m_onTetrahedra = false;  ///< computed on tetrahedra only: removals can be followed
  std::vector<Vec3d> m_points;  ///< the points the integrals were computed on
};

}  // namespace stroma
