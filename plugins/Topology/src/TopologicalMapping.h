// SPDX-License-Identifier: MIT
#pragma once

#include <string>
#include <vector>

#include "core/Link.h"
#include "topology/Topology.h"

namespace stroma {

/// What SOFA's topological mappings share: an input topology and an output one, linked as
/// input="@..." output="@...". At init the mapping computes the output's elements from the
/// input's, sets them on the output (which then makes its sub-elements and checks them), and
/// gives the output the input's points when it has none. After init, only
/// Tetra2TriangleTopologicalMapping follows the input's changes (removed tetrahedra); the others
/// keep their output as made at init.
class TopologicalMapping : public Base {
 public:
  Link<Base> l_input{this, "input",
                     "The topology the elements are computed from (or a node holding one)."};
  Link<Base> l_output{this, "output",
                      "The topology that receives the computed elements (or a node holding one)."};

 protected:
  /// Finds both topologies and checks that the output keeps `kind` (a kinds:: bit named
  /// `kindName`). Reports what is wrong and returns false.
  bool findTopologies(unsigned kind, const char* kindName, const char* expectedClass);
  Topology* input() const { return m_input; }
  Topology* output() const { return m_output; }
  /// Sets `values` as the output's list `data` and completes the output.
  template <class T>
  void setOutput(Data<std::vector<T>>& data, std::vector<T> values);

 private:
  /// The topology a link names: the object itself, or the first topology of the node it names.
  Topology* topologyOf(const Link<Base>& link, const char* expectedClass);

  Topology* m_input = nullptr;
  Topology* m_output = nullptr;
};

template <class T>
void TopologicalMapping::setOutput(Data<std::vector<T>>& data, std::vector<T> values) {
  Topology& output = *m_output;
  std::string ignored;
  data.setParent(nullptr, ignored);
  data.setValue(std::move(values));
  if (output.positions().empty() && output.d_position.linkText().empty() &&
      !m_input->positions().empty())
    output.d_position.setValue(m_input->positions());
  output.reinit();
}

}  // namespace stroma
