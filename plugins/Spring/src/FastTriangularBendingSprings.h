// SPDX-License-Identifier: MIT
#pragma once

#include <vector>

#include "LinearBending.h"
#include "core/StateTypes.h"
#include "simulation/ForceField.h"
#include "topology/Topology.h"

namespace stroma {

/// Linear bending of each pair of triangles sharing an edge (SOFA's
/// FastTriangularBendingSprings): the energy lambda |R|^2 / 2 of the pair's bending vector R, a
/// fixed combination of its four points that vanishes when the pair is flat, with
/// lambda = (2/3) bendingStiffness |e| / (H_b + H_d) (LinearBending.h, after Volino and
/// Magnenat-Thalmann 2006). The force is linear in the positions and the stiffness constant. The
/// constants are computed at the rest positions; the flat pair is the rest shape of every hinge
/// (a mesh curved at rest is pulled flat, as in SOFA). An edge of more than two triangles uses
/// its first two, with a warning. No damping (use the solver's Rayleigh damping).
class FastTriangularBendingSprings final : public ForceField<Vec3Types> {
 public:
  Data<double> d_bendingStiffness{this,
                                  "bendingStiffness",
                                  1.0,
                                  "Bending stiffness B of the material (energy per squared fold "
                                  "angle, scaled by |e| / (H_b + H_d) per pair).",
                                  {.unit = "N m", .min = 0.0}};
  Data<double> d_minDistValidity{this,
                                 "minDistValidity",
                                 1e-6,
                                 "A pair whose edge or heights are shorter than this at rest is "
                                 "degenerate (an error).",
                                 {.unit = "m", .min = 0.0}};
  Link<Topology> l_topology{this, "topology",
                            "Topology whose triangles give the pairs (default: the nearest one "
                            "from this node up)."};

  void init() override;
  void reinit() override { init(); }

  void addForce(const MechanicalParams& mp, VecDeriv& f, const VecCoord& x,
                const VecDeriv& v) override;
  void addDForce(const MechanicalParams& mp, VecDeriv& df, const VecDeriv& dx) override;
  void addKToMatrix(const MechanicalParams& mp, MatrixAccumulator& matrix,
                    std::size_t offset) override;
  double potentialEnergy(const MechanicalParams& mp, const VecCoord& x) const override;

  /// The hinges built at init (one per edge shared by two triangles).
  const std::vector<LinearBendingHinge>& hinges() const { return m_hinges; }

 private:
  void build();

  const Topology* m_topology = nullptr;
  std::uint64_t m_topologyRevision = 0;
  std::vector<LinearBendingHinge> m_hinges;
};

}  // namespace stroma
