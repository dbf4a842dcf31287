// SPDX-License-Identifier: MIT
#pragma once

#include <string>
#include <vector>

#include "core/Link.h"
#include "simulation/AnimationLoop.h"
#include "topology/Topology.h"

namespace stroma {

/// SOFA's TopologicalChangeProcessor: replays a list of topological changes read from a text
/// file (or given as Data) on the topology of its node, each at the step when its time comes,
/// before the solvers; the components that follow the topology update at their next use
/// (framework/topology/TopologyChange.h).
///
/// The file (`filename`, SOFA's format): blocks, each a line `T= time` followed by command
/// lines, each with its element indices on the next line:
///
///   T= 0.1
///     REMOVE= 2
///   7 8
///
/// `REMOVE= n` removes n elements of the container's own kind (the tetrahedra of a
/// TetrahedronSetTopologyContainer, the triangles of a TriangleSetTopologyContainer), indices in
/// the numbering of that time (each removal renumbers, SOFA's way: TopologyChange.h). As SOFA reads
/// it, n rules: indices past the end of the line read as 0 (SOFA's shipped files write "REMOVE= 10"
/// over "1 2 ... 9"), and numbers past n are ignored; either case is reported by a warning. Times
/// apply as in TetrahedraRemover: during the step [t0, t0 + dt) that contains them.
///
/// Stroma removes tetrahedra and triangles (Topology::removeTetrahedra, removeTriangles), and
/// keeps the points: SOFA also deletes the points left without elements, Stroma keeps them free
/// (no mass, no stiffness). A removal of another kind, `ADD=` and `INCISE=` are
/// errors at load naming the command, the file and the line.
class TopologicalChangeProcessor final : public BehaviorModel {
 public:
  Data<FileName> d_filename{this,
                            "filename",
                            {},
                            "Topological change file: 'T= time' lines, each followed by "
                            "commands ('REMOVE= n' and its n indices on the next line)."};
  Data<bool> d_listening{this, "listening", true,
                         "SOFA's event switch, accepted: the changes are applied at the start of "
                         "their step either way."};
  Data<bool> d_useDataInputs{this, "useDataInputs", false,
                             "Take the removal from timeToRemove and tetrahedraToRemove (or "
                             "trianglesToRemove) instead of a file."};
  Data<double> d_timeToRemove{
      this, "timeToRemove", 0.0, "With useDataInputs: time of the removal.", {.unit = "s"}};
  Data<std::vector<Index>> d_tetrahedraToRemove{
      this,
      "tetrahedraToRemove",
      {},
      "With useDataInputs: indices of the tetrahedra removed at timeToRemove (nbRemoved)."};
  Data<std::vector<Index>> d_pointsToRemove{
      this,
      "pointsToRemove",
      {},
      "With useDataInputs: points to remove; Stroma cannot remove points (an error)."};
  Data<std::vector<Index>> d_edgesToRemove{
      this,
      "edgesToRemove",
      {},
      "With useDataInputs: edges to remove; Stroma cannot remove edges yet (an error)."};
  Data<std::vector<Index>> d_trianglesToRemove{
      this,
      "trianglesToRemove",
      {},
      "With useDataInputs: triangles to remove; Stroma cannot remove triangles yet (an error)."};
  Data<std::vector<Index>> d_quadsToRemove{
      this,
      "quadsToRemove",
      {},
      "With useDataInputs: quads to remove; Stroma cannot remove quads yet (an error)."};
  Data<std::vector<Index>> d_hexahedraToRemove{
      this,
      "hexahedraToRemove",
      {},
      "With useDataInputs: hexahedra to remove; Stroma cannot remove hexahedra yet (an error)."};
  Data<double> d_interval{this,
                          "interval",
                          0.0,
                          "SOFA's time between two incisions of INCISE= commands, accepted (the "
                          "incisions are not supported).",
                          {.unit = "s"}};
  Data<bool> d_saveIndicesAtInit{this, "saveIndicesAtInit", false,
                                 "SOFA's precomputation of the INCISE= paths, accepted (the "
                                 "incisions are not supported)."};
  Data<double> d_epsilonSnapPath{this, "epsilonSnapPath", 0.1,
                                 "SOFA's snapping of INCISE= paths to vertices, accepted (the "
                                 "incisions are not supported)."};
  Data<double> d_epsilonSnapBorder{this, "epsilonSnapBorder", 0.25,
                                   "SOFA's snapping of INCISE= paths to the border, accepted "
                                   "(the incisions are not supported)."};
  Data<bool> d_draw{this, "draw", false,
                    "SOFA's drawing of the incision paths, accepted (nothing is drawn)."};
  Link<Topology> l_topology{this, "topology",
                            "The topology to change (default: the one in this node)."};

  /// Reads the file (or the Data inputs) into the list of changes.
  void init() override;
  /// Finds the topology (filled by then) and checks each change against it.
  void bwdInit() override;
  void updatePosition(double dt) override;

  /// One `REMOVE=` of the file (or of the Data inputs): its time, the indices, and the line of
  /// its command in the file (its indices are on the next; 0 for Data inputs), for messages.
  struct Removal {
    double time = 0;
    std::vector<Index> indices;
    int line = 0;
  };
  const std::vector<Removal>& removals() const { return m_removals; }
  /// How many elements this component removed so far.
  std::size_t removedCount() const { return m_removedCount; }

 private:
  /// Parses the file into m_removals; false after reporting an error.
  bool readFile();
  /// "file:line" of a change's command (or of its indices), or the Data field's name for the
  /// Data inputs.
  std::string where(const Removal& removal, bool indexLine) const;

  /// The number of elements of the kind removed.
  std::size_t elementCount() const;

  Topology* m_topology = nullptr;
  bool m_onTriangles = false;  ///< removes triangles (a surface), else tetrahedra
  std::string m_dataField = "tetrahedraToRemove";  ///< the Data input used
  std::vector<Removal> m_removals;
  std::size_t m_next = 0;
  std::size_t m_removedCount = 0;
};

}  // namespace stroma
