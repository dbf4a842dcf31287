// SPDX-License-Identifier: MIT
#include "Tetra2TriangleTopologicalMapping.h"

#include <algorithm>

#include "TopologyContainer.h"

namespace stroma {

namespace {

std::array<Index, 3> sortedFace(const Triangle& t) {
  std::array<Index, 3> key = t;
  std::sort(key.begin(), key.end());
  return key;
}

}  // namespace

std::size_t Tetra2TriangleTopologicalMapping::FaceKeyHash::operator()(const FaceKey& key) const {
  return (std::size_t{key[0]} * 0x9E3779B97F4A7C15ull) ^
         (std::size_t{key[1]} * 0xC2B2AE3D27D4EB4Full) ^
         (std::size_t{key[2]} * 0x165667B19E3779F9ull);
}

void Tetra2TriangleTopologicalMapping::init() {
  if (!findTopologies(kinds::triangles, "triangles", "TriangleSetTopologyContainer")) {
    setInvalid();
    return;
  }
  std::vector<Triangle> triangles;
  if (!d_noInitialTriangles.value()) {
    if (input()->tetrahedra().empty())
      msgWarning("the input " + input()->path() + " has no tetrahedra: no triangles are made",
                 "input");
    rebuild(triangles);
  } else {
    // The face counts are needed to follow removals even without initial triangles.
    std::vector<Triangle> ignored;
    rebuild(ignored);
    m_outputSlot.clear();
  }
  setOutput(output()->d_triangles, std::move(triangles));
  // From now on the output's triangles follow the input's tetrahedra when read.
  addInput(&input()->d_tetrahedra);
  addOutput(&output()->d_triangles);
  m_following = true;
}

void Tetra2TriangleTopologicalMapping::cleanup() {
  if (m_following && output()) output()->d_triangles.setEngine(nullptr);
  m_following = false;
}

void Tetra2TriangleTopologicalMapping::rebuild(std::vector<Triangle>& triangles) {
  m_revision = input()->revision();
  m_faceUses.clear();
  m_outputSlot.clear();
  for (const Tetrahedron& t : input()->tetrahedra())
    for (const auto& face : kTetrahedronFaces)
      ++m_faceUses[sortedFace({t[face[0]], t[face[1]], t[face[2]]})];
  triangles = input()->boundaryTriangles();
  for (std::size_t i = 0; i < triangles.size(); ++i) {
    if (d_flipNormals.value()) std::swap(triangles[i][1], triangles[i][2]);
    m_outputSlot[sortedFace(triangles[i])] = static_cast<Index>(i);
  }
}

void Tetra2TriangleTopologicalMapping::follow(const std::vector<Tetrahedron>& removed,
                                              std::vector<Triangle>& triangles) {
  for (const Tetrahedron& t : removed)
    for (const auto& local : kTetrahedronFaces) {
      // Outwards from the removed tetrahedron, so inwards for a neighbour that keeps it.
      Triangle face{t[local[0]], t[local[1]], t[local[2]]};
      const FaceKey key = sortedFace(face);
      const auto uses = m_faceUses.find(key);
      if (uses == m_faceUses.end()) continue;  // not a face of the input (changed another way)
      if (--uses->second == 0) {
        m_faceUses.erase(uses);
        // A boundary face with no tetrahedron left: the last triangle moves into its slot.
        const auto slot = m_outputSlot.find(key);
        if (slot == m_outputSlot.end()) continue;
        const Index at = slot->second;
        m_outputSlot.erase(slot);
        if (at + 1 != triangles.size()) {
          triangles[at] = triangles.back();
          m_outputSlot[sortedFace(triangles[at])] = at;
        }
        triangles.pop_back();
      } else if (!d_noNewTriangles.value()) {
        // An inner face now on the boundary, outwards from the tetrahedron that remains.
        if (!d_flipNormals.value()) std::swap(face[1], face[2]);
        m_outputSlot[key] = static_cast<Index>(triangles.size());
        triangles.push_back(face);
      }
    }
}

void Tetra2TriangleTopologicalMapping::doUpdate() {
  if (!input() || !output()) return;
  const std::uint64_t now = input()->revision();
  if (now == m_revision) return;
  std::vector<Triangle> triangles = output()->triangles();
  if (const auto changes = input()->changesSince(m_revision)) {
    for (const TopologyChange& change : *changes)
      follow(change.tetrahedra.removedElements, triangles);
    m_revision = now;
  } else {
    rebuild(triangles);
  }
  output()->d_triangles.setValue(std::move(triangles));
  // The output remakes the edges it made from its triangles.
  output()->reinit();
}

}  // namespace stroma
