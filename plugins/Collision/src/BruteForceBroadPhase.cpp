// SPDX-License-Identifier: MIT
#include "BruteForceBroadPhase.h"

namespace stroma {

void BruteForceBroadPhase::findModelPairs(std::span<CollisionModel* const> models,
                                          std::span<const Aabb> bounds,
                                          std::vector<ModelPair>& pairs) {
  pairs.clear();
  m_bounds.assign(bounds.begin(), bounds.end());
  if (m_bounds.size() == m_tree.size())
    m_tree.refit(m_bounds);
  else
    m_tree.build(m_bounds);
  // Each model with itself first (self-collision), then the overlapping pairs.
  for (CollisionModel* m : models)
    if (m->canCollideWith(*m)) pairs.push_back({m, m});
  m_tree.selfOverlappingPairs(m_overlaps);
  for (const auto& [i, j] : m_overlaps)
    if (models[i]->canCollideWith(*models[j])) pairs.push_back({models[i], models[j]});
}

}  // namespace stroma
