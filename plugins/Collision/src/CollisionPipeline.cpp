// SPDX-License-Identifier: MIT
#include "CollisionPipeline.h"

#include "BVHNarrowPhase.h"
#include "core/Node.h"
#include "simulation/Timing.h"

namespace stroma {

CollisionPipeline::CollisionPipeline() = default;
CollisionPipeline::~CollisionPipeline() = default;

void CollisionPipeline::init() {
  Node* here = node();
  if (!here) return;
  if (here->parent())
    msgWarning("a collision pipeline acts from the root node only: move it to " +
               here->root().path() + " (this one is ignored)");
  m_broad = here->get<BroadPhase>();
  m_narrow = here->get<NarrowPhase>();
  m_intersection = here->get<Intersection>();
  m_manager = here->get<ContactManager>();
  std::string missing;
  auto need = [&](bool found, const char* what) {
    if (found) return;
    missing += missing.empty() ? "" : ", ";
    missing += what;
  };
  need(m_broad, "a broad phase (BruteForceBroadPhase)");
  need(m_intersection,
       "an intersection method (MinProximityIntersection, NewProximityIntersection, "
       "LocalMinDistance or DiscreteIntersection)");
  need(m_manager, "a contact manager (CollisionResponse)");
  if (!missing.empty()) {
    msgError("needs, in its node " + here->path() + ", " + missing);
    return;
  }
  if (!m_narrow) {
    m_ownNarrow = std::make_unique<BVHNarrowPhase>();
    m_narrow = m_ownNarrow.get();
    msgInfo("no narrow phase in " + here->path() + ": a BVHNarrowPhase is used");
  }
}

void CollisionPipeline::collectModels(const Node& node) {
  if (!node.d_activated.value()) return;
  for (const auto& object : node.objects())
    if (auto* model = dynamic_cast<CollisionModel*>(object.get()))
      if (model->isValid() && model->d_active.value()) m_models.push_back(model);
  for (const auto& child : node.children()) collectModels(*child);
}

void CollisionPipeline::computeCollisions(Node& root, Timing& timing) {
  if (node() != &root || !m_broad || !m_intersection || !m_manager) return;
  m_models.clear();
  collectModels(root);
  // Models without primitives (an empty surface, everything cut away) take no part.
  std::erase_if(m_models, [](CollisionModel* m) {
    m->updateGeometry();
    return m->geometry().primitiveCount() == 0;
  });
  {
    ScopedPhase phase(timing, "collision.boxes");
    m_narrow->updateModels(m_models, 0.5 * m_intersection->alarmDistance(), m_bounds);
  }
  {
    ScopedPhase phase(timing, "collision.pairs");
    m_broad->findModelPairs(m_models, m_bounds, m_pairs);
    m_narrow->findContacts(m_pairs, *m_intersection, m_contacts, m_count);
  }
  {
    ScopedPhase phase(timing, "collision.response");
    m_manager->updateResponses(lastContacts(), *m_intersection);
  }
  if (d_verbose.value()) {
    std::size_t total = 0;
    for (const ModelPairContacts& c : lastContacts()) total += c.contacts.size();
    msgInfo(std::to_string(m_models.size()) + " models, " + std::to_string(m_pairs.size()) +
            " pairs of models to test, " + std::to_string(total) + " contacts in " +
            std::to_string(m_count) + " pairs");
  }
}

}  // namespace stroma
