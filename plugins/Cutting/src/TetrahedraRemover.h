// SPDX-License-Identifier: MIT
#pragma once

#include <vector>

#include "core/Link.h"
#include "core/StateTypes.h"
#include "simulation/AnimationLoop.h"
#include "simulation/MechanicalState.h"
#include "topology/Topology.h"

namespace stroma {

/// Removes tetrahedra of a topology while the simulation runs (cutting), at the start of the
/// steps when they apply, before the solvers: the components that follow the topology update at
/// their next use (framework/topology/TopologyChange.h). Three ways, which can be combined:
/// - listed: at each of `times`, the tetrahedra of the matching group of `tetrahedra` (indices
///   in the numbering of that time: each removal renumbers, SOFA's way);
/// - box: at every step between startTime and endTime, the tetrahedra whose barycentre, at the
///   current positions, lies in one of the `box`es;
/// - tool: a segment whose end points move linearly from `toolStart` (at startTime) to `toolEnd`
///   (at endTime); at every step between those times, the tetrahedra that the surface it sweeps
///   during the step meets, at the current positions.
/// A time t applies during the step [t0, t0 + dt) that contains it; times before the first step
/// apply at the first step.
class TetrahedraRemover final : public BehaviorModel {
 public:
  Data<std::vector<double>> d_times{
      this, "times", {}, "Times of the listed removals, increasing (nbTimes).", {.unit = "s"}};
  Data<std::string> d_tetrahedra{this, "tetrahedra", "",
                                 "Indices of the tetrahedra to remove at each of times: one group "
                                 "per time, groups separated by commas ('3 7 12, 40 41')."};
  Data<std::vector<Vec6d>> d_box{this,
                                 "box",
                                 {},
                                 "Boxes 'xmin ymin zmin xmax ymax zmax' (nbBoxes x 6): the "
                                 "tetrahedra whose barycentre is inside are removed.",
                                 {.unit = "m"}};
  Data<std::vector<Vec3d>> d_toolStart{this,
                                       "toolStart",
                                       {},
                                       "The tool segment's two end points at startTime (2 x 3).",
                                       {.unit = "m"}};
  Data<std::vector<Vec3d>> d_toolEnd{this,
                                     "toolEnd",
                                     {},
                                     "The tool segment's two end points at endTime (2 x 3); "
                                     "default: toolStart (a still tool).",
                                     {.unit = "m"}};
  Data<double> d_startTime{this,
                           "startTime",
                           0.0,
                           "Time from which the box and the tool remove tetrahedra.",
                           {.unit = "s"}};
  Data<double> d_endTime{this,
                         "endTime",
                         0.0,
                         "Time until which the box and the tool remove tetrahedra (the tool "
                         "reaches toolEnd then); <= startTime: no end for the box, a still tool.",
                         {.unit = "s"}};
  Link<Topology> l_topology{this, "topology",
                            "The topology to cut (default: the one in this node)."};

  void init() override;
  /// Finds the topology and the state (filled by then) and checks the listed indices.
  void bwdInit() override;
  void updatePosition(double dt) override;

  /// How many tetrahedra this component removed so far.
  std::size_t removedCount() const { return m_removedCount; }

 private:
  /// The points the tetrahedra are tested at: the state's positions, else the topology's.
  const std::vector<Vec3d>& currentPoints() const;
  void collectInBoxes(std::vector<Index>& out) const;
  void collectCrossedByTool(double from, double to, std::vector<Index>& out) const;
  /// The tool's end points at time t.
  std::array<Vec3d, 2> toolAt(double t) const;

  Topology* m_topology = nullptr;
  MechanicalState<Vec3Types>* m_state = nullptr;
  std::vector<std::vector<Index>> m_groups;  ///< parsed `tetrahedra`, one per time
  std::size_t m_nextGroup = 0;
  std::size_t m_removedCount = 0;
};

}  // namespace stroma
