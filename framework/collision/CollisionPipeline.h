// SPDX-License-Identifier: MIT
// The phases of collision detection and response, as interfaces the plugins implement (SOFA's
// split, which scenes name component by component):
//
//   CollisionPhase (CollisionPipeline)     once per step, before the solvers, when present
//     models: updateGeometry, boxes
//     BroadPhase (BruteForceBroadPhase)   which pairs of models may touch
//     NarrowPhase (BVHNarrowPhase)        which pairs of primitives may touch (their boxes)
//       Intersection (MinProximityIntersection, LocalMinDistance, ...)
//                                         the exact test: contacts within the alarm distance
//     ContactManager (CollisionResponse)  contacts -> responses (penalty force fields, ...)
//
// A scene without a CollisionPhase in its root node has no collision step at all.
#pragma once

#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "collision/Aabb.h"
#include "collision/CollisionModel.h"
#include "collision/Contact.h"
#include "core/Base.h"

namespace stroma {

class Node;
class Timing;

/// Two models to test against each other (the same one twice for self-collision).
struct ModelPair {
  CollisionModel* first = nullptr;
  CollisionModel* second = nullptr;
};

/// A pair of primitives, index in the first and in the second model.
using PrimitivePair = std::pair<std::uint32_t, std::uint32_t>;

/// Which pairs of models may touch.
class BroadPhase : public Base {
 public:
  /// Appends the pairs of `models` whose `bounds` overlap and that may collide
  /// (CollisionModel::canCollideWith), a model with itself when it asks for self-collision.
  virtual void findModelPairs(std::span<CollisionModel* const> models, std::span<const Aabb> bounds,
                              std::vector<ModelPair>& pairs) = 0;
};

/// The exact proximity test of pairs of primitives.
class Intersection : public Base {
 public:
  /// Pairs farther apart than this (plus both models' contactDistance) are not contacts.
  virtual double alarmDistance() const = 0;
  /// The gap that responses keep between the surfaces (penalty forces start below it).
  virtual double contactDistance() const = 0;
  /// Whether it has a test for these kinds of primitives (in either order).
  virtual bool supports(PrimitiveKind a, PrimitiveKind b) const = 0;
  /// Appends to `contacts` those of the `candidates` (index in `first`, index in `second`) whose
  /// gap is below the alarm distance. For a model against itself, pairs that share a vertex
  /// are skipped.
  virtual void intersect(const CollisionModel& first, const CollisionModel& second,
                         std::span<const PrimitivePair> candidates,
                         std::vector<Contact>& contacts) const = 0;
};

/// Which pairs of primitives may touch, and their contacts.
class NarrowPhase : public Base {
 public:
  /// Brings each model's hierarchy up to date with its geometry (primitive boxes enlarged by
  /// `margin` and the model's contactDistance) and gives each model's bounds (`bounds[i]` for
  /// `models[i]`).
  virtual void updateModels(std::span<CollisionModel* const> models, double margin,
                            std::vector<Aabb>& bounds) = 0;
  /// For each pair of models: the primitive pairs whose boxes overlap, tested by
  /// `intersection`. The first `count` entries of `out` get the pairs that have contacts
  /// (entries are reused from step to step: no allocation once warm).
  virtual void findContacts(std::span<const ModelPair> pairs, const Intersection& intersection,
                            std::vector<ModelPairContacts>& out, std::size_t& count) = 0;
};

/// Turns contacts into responses.
class ContactManager : public Base {
 public:
  /// This step's contacts (`count` entries of `contacts`); pairs that lost theirs drop their
  /// responses. Responses are kept from step to step and reused.
  virtual void updateResponses(std::span<const ModelPairContacts> contacts,
                               const Intersection& intersection) = 0;
};

/// The collision step the animation loop runs before the solvers.
class CollisionPhase : public Base {
 public:
  virtual void computeCollisions(Node& root, Timing& timing) = 0;
  /// The contacts of the last step, per pair of models (for viewers and tests).
  virtual std::span<const ModelPairContacts> lastContacts() const = 0;
  /// The intersection method, or nullptr when there is none.
  virtual const Intersection* intersection() const = 0;
};

}  // namespace stroma
