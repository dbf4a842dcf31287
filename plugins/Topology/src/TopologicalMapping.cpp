// SPDX-License-Identifier: MIT
#include "TopologicalMapping.h"

#include "TopologyContainer.h"
#include "core/Node.h"

namespace stroma {

Topology* TopologicalMapping::topologyOf(const Link<Base>& link, const char* expectedClass) {
  Base* target = link.get();
  if (!target) {
    msgError(std::string("no ") + link.name() + " topology: set " + link.name() + "=\"@path/to/" +
                 expectedClass + "\"",
             link.name());
    return nullptr;
  }
  if (auto* topology = dynamic_cast<Topology*>(target)) return topology;
  if (auto* node = dynamic_cast<Node*>(target)) {
    if (auto* topology = node->get<Topology>()) return topology;
    msgError("the node " + node->path() + " holds no topology", link.name());
    return nullptr;
  }
  msgError(target->path() + " is a " + target->className() + ", not a topology", link.name());
  return nullptr;
}

bool TopologicalMapping::findTopologies(unsigned kind, const char* kindName,
                                        const char* expectedClass) {
  m_input = topologyOf(l_input, "topology");
  m_output = topologyOf(l_output, expectedClass);
  if (!m_input || !m_output) return false;
  if (const auto* container = dynamic_cast<const TopologyContainer*>(m_output);
      container && !container->holds(kind)) {
    msgError("the output " + m_output->path() + " is a " + m_output->className() +
                 ", which keeps no " + kindName + "; expected a " + expectedClass,
             "output");
    return false;
  }
  if (m_input == m_output) {
    msgError("the input and the output are the same topology", "output");
    return false;
  }
  return true;
}

}  // namespace stroma
