// SPDX-License-Identifier: MIT
#pragma once

#include "Collision/kernels/PrimitiveTree.h"
#include "collision/CollisionPipeline.h"

namespace stroma {

/// SOFA's BruteForceBroadPhase (old name BruteForceDetection): every pair of models whose
/// bounds overlap and that may collide. The bounds go in a Bullet tree (PrimitiveTree), refitted
/// each step, so the pairs cost the overlaps found rather than all pairs of models; the result
/// is the brute-force one, exactly.
class BruteForceBroadPhase final : public BroadPhase {
 public:
  void findModelPairs(std::span<CollisionModel* const> models, std::span<const Aabb> bounds,
                      std::vector<ModelPair>& pairs) override;

 private:
  collision::PrimitiveTree m_tree;
  std::vector<Aabb> m_bounds;
  std::vector<collision::PrimitivePair> m_overlaps;
};

}  // namespace stroma
