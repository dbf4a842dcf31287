// SPDX-License-Identifier: MIT
#include "FemTopology.h"

#include "core/Node.h"

namespace stroma {

namespace {

bool holds(const Topology& topology, FemElementKind kind) {
  return kind == FemElementKind::tetrahedra ? !topology.tetrahedra().empty()
                                            : !topology.hexahedra().empty();
}

// The last topology of `node` holding elements of `kind`.
const Topology* lastHolding(const Node& node, FemElementKind kind) {
  const Topology* found = nullptr;
  for (const Topology* topology : node.getAll<Topology>())
    if (holds(*topology, kind)) found = topology;
  return found;
}

}  // namespace

const Topology* findFemTopology(Base& owner, const Link<Topology>& link, FemElementKind kind) {
  const char* elements = kind == FemElementKind::tetrahedra ? "tetrahedra" : "hexahedra";
  if (link) {
    const bool usable = holds(*link.get(), kind) || (kind == FemElementKind::tetrahedra &&
                                                     holds(*link.get(), FemElementKind::hexahedra));
    if (!usable) {
      owner.msgError("the topology " + link->path() + " has no " + elements, "topology");
      return nullptr;
    }
    return link.get();
  }
  const Topology* anyTopology = nullptr;
  for (const Node* node = owner.node(); node; node = node->parent()) {
    if (const Topology* t = lastHolding(*node, kind)) return t;
    if (kind == FemElementKind::tetrahedra)
      if (const Topology* t = lastHolding(*node, FemElementKind::hexahedra)) return t;
    if (!anyTopology) anyTopology = node->get<Topology>();
  }
  if (anyTopology)
    owner.msgError("no topology with " + std::string(elements) + " in its node or above (" +
                       anyTopology->path() + " has none): give a mesh with " + elements +
                       " or a 'topology' link",
                   "topology");
  else
    owner.msgError("needs a topology with " + std::string(elements) +
                       " (TetrahedronSetTopologyContainer, MeshTopology, RegularGridTopology, "
                       "...) in its node or above, or a 'topology' link",
                   "topology");
  return nullptr;
}

std::vector<Tetrahedron> splitHexahedraIntoTetrahedra(std::span<const Hexahedron> hexahedra) {
  // The six monotone paths 0 -> 6 through the cube (one per order of the axes), each vertex
  // order chosen so that the tetrahedron is positive for a positive hexahedron
  // (TopologyTypes.h); tests check both properties.
  static constexpr std::array<std::array<int, 4>, 6> kSplit{
      {{0, 1, 2, 6}, {0, 1, 6, 5}, {0, 3, 6, 2}, {0, 3, 7, 6}, {0, 4, 5, 6}, {0, 4, 6, 7}}};
  std::vector<Tetrahedron> tetrahedra;
  tetrahedra.reserve(6 * hexahedra.size());
  for (const Hexahedron& h : hexahedra)
    for (const auto& t : kSplit) tetrahedra.push_back({h[t[0]], h[t[1]], h[t[2]], h[t[3]]});
  return tetrahedra;
}

template <std::size_t N>
bool checkElementIndices(Base& owner, const std::string& what,
                         std::span<const std::array<Index, N>> elements, std::size_t pointCount) {
  std::vector<Index> bad;
  for (std::size_t e = 0; e < elements.size(); ++e)
    for (Index v : elements[e])
      if (v >= pointCount) {
        bad.push_back(static_cast<Index>(e));
        break;
      }
  if (bad.empty()) return true;
  std::string first;
  for (Index v : elements[bad.front()]) first += ' ' + std::to_string(v);
  owner.msgError(std::to_string(bad.size()) + " " + what + " use points out of range of the " +
                     std::to_string(pointCount) + " points of the mechanical state: elements " +
                     describeIndices(bad) + " (element " + std::to_string(bad.front()) + ":" +
                     first + ")",
                 "topology");
  return false;
}

template bool checkElementIndices<3>(Base&, const std::string&, std::span<const Triangle>,
                                     std::size_t);
template bool checkElementIndices<4>(Base&, const std::string&, std::span<const Tetrahedron>,
                                     std::size_t);
template bool checkElementIndices<8>(Base&, const std::string&, std::span<const Hexahedron>,
                                     std::size_t);

std::string describeIndices(std::span<const Index> indices) {
  constexpr std::size_t kShown = 10;
  std::string text;
  for (std::size_t i = 0; i < indices.size() && i < kShown; ++i)
    text += (i ? ", " : "") + std::to_string(indices[i]);
  if (indices.size() > kShown) text += ", ... (" + std::to_string(indices.size()) + " in all)";
  return text;
}

}  // namespace stroma
