// SPDX-License-Identifier: MIT
#include "topology/TopologyChange.h"

#include <algorithm>
#include <array>
#include <unordered_map>
#include <unordered_set>

#include "topology/MeshAdjacency.h"

namespace stroma {

namespace {

/// The vertices of an element sorted: the same key for any orientation.
template <std::size_t N>
std::array<Index, N> sortedKey(std::array<Index, N> vertices) {
  std::sort(vertices.begin(), vertices.end());
  return vertices;
}

struct KeyHash {
  template <std::size_t N>
  std::size_t operator()(const std::array<Index, N>& key) const {
    std::size_t h = 0;
    for (Index v : key) h = h * 0x9E3779B97F4A7C15ull + v + (h >> 29);
    return h;
  }
};

template <std::size_t N>
using KeySet = std::unordered_set<std::array<Index, N>, KeyHash>;

std::array<Index, 3> faceOf(const Tetrahedron& t, int f) {
  return sortedKey<3>(
      {t[kTetrahedronFaces[f][0]], t[kTetrahedronFaces[f][1]], t[kTetrahedronFaces[f][2]]});
}
std::array<Index, 2> edgeOf(const Tetrahedron& t, int e) {
  return sortedKey<2>({t[kTetrahedronEdges[e][0]], t[kTetrahedronEdges[e][1]]});
}

/// Removes `removed` (decreasing) from `list` by moving the last element into each slot, and
/// records the removal.
template <class Element>
void removeFromList(std::vector<Element>& list, std::vector<Index> removed,
                    ElementRemoval<Element>& out) {
  out.sizeBefore = list.size();
  out.removed = std::move(removed);
  out.removedElements.reserve(out.removed.size());
  // Where each touched slot's element came from (slots absent hold their own element).
  std::unordered_map<Index, Index> origin;
  auto originOf = [&](Index slot) {
    const auto it = origin.find(slot);
    return it == origin.end() ? slot : it->second;
  };
  for (Index r : out.removed) {
    out.removedElements.push_back(list[r]);
    const auto last = static_cast<Index>(list.size() - 1);
    if (r != last) {
      list[r] = list[last];
      origin[r] = originOf(last);
    }
    origin.erase(last);
    list.pop_back();
  }
  out.sizeAfter = list.size();
  for (const auto& [slot, from] : origin)
    if (slot != from) out.moved.emplace_back(from, slot);
  std::sort(out.moved.begin(), out.moved.end());
}

}  // namespace

bool removeTetrahedraFromLists(std::vector<Tetrahedron>& tetrahedra,
                               std::vector<Triangle>& triangles, std::vector<Edge>& edges,
                               std::span<const Index> indices, TopologyChange& change,
                               std::string& error) {
  // 1. Check the indices, then sort them in decreasing order without duplicates.
  for (Index i : indices)
    if (i >= tetrahedra.size()) {
      error = "tetrahedron " + std::to_string(i) + " does not exist (there are " +
              std::to_string(tetrahedra.size()) + " tetrahedra" +
              (tetrahedra.empty() ? std::string()
                                  : ", indices 0 to " + std::to_string(tetrahedra.size() - 1)) +
              ")";
      return false;
    }
  std::vector<Index> removed(indices.begin(), indices.end());
  std::sort(removed.begin(), removed.end());
  removed.erase(std::unique(removed.begin(), removed.end()), removed.end());
  change = TopologyChange{};
  if (removed.empty()) {
    change.tetrahedra.sizeBefore = change.tetrahedra.sizeAfter = tetrahedra.size();
    change.triangles.sizeBefore = change.triangles.sizeAfter = triangles.size();
    change.edges.sizeBefore = change.edges.sizeAfter = edges.size();
    return true;
  }
  auto isRemoved = [&](std::size_t t) {
    return std::binary_search(removed.begin(), removed.end(), static_cast<Index>(t));
  };

  // 2. The points, faces and edges of the removed tetrahedra.
  std::vector<Index> touched;
  KeySet<3> faces;
  KeySet<2> tetEdges;
  for (Index r : removed) {
    const Tetrahedron& t = tetrahedra[r];
    touched.insert(touched.end(), t.begin(), t.end());
    for (int f = 0; f < 4; ++f) faces.insert(faceOf(t, f));
    for (int e = 0; e < 6; ++e) tetEdges.insert(edgeOf(t, e));
  }
  std::sort(touched.begin(), touched.end());
  touched.erase(std::unique(touched.begin(), touched.end()), touched.end());

  // 3. What the remaining tetrahedra around the touched points still use.
  std::vector<char> stillUsed(touched.size(), 0);
  for (std::size_t t = 0; t < tetrahedra.size(); ++t) {
    const Tetrahedron& tet = tetrahedra[t];
    bool near = false;
    for (Index v : tet) {
      const auto it = std::lower_bound(touched.begin(), touched.end(), v);
      if (it != touched.end() && *it == v) {
        near = true;
        if (!isRemoved(t)) stillUsed[static_cast<std::size_t>(it - touched.begin())] = 1;
      }
    }
    if (!near || isRemoved(t)) continue;
    for (int f = 0; f < 4; ++f) faces.erase(faceOf(tet, f));
    for (int e = 0; e < 6; ++e) tetEdges.erase(edgeOf(tet, e));
  }
  for (std::size_t k = 0; k < touched.size(); ++k)
    if (!stillUsed[k]) change.freedPoints.push_back(touched[k]);

  // 4. The listed triangles and edges that no remaining tetrahedron uses.
  std::vector<Index> removedTriangles, removedEdges;
  if (!faces.empty())
    for (std::size_t i = 0; i < triangles.size(); ++i)
      if (faces.contains(sortedKey<3>(triangles[i])))
        removedTriangles.push_back(static_cast<Index>(i));
  if (!tetEdges.empty())
    for (std::size_t i = 0; i < edges.size(); ++i)
      if (tetEdges.contains(sortedKey<2>(edges[i]))) removedEdges.push_back(static_cast<Index>(i));
  std::reverse(removed.begin(), removed.end());
  std::reverse(removedTriangles.begin(), removedTriangles.end());
  std::reverse(removedEdges.begin(), removedEdges.end());

  // 5. Remove, last element into each removed slot.
  removeFromList(tetrahedra, std::move(removed), change.tetrahedra);
  removeFromList(triangles, std::move(removedTriangles), change.triangles);
  removeFromList(edges, std::move(removedEdges), change.edges);
  return true;
}

bool removeTrianglesFromLists(std::vector<Triangle>& triangles, std::vector<Edge>& edges,
                              std::span<const Index> indices, TopologyChange& change,
                              std::string& error) {
  // 1. Check the indices, then sort them in decreasing order without duplicates.
  for (Index i : indices)
    if (i >= triangles.size()) {
      error = "triangle " + std::to_string(i) + " does not exist (there are " +
              std::to_string(triangles.size()) + " triangles" +
              (triangles.empty() ? std::string()
                                 : ", indices 0 to " + std::to_string(triangles.size() - 1)) +
              ")";
      return false;
    }
  std::vector<Index> removed(indices.begin(), indices.end());
  std::sort(removed.begin(), removed.end());
  removed.erase(std::unique(removed.begin(), removed.end()), removed.end());
  change = TopologyChange{};
  change.triangles.sizeBefore = change.triangles.sizeAfter = triangles.size();
  change.edges.sizeBefore = change.edges.sizeAfter = edges.size();
  if (removed.empty()) return true;
  auto isRemoved = [&](std::size_t t) {
    return std::binary_search(removed.begin(), removed.end(), static_cast<Index>(t));
  };
  auto edgeOfTriangle = [](const Triangle& t, int e) {
    return sortedKey<2>({t[e], t[(e + 1) % 3]});
  };

  // 2. The points and edges of the removed triangles.
  std::vector<Index> touched;
  KeySet<2> triangleEdges;
  for (Index r : removed) {
    const Triangle& t = triangles[r];
    touched.insert(touched.end(), t.begin(), t.end());
    for (int e = 0; e < 3; ++e) triangleEdges.insert(edgeOfTriangle(t, e));
  }
  std::sort(touched.begin(), touched.end());
  touched.erase(std::unique(touched.begin(), touched.end()), touched.end());

  // 3. What the remaining triangles around the touched points still use.
  std::vector<char> stillUsed(touched.size(), 0);
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    if (isRemoved(t)) continue;
    const Triangle& tri = triangles[t];
    bool near = false;
    for (Index v : tri) {
      const auto it = std::lower_bound(touched.begin(), touched.end(), v);
      if (it != touched.end() && *it == v) {
        near = true;
        stillUsed[static_cast<std::size_t>(it - touched.begin())] = 1;
      }
    }
    if (near)
      for (int e = 0; e < 3; ++e) triangleEdges.erase(edgeOfTriangle(tri, e));
  }
  for (std::size_t k = 0; k < touched.size(); ++k)
    if (!stillUsed[k]) change.freedPoints.push_back(touched[k]);

  // 4. The listed edges that no remaining triangle uses.
  std::vector<Index> removedEdges;
  if (!triangleEdges.empty())
    for (std::size_t i = 0; i < edges.size(); ++i)
      if (triangleEdges.contains(sortedKey<2>(edges[i])))
        removedEdges.push_back(static_cast<Index>(i));
  std::reverse(removed.begin(), removed.end());
  std::reverse(removedEdges.begin(), removedEdges.end());

  // 5. Remove, last element into each removed slot.
  removeFromList(triangles, std::move(removed), change.triangles);
  removeFromList(edges, std::move(removedEdges), change.edges);
  return true;
}

}  // namespace stroma
