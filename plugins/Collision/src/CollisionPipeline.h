// SPDX-License-Identifier: MIT
#pragma once

#include <memory>
#include <vector>

#include "collision/CollisionPipeline.h"

namespace stroma {

class BVHNarrowPhase;

/// SOFA's CollisionPipeline (old name DefaultPipeline), in the root node: the collision step of
/// each animation step (framework/collision/CollisionPipeline.h). It finds the broad phase, the
/// narrow phase (its own BVHNarrowPhase when the scene has none, as SOFA's old
/// BruteForceDetection did both), the intersection method and the contact manager in its node,
/// and every active collision model of the scene.
class CollisionPipeline final : public CollisionPhase {
 public:
  Data<int> d_depth{
      this, "depth", 6, "SOFA option, accepted: the trees have the depth they need.", {.min = 0.0}};
  Data<bool> d_verbose{this, "verbose", false,
                       "Report each step's model pairs and contacts as info messages."};
  Data<bool> d_draw{this, "draw", false, "Viewers only."};

  CollisionPipeline();
  ~CollisionPipeline() override;

  void init() override;
  void computeCollisions(Node& root, Timing& timing) override;

  std::span<const ModelPairContacts> lastContacts() const override {
    return {m_contacts.data(), m_count};
  }
  const Intersection* intersection() const override { return m_intersection; }

 private:
  void collectModels(const Node& node);

  BroadPhase* m_broad = nullptr;
  NarrowPhase* m_narrow = nullptr;
  std::unique_ptr<BVHNarrowPhase> m_ownNarrow;
  Intersection* m_intersection = nullptr;
  ContactManager* m_manager = nullptr;
  std::vector<CollisionModel*> m_models;
  std::vector<Aabb> m_bounds;
  std::vector<ModelPair> m_pairs;
  std::vector<ModelPairContacts> m_contacts;
  std::size_t m_count = 0;
};

}  // namespace stroma
