// SPDX-License-Identifier: MIT
#include "BVHNarrowPhase.h"

#include <algorithm>

#include "core/Node.h"

namespace stroma {

BVHNarrowPhase::ModelTree& BVHNarrowPhase::treeOf(const CollisionModel& model) {
  for (ModelTree& t : m_trees)
    if (t.model == &model) return t;
  m_trees.emplace_back();
  m_trees.back().model = &model;
  return m_trees.back();
}

void BVHNarrowPhase::updateModels(std::span<CollisionModel* const> models, double margin,
                                  std::vector<Aabb>& bounds) {
  // Trees of models gone from the scene (removed nodes) are dropped.
  std::erase_if(m_trees, [&](const ModelTree& t) {
    return std::find(models.begin(), models.end(), t.model) == models.end();
  });
  bounds.resize(models.size());
  for (std::size_t m = 0; m < models.size(); ++m) {
    ModelTree& t = treeOf(*models[m]);
    const bool built = !t.tree.empty() || !t.boxes.empty();
    if (built && !models[m]->d_moving.value() &&
        t.boxes.size() == models[m]->geometry().primitiveCount()) {
      bounds[m] = t.tree.bounds();
      continue;
    }
    models[m]->computeBoxes(t.boxes, margin);
    const int interval = d_rebuildInterval.value();
    if (t.boxes.size() == t.tree.size() && !(interval > 0 && t.refits >= interval)) {
      t.tree.refit(t.boxes);
      ++t.refits;
    } else {
      t.tree.build(t.boxes);
      t.refits = 0;
    }
    bounds[m] = t.tree.bounds();
  }
}

// A pair of models the intersection has no test for is normal when their objects meet through
// other models (SOFA's line models against triangles, say); it is worth a warning only when no
// model of the one object can be tested against a model of the other: then they never collide.
void BVHNarrowPhase::checkUntested(const ModelPair& pair, const Intersection& intersection) {
  const Node* a = pair.first->node();
  const Node* b = pair.second->node();
  for (const auto& [x, y] : m_checkedObjects)
    if ((x == a && y == b) || (x == b && y == a)) return;
  m_checkedObjects.push_back({a, b});
  const auto modelsA = a->getAll<CollisionModel>();
  const auto modelsB = b->getAll<CollisionModel>();
  for (const CollisionModel* ma : modelsA)
    for (const CollisionModel* mb : modelsB)
      if (intersection.supports(ma->geometry().kind, mb->geometry().kind)) return;
  msgWarning(intersection.className() + " has no test for the models of " + a->path() +
             " against those of " + b->path() + " (" +
             primitiveKindName(pair.first->geometry().kind) + "s against " +
             primitiveKindName(pair.second->geometry().kind) +
             "s): they never collide; give the surfaces point and line models too, as SOFA's "
             "scenes do, or use NewProximityIntersection for triangles against triangles");
}

void BVHNarrowPhase::findContacts(std::span<const ModelPair> pairs,
                                  const Intersection& intersection,
                                  std::vector<ModelPairContacts>& out, std::size_t& count) {
  count = 0;
  for (const ModelPair& pair : pairs) {
    if (!intersection.supports(pair.first->geometry().kind, pair.second->geometry().kind)) {
      checkUntested(pair, intersection);
      continue;
    }
    const ModelTree& a = treeOf(*pair.first);
    const ModelTree& b = treeOf(*pair.second);
    if (pair.first == pair.second)
      a.tree.selfOverlappingPairs(m_candidates);
    else
      a.tree.overlappingPairs(b.tree, m_candidates);
    if (m_candidates.empty()) continue;
    // Each pair of models keeps its own entry (and the capacity of its contact list) from step
    // to step: the entry is moved to slot `count` rather than another pair's list reused.
    auto it = std::find_if(out.begin() + static_cast<std::ptrdiff_t>(count), out.end(),
                           [&](const ModelPairContacts& e) {
                             return e.first == pair.first && e.second == pair.second;
                           });
    if (it == out.end()) {
      out.emplace_back();
      it = out.end() - 1;
      it->first = pair.first;
      it->second = pair.second;
    }
    std::swap(*it, out[count]);
    ModelPairContacts& entry = out[count];
    entry.contacts.clear();
    intersection.intersect(*pair.first, *pair.second, m_candidates, entry.contacts);
    if (!entry.contacts.empty()) ++count;
  }
}

}  // namespace stroma
