// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <vector>

#include "core/StateTypes.h"
#include "simulation/ForceField.h"
#include "topology/Topology.h"

namespace stroma {

/// A pressure on triangles of a surface (SOFA's TrianglePressureForceField): `pressure` is a
/// force per unit area, a vector in world coordinates (it is not along the triangles' normals
/// unless given so). Triangle t of area A_t gets the force pressure A_t, a third on each of its
/// vertices, so that the forces sum to pressure times the loaded area.
///
/// The triangles are `triangleList`, indices into the triangles of the topology (the link, else
/// the nearest topology from this node up: typically a TriangleSetTopologyContainer filled by
/// Tetra2TriangleTopologicalMapping, the list coming from a BoxROI's `triangleIndices`); the
/// points are those of the state (the node's, else the nearest one up, as SOFA's context).
/// With `useConstantForce` (the default) A_t is the rest area and the force is constant
/// (energy -f.x, no stiffness); otherwise A_t is the current area and the load follows the
/// surface's stretching: K_ij = pressure (grad_j A_t)^T / 3 for the vertices i, j of t,
/// grad_a A = (b - c) x n / 2 (n the unit normal of (a, b, c)), non-symmetric, no energy.
/// `triangleList` is read at init (and reinit), as SOFA reads it: a BoxROI that follows the
/// moving positions does not move the load (SOFA's TrianglePressureForceField.scn gives the same
/// motion only so). When the topology's triangles change (a cut), the loaded triangles it no
/// longer has are dropped at the next force computation, the others kept whatever their new
/// index; triangles it gains are not loaded. Errors: a triangle index out of range of the topology,
/// a triangle whose points are out of range of the state (both skipped), no topology.
class TrianglePressureForceField final : public ForceField<Vec3Types> {
 public:
  Data<Vec3d> d_pressure{this,
                         "pressure",
                         Vec3d::Zero(),
                         "Force per unit area on the triangles, world coordinates.",
                         {.unit = "Pa"}};
  Data<std::vector<unsigned>> d_triangleList{
      this, "triangleList", {}, "Indices of the loaded triangles in the topology's triangles."};
  Data<bool> d_useConstantForce{this, "useConstantForce", true,
                                "The area is the rest area (constant force); false: the current "
                                "area."};
  Data<bool> d_showForces{this, "showForces", false, "Viewers only."};
  Link<Topology> l_topology{this, "topology",
                            "The topology holding the triangles (default: the nearest one from "
                            "this node up)."};

  void init() override;
  void reinit() override { init(); }

  void addForce(const MechanicalParams& mp, VecDeriv& f, const VecCoord& x,
                const VecDeriv& v) override;
  void addDForce(const MechanicalParams& mp, VecDeriv& df, const VecDeriv& dx) override;
  void addKToMatrix(const MechanicalParams& mp, MatrixAccumulator& matrix,
                    std::size_t offset) override;
  double potentialEnergy(const MechanicalParams& mp, const VecCoord& x) const override;

  /// The loaded triangles (after the checks) and their rest areas.
  const std::vector<Triangle>& loadedTriangles() const { return m_triangles; }
  const std::vector<double>& restAreas() const { return m_restAreas; }

 private:
  /// Builds the loaded triangles at init; after a change of the topology, drops those it no
  /// longer has.
  void update();
  void build();
  void dropRemovedTriangles();

  const Topology* m_topology = nullptr;
  std::vector<Triangle> m_triangles;
  std::vector<double> m_restAreas;
  std::uint64_t m_builtTopology = 0;
  bool m_built = false;
};

}  // namespace stroma
