// SPDX-License-Identifier: MIT
#include "ModelSupport.h"

#include <algorithm>

namespace stroma::collision {

const Topology* findModelTopology(const CollisionModel& model, const Link<Topology>& link) {
  if (link) return link.get();
  return model.node() ? model.node()->getUp<Topology>() : nullptr;
}

namespace {

NeighborLists toCsr(std::vector<std::vector<std::uint32_t>>& lists) {
  NeighborLists out;
  out.offsets.reserve(lists.size() + 1);
  out.offsets.push_back(0);
  for (auto& l : lists) {
    std::sort(l.begin(), l.end());
    l.erase(std::unique(l.begin(), l.end()), l.end());
    out.entries.insert(out.entries.end(), l.begin(), l.end());
    out.offsets.push_back(static_cast<std::uint32_t>(out.entries.size()));
  }
  return out;
}

}  // namespace

NeighborLists pointNeighbors(std::size_t pointCount, std::span<const Edge> edges,
                             std::span<const Triangle> triangles) {
  std::vector<std::vector<std::uint32_t>> lists(pointCount);
  auto join = [&](Index a, Index b) {
    if (a < pointCount && b < pointCount && a != b) {
      lists[a].push_back(b);
      lists[b].push_back(a);
    }
  };
  for (const Edge& e : edges) join(e[0], e[1]);
  for (const Triangle& t : triangles) {
    join(t[0], t[1]);
    join(t[1], t[2]);
    join(t[2], t[0]);
  }
  return toCsr(lists);
}

NeighborLists edgeOppositeVertices(std::span<const Edge> edges,
                                   std::span<const Triangle> triangles) {
  // Edge lookup by its sorted end points.
  std::vector<std::pair<std::pair<Index, Index>, std::uint32_t>> keys;
  keys.reserve(edges.size());
  for (std::size_t e = 0; e < edges.size(); ++e)
    keys.push_back({{std::min(edges[e][0], edges[e][1]), std::max(edges[e][0], edges[e][1])},
                    static_cast<std::uint32_t>(e)});
  std::sort(keys.begin(), keys.end());
  std::vector<std::vector<std::uint32_t>> lists(edges.size());
  for (const Triangle& t : triangles)
    for (int k = 0; k < 3; ++k) {
      const Index a = t[k], b = t[(k + 1) % 3], c = t[(k + 2) % 3];
      const std::pair<Index, Index> key{std::min(a, b), std::max(a, b)};
      auto it = std::lower_bound(keys.begin(), keys.end(), std::make_pair(key, std::uint32_t{0}));
      if (it != keys.end() && it->first == key) lists[it->second].push_back(c);
    }
  return toCsr(lists);
}

}  // namespace stroma::collision
