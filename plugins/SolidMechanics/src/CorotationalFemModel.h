// SPDX-License-Identifier: MIT
// CorotationalFemModel<Element>: what a corotational FEM force field does besides computing
// forces (TetrahedronFEMForceField, HexahedronFEMForceField, HexahedronFEMForceFieldAndMass
// each own one): find the topology, read and check the elements against the state, check the
// material, compute the element constants (CorotationalElements), report bad input on the
// component, and redo what changed while running (the material, the topology, the state size).
#pragma once

#include <cstdint>
#include <vector>

#include "CorotationalElements.h"
#include "core/Base.h"
#include "core/Link.h"
#include "core/StateTypes.h"
#include "simulation/MechanicalState.h"
#include "topology/Topology.h"

namespace stroma {

template <class Element>
class CorotationalFemModel {
 public:
  using Elements = CorotationalElements<Element>;
  using State = MechanicalState<Vec3Types>;

  /// `owner` reports; the Data and link are its fields (they outlive this object).
  CorotationalFemModel(Base& owner, const Data<std::vector<double>>& youngModulus,
                       const Data<double>& poissonRatio, const Link<Topology>& topology)
      : m_owner(owner),
        m_youngModulus(youngModulus),
        m_poissonRatio(poissonRatio),
        m_topologyLink(topology) {}

  /// Finds the topology, reads the elements, checks them and the material, computes the
  /// constants from the state's rest positions and the rotations at its positions. Errors go
  /// to the owner (bad input); returns false after one.
  bool init(State* state, fem::RotationMethod method);

  /// Call at the start of addForce: recomputes the constants when youngModulus or
  /// poissonRatio changed (an invalid change is a warning and is not applied), everything when
  /// the topology's elements or the state's size changed. Tetrahedra removed at run time
  /// (cutting, Topology::removeTetrahedra) are followed instead: the per-element data of the
  /// removed and moved elements only, nothing recomputed (CorotationalElements::removeElements);
  /// with no tetrahedron left the force is zero. Returns ready().
  bool refresh(State& state, fem::RotationMethod method);

  /// True once init succeeded (the loops may run).
  bool ready() const { return m_ready; }
  const Topology* topology() const { return m_topology; }
  /// Incremented each time the elements are read (init, topology or state size changes):
  /// what a component derives from the elements is stale when it changed.
  std::uint64_t elementsRevision() const { return m_elementsRevision; }
  Elements& elements() { return m_elements; }
  const Elements& elements() const { return m_elements; }

 private:
  bool readElements(const State& state);
  /// Follows the logged removals since the elements were read; false when they cannot be
  /// followed (not logged, hexahedra, elements split from a grid, a new state size).
  bool followRemovals(const State& state);
  bool computeConstants(const State& state, bool atInit);
  const char* elementName() const { return Element::nodeCount == 4 ? "tetrahedra" : "hexahedra"; }

  Base& m_owner;
  const Data<std::vector<double>>& m_youngModulus;
  const Data<double>& m_poissonRatio;
  const Link<Topology>& m_topologyLink;

  Elements m_elements;
  const Topology* m_topology = nullptr;
  bool m_ready = false;
  bool m_readTetrahedra = false;  ///< the elements are the topology's tetrahedra, in its order
  std::size_t m_stateSize = 0;
  std::uint64_t m_topologyRevision = 0;
  std::uint64_t m_elementsRevision = 0;
  std::uint64_t m_youngModulusVersion = 0;
  std::uint64_t m_poissonRatioVersion = 0;
};

extern template class CorotationalFemModel<fem::CorotationalTetrahedron>;
extern template class CorotationalFemModel<fem::CorotationalHexahedron>;

}  // namespace stroma
