// SPDX-License-Identifier: MIT
#pragma once

#include <span>
#include <string>

#include "core/Base.h"
#include "core/Link.h"
#include "core/Node.h"
#include "topology/Topology.h"

namespace stroma {

/// SOFA's TetrahedronSetTopologyModifier: changes the tetrahedra of the topology in its node at
/// run time. removeTetrahedra() removes tetrahedra (and the triangles and edges left without a
/// tetrahedron) through Topology::removeTetrahedra, which logs the change for the components that
/// follow the topology (framework/topology/TopologyChange.h). Points are never removed, so
/// `propagateToDOF` has nothing to propagate. Scene components such as TetrahedraRemover
/// (plugins/Cutting) drive it; C++ code may call it directly. Header-only, so that code outside
/// the plugin can call it.
class TetrahedronSetTopologyModifier final : public Base {
 public:
  Data<bool> d_propagateToDOF{this, "propagateToDOF", true,
                              "SOFA option, accepted: Stroma keeps every point when elements are "
                              "removed, so the state vectors keep their size."};
  Data<bool> d_removeIsolated{this, "removeIsolated", true,
                              "SOFA option, accepted: points left without elements are kept (and "
                              "reported once by the topology)."};
  Link<Topology> l_topology{this, "topology",
                            "The topology to change (default: the one in this node)."};

  /// Removes the tetrahedra `indices` (indices before the call; duplicates count once). A bad
  /// index changes nothing and is reported as an error on this component (field "tetrahedra",
  /// with the index and the valid range); returns false then.
  bool removeTetrahedra(std::span<const Index> indices) {
    if (!findTopology()) return false;
    std::string error;
    if (m_topology->removeTetrahedra(indices, error)) return true;
    msgError("cannot remove from " + m_topology->path() + ": " + error, "tetrahedra");
    return false;
  }

  /// The topology it changes (found at first use).
  Topology* findTopology() {
    if (m_topology) return m_topology;
    // The link, else the node's topology that has tetrahedra (a grid may come first), else the
    // node's first topology. Looked up at first use: a topological mapping may fill the
    // container after this component's init.
    m_topology = l_topology.get();
    if (!m_topology && node())
      for (Topology* t : node()->getAll<Topology>())
        if (!m_topology || (m_topology->tetrahedra().empty() && !t->tetrahedra().empty()))
          m_topology = t;
    if (!m_topology)
      msgError(
          "no topology to modify: put a TetrahedronSetTopologyContainer in the node of "
          "the modifier, or set topology=\"@path/to/container\"",
          "topology");
    return m_topology;
  }

 private:
  Topology* m_topology = nullptr;
};

}  // namespace stroma
