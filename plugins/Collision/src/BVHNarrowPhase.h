// SPDX-License-Identifier: MIT
#pragma once

#include <vector>

#include "Collision/kernels/PrimitiveTree.h"
#include "collision/CollisionPipeline.h"

namespace stroma {

/// SOFA's BVHNarrowPhase: for each pair of models, the pairs of primitives whose boxes overlap,
/// from a Bullet tree per model (PrimitiveTree) refitted each step as the surfaces move (the
/// tree reinserts its leaves by itself when a refit has doubled its cost), built again when the
/// primitive count changes (a cut) and, if asked, every `rebuildInterval` steps; then the
/// intersection method's exact tests. A model with `moving` false keeps the boxes of its first
/// step.
class BVHNarrowPhase final : public NarrowPhase {
 public:
  Data<int> d_rebuildInterval{this,
                              "rebuildInterval",
                              0,
                              "Steps between two builds of a moving model's tree (refits in "
                              "between; 0: refits only, while the primitive count holds).",
                              {.min = 0.0}};

  void updateModels(std::span<CollisionModel* const> models, double margin,
                    std::vector<Aabb>& bounds) override;
  void findContacts(std::span<const ModelPair> pairs, const Intersection& intersection,
                    std::vector<ModelPairContacts>& out, std::size_t& count) override;

 private:
  struct ModelTree {
    const CollisionModel* model = nullptr;
    collision::PrimitiveTree tree;
    std::vector<Aabb> boxes;
    int refits = 0;  // since the last build
  };
  ModelTree& treeOf(const CollisionModel& model);
  void checkUntested(const ModelPair& pair, const Intersection& intersection);

  std::vector<ModelTree> m_trees;
  std::vector<collision::PrimitivePair> m_candidates;
  std::vector<std::pair<const Node*, const Node*>> m_checkedObjects;
};

}  // namespace stroma
