// SPDX-License-Identifier: MIT
#include "CorotationalFemModel.h"

#include "FemMaterial.h"
#include "FemTopology.h"
#include "core/Node.h"

namespace stroma {

template <class Element>
bool CorotationalFemModel<Element>::init(State* state, fem::RotationMethod method) {
  m_ready = false;
  if (!state) return false;  // ForceField::init reported it
  m_topology = findFemTopology(
      m_owner, m_topologyLink,
      Element::nodeCount == 4 ? FemElementKind::tetrahedra : FemElementKind::hexahedra);
  if (!m_topology || !readElements(*state) || !computeConstants(*state, true)) return false;
  m_elements.updateRotations(method, state->readCoord(VecId::position()),
                             m_owner.node()->threadPool());
  m_ready = true;
  return true;
}

template <class Element>
bool CorotationalFemModel<Element>::readElements(const State& state) {
  m_stateSize = state.size();
  std::vector<typename Elements::Indices> split;
  std::span<const typename Elements::Indices> elements;
  m_readTetrahedra = false;
  if constexpr (Element::nodeCount == 4) {
    elements = m_topology->tetrahedra();
    m_readTetrahedra = !elements.empty();
    if (elements.empty()) {
      // A hexahedral mesh (a grid) given to a tetrahedral force field: SOFA splits it too.
      split = splitHexahedraIntoTetrahedra(m_topology->hexahedra());
      elements = split;
    }
  } else {
    elements = m_topology->hexahedra();
  }
  if (elements.empty()) {
    m_owner.msgError("the topology " + m_topology->path() + " has no " + elementName(), "topology");
    return false;
  }
  if (!checkElementIndices<Element::nodeCount>(m_owner, elementName(), elements, m_stateSize))
    return false;
  if (state.readCoord(VecId::restPosition()).size() != m_stateSize) {
    m_owner.msgError("the mechanical state " + state.path() + " has " +
                         std::to_string(state.readCoord(VecId::restPosition()).size()) +
                         " rest positions for " + std::to_string(m_stateSize) + " points",
                     "mstate");
    return false;
  }
  m_elements.setElements(elements, m_stateSize);
  ++m_elementsRevision;
  // Read after the lists: a topology that makes them on first read (a grid) has then settled.
  m_topologyRevision = m_topology->revision();
  return true;
}

template <class Element>
bool CorotationalFemModel<Element>::computeConstants(const State& state, bool atInit) {
  const std::vector<double>& youngModulus = m_youngModulus.value();
  const double poissonRatio = m_poissonRatio.value();
  m_youngModulusVersion = m_youngModulus.version();
  m_poissonRatioVersion = m_poissonRatio.version();
  if (auto problem = checkMaterial(youngModulus, poissonRatio, m_elements.size(), elementName())) {
    if (atInit) {
      m_owner.msgError(problem->text, problem->field);
    } else {
      m_owner.msgWarning(problem->text +
                             "; the change is not applied, the previous material "
                             "stays",
                         problem->field);
    }
    return false;
  }
  const auto report =
      m_elements.computeConstants(state.readCoord(VecId::restPosition()), youngModulus,
                                  poissonRatio, m_owner.node()->threadPool());
  if (!atInit) return true;  // the rest shape was checked at init
  if (!report.inverted.empty())
    m_owner.msgWarning(
        std::to_string(report.inverted.size()) + " " + elementName() + " of " + m_topology->path() +
            " are inverted in the rest shape (negative volume: their vertex "
            "order is not SOFA's): elements " +
            describeIndices(report.inverted) + "; they are computed with their absolute volume",
        "topology");
  if (!report.degenerate.empty()) {
    m_owner.msgError(std::to_string(report.degenerate.size()) + " " + elementName() + " of " +
                         m_topology->path() +
                         " are degenerate in the rest shape (zero volume, or non-finite "
                         "positions): elements " +
                         describeIndices(report.degenerate),
                     "topology");
    return false;
  }
  return true;
}

template <class Element>
bool CorotationalFemModel<Element>::followRemovals(const State& state) {
  if (!m_ready || !m_readTetrahedra || state.size() != m_stateSize) return false;
  const auto changes = m_topology->changesSince(m_topologyRevision);
  if (!changes) return false;
  for (const TopologyChange& change : *changes) {
    // A change made before these elements were read would not match them: rebuild.
    if (change.tetrahedra.sizeBefore != m_elements.size()) return false;
    m_elements.removeElements(change.tetrahedra.removed);
  }
  ++m_elementsRevision;
  m_topologyRevision = m_topology->revision();
  return true;
}

template <class Element>
bool CorotationalFemModel<Element>::refresh(State& state, fem::RotationMethod method) {
  if (!m_topology) return false;
  if (m_topology->revision() != m_topologyRevision && followRemovals(state)) return m_ready;
  if (m_topology->revision() != m_topologyRevision || state.size() != m_stateSize) {
    // The mesh changed: start again (allocates, as a topological change does).
    if (!readElements(state) || !computeConstants(state, true)) {
      m_ready = false;
      return false;
    }
    m_elements.updateRotations(method, state.readCoord(VecId::position()),
                               m_owner.node()->threadPool());
    m_ready = true;
    return true;
  }
  if (m_ready && (m_youngModulus.version() != m_youngModulusVersion ||
                  m_poissonRatio.version() != m_poissonRatioVersion))
    computeConstants(state, false);
  return m_ready;
}

template class CorotationalFemModel<fem::CorotationalTetrahedron>;
template class CorotationalFemModel<fem::CorotationalHexahedron>;

}  // namespace stroma
