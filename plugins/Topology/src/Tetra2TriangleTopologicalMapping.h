// SPDX-License-Identifier: MIT
#pragma once

#include <array>
#include <unordered_map>

#include "TopologicalMapping.h"

namespace stroma {

/// The boundary of the input's tetrahedra: the triangles that belong to one tetrahedron,
/// oriented outwards (for positive tetrahedra), in order of first appearance.
///
/// When tetrahedra are removed at run time (Topology::removeTetrahedra), the output follows on
/// its next read (the mapping is the engine of the output's triangles): each face of a removed
/// tetrahedron that was on the boundary goes (the last triangle moving into its slot), and each
/// that the removal exposes (shared with a remaining tetrahedron) is appended, oriented outwards
/// from that tetrahedron. The cost is proportional to the removed tetrahedra (plus the output's
/// own edges, remade from its triangles). A change the input did not log rebuilds the boundary.
class Tetra2TriangleTopologicalMapping final : public TopologicalMapping, public DataEngine {
 public:
  Data<bool> d_flipNormals{this, "flipNormals", false,
                           "Orient the triangles inwards instead of outwards."};
  Data<bool> d_noNewTriangles{this, "noNewTriangles", false,
                              "When tetrahedra are removed, only remove the triangles that are no "
                              "longer on the boundary, do not add the faces the removal exposes."};
  Data<bool> d_noInitialTriangles{this, "noInitialTriangles", false,
                                  "Leave the output without triangles at init."};
  void init() override;
  /// Stops following the input (the output's triangles no longer name this engine).
  void cleanup() override;

 protected:
  void doUpdate() override;

 private:
  using FaceKey = std::array<Index, 3>;
  struct FaceKeyHash {
    std::size_t operator()(const FaceKey& key) const;
  };
  /// Recomputes the whole boundary and the face counts.
  void rebuild(std::vector<Triangle>& triangles);
  /// Follows the removal of `removed` (the removed tetrahedra's vertices).
  void follow(const std::vector<Tetrahedron>& removed, std::vector<Triangle>& triangles);

  bool m_following = false;
  std::uint64_t m_revision = 0;
  /// How many tetrahedra of the input use each face (1 or 2).
  std::unordered_map<FaceKey, unsigned char, FaceKeyHash> m_faceUses;
  /// Where each boundary face is in the output's triangles.
  std::unordered_map<FaceKey, Index, FaceKeyHash> m_outputSlot;
};

}  // namespace stroma
