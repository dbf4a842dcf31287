// SPDX-License-Identifier: MIT
#include "Collision/kernels/PrimitiveTree.h"

#include <BulletCollision/BroadphaseCollision/btDbvt.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <random>
#include <stdexcept>
#include <string>

namespace stroma::collision {

namespace {

// Bullet's recursion threshold of optimizeTopDown: below it, a group of leaves is paired
// bottom-up, O(k^3) in the group size k. Its default (128) makes a build of 10,000 boxes cost
// six times more than this one (46 ms) for queries 5% faster (README-tree.md).
constexpr int kBottomUpThreshold = 32;

// Seed of the insertion order of build() (any fixed value: builds are reproducible).
constexpr std::uint32_t kShuffleSeed = 20240607;

// refit() reinserts every leaf when the tree's cost exceeds this multiple of its cost when made.
constexpr double kReinsertionFactor = 2.0;

// Surface area of a volume; 0 for an empty one (negative lengths, from empty leaves).
double surfaceArea(const btDbvtVolume& volume) {
  const btVector3 lengths = volume.Lengths();
  const double x = std::max<double>(lengths.x(), 0);
  const double y = std::max<double>(lengths.y(), 0);
  const double z = std::max<double>(lengths.z(), 0);
  return x * y + y * z + z * x;
}

// Leaf volumes: the box coordinates clamped to [-2^40, 2^40], then rounded to the nearest
// btScalar (float in Debian's Bullet). Both maps are monotone (x <= y gives f(x) <= f(y)), so
// when two boxes overlap their volumes do, and so do the volumes of all their ancestors (Bullet
// merges children by min and max, which keeps every non-empty child inside): the traversal meets
// every overlapping leaf pair. The rounding may make boxes apart by less than a float's
// precision touch, and an empty box keeps its inverted volume, which may still meet others; the
// exact test on the double boxes drops both.
// The clamp keeps Bullet's top-down build finite: it takes centres, differences and volumes
// (products of three edge lengths) of leaf volumes, and corrupts memory when they are infinite
// or NaN (an infinite coordinate, or a float overflow beyond 1e38).
constexpr double kLargestCoordinate = 0x1p40;

btScalar scalarOf(double x) {
  return static_cast<btScalar>(std::clamp(x, -kLargestCoordinate, kLargestCoordinate));
}

btDbvtVolume volumeOf(const Aabb& box) {
  return btDbvtVolume::FromMM(
      btVector3(scalarOf(box.min.x()), scalarOf(box.min.y()), scalarOf(box.min.z())),
      btVector3(scalarOf(box.max.x()), scalarOf(box.max.y()), scalarOf(box.max.z())));
}

// A leaf stores its primitive index in its data pointer.
void* dataOf(std::uint32_t index) { return reinterpret_cast<void*>(std::uintptr_t{index}); }
std::uint32_t indexOf(const btDbvtNode* leaf) {
  return static_cast<std::uint32_t>(reinterpret_cast<std::uintptr_t>(leaf->data));
}

// The union of the non-empty `boxes`, after checking that no coordinate is NaN; `function`
// names the caller in the exception.
Aabb checkedUnion(const std::vector<Aabb>& boxes, const char* function) {
  Aabb bounds;
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    const Aabb& box = boxes[i];
    if (box.min.hasNaN() || box.max.hasNaN()) {
      const auto text = [](const Vec3d& v) {
        return std::to_string(v.x()) + " " + std::to_string(v.y()) + " " + std::to_string(v.z());
      };
      throw std::invalid_argument(std::string("PrimitiveTree::") + function + ": box " +
                                  std::to_string(i) + " has a NaN coordinate (min " +
                                  text(box.min) + ", max " + text(box.max) + ")");
    }
    bounds.merge(box);
  }
  return bounds;
}

// Bullet's traversal stack of the calling thread. btDbvt::collideTTpersistentStack keeps its
// stack in the btDbvt it is called on, whatever roots it is given; calling it on this empty
// tree makes the queries const, safe to run from several threads, and free of allocation once
// the stack has grown (plain collideTT allocates a stack on every call).
btDbvt& traversalStack() {
  thread_local btDbvt host;
  return host;
}

// Leaf pairs met by the tree/tree traversal, kept when their double boxes overlap.
struct PairCollector : btDbvt::ICollide {
  using btDbvt::ICollide::Process;

  const std::vector<Aabb>* boxes0;
  const std::vector<Aabb>* boxes1;
  std::vector<PrimitivePair>* pairs;
  bool self;  // one tree against itself: each unordered pair {i, j} is met once, i != j

  void Process(const btDbvtNode* leaf0, const btDbvtNode* leaf1) override {
    std::uint32_t i = indexOf(leaf0);
    std::uint32_t j = indexOf(leaf1);
    if (!(*boxes0)[i].overlaps((*boxes1)[j])) return;
    if (self && i > j) std::swap(i, j);
    pairs->emplace_back(i, j);
  }
};

}  // namespace

struct PrimitiveTree::Impl {
  btDbvt tree;
  std::vector<btDbvtNode*> leaves;            // (n) leaf of each primitive
  std::vector<btDbvtNode*> internalsUpwards;  // (n - 1) internal nodes, children before parents
  std::vector<Aabb> boxes;                    // (n) the exact boxes
  Aabb bounds;                                // empty
  double referenceCost = 0;                   // cost() after the last build or reinsertion
  std::size_t reinsertions = 0;

  // The internal nodes, parents first (breadth first), then reversed. Allocates nothing once
  // internalsUpwards has held n - 1 nodes.
  void collectInternals() {
    internalsUpwards.clear();
    if (tree.m_root && tree.m_root->isinternal()) internalsUpwards.push_back(tree.m_root);
    for (std::size_t k = 0; k < internalsUpwards.size(); ++k) {
      for (btDbvtNode* child : internalsUpwards[k]->childs) {
        if (child->isinternal()) internalsUpwards.push_back(child);
      }
    }
    std::reverse(internalsUpwards.begin(), internalsUpwards.end());
  }

  // Surface area heuristic (MacDonald and Booth 1990): the sum of the internal nodes' surface
  // areas over the root's, proportional to the expected number of nodes that a query visits.
  double cost() const {
    double areas = 0;
    for (const btDbvtNode* node : internalsUpwards) areas += surfaceArea(node->volume);
    return costOf(areas);
  }
  // The cost of a tree whose internal nodes' areas sum to `areas`: 0 for a tree of at most one
  // leaf or of zero root area.
  double costOf(double areas) const {
    const double rootArea = tree.m_root ? surfaceArea(tree.m_root->volume) : 0;
    return rootArea > 0 ? areas / rootArea : 0;
  }
};

PrimitiveTree::PrimitiveTree() : m_impl(std::make_unique<Impl>()) {}
PrimitiveTree::~PrimitiveTree() = default;
PrimitiveTree::PrimitiveTree(PrimitiveTree&&) noexcept = default;
PrimitiveTree& PrimitiveTree::operator=(PrimitiveTree&&) noexcept = default;

void PrimitiveTree::build(const std::vector<Aabb>& boxes) {
  if (boxes.size() > static_cast<std::size_t>(std::numeric_limits<int>::max())) {
    throw std::invalid_argument("PrimitiveTree::build: " + std::to_string(boxes.size()) +
                                " boxes, more than a btDbvt holds (2^31 - 1)");
  }
  const Aabb bounds = checkedUnion(boxes, "build");
  if (!m_impl) m_impl = std::make_unique<Impl>();
  Impl& t = *m_impl;
  const std::size_t n = boxes.size();

  // Leaves by Bullet's incremental insertion in a shuffled order: primitives come in mesh
  // order, and inserted so they make a tree hundreds of levels deep (220 for a 10,000-triangle
  // sphere) and slow to insert into.
  std::vector<std::uint32_t> order(n);
  std::iota(order.begin(), order.end(), 0u);
  std::mt19937 rng(kShuffleSeed);
  for (std::size_t k = n; k > 1; --k) std::swap(order[k - 1], order[rng() % k]);
  t.tree.clear();
  t.tree.m_leaves = 0;  // clear() leaves the count as it was
  t.leaves.resize(n);
  for (const std::uint32_t i : order) t.leaves[i] = t.tree.insert(volumeOf(boxes[i]), dataOf(i));
  // Then Bullet's top-down rebuild of the internal nodes (the leaf nodes stay).
  t.tree.optimizeTopDown(kBottomUpThreshold);

  t.internalsUpwards.reserve(n == 0 ? 0 : n - 1);
  t.collectInternals();
  t.referenceCost = t.cost();
  t.reinsertions = 0;
  t.boxes = boxes;
  t.bounds = bounds;
}

void PrimitiveTree::refit(const std::vector<Aabb>& boxes) {
  if (boxes.size() != size()) {
    throw std::invalid_argument("PrimitiveTree::refit: " + std::to_string(boxes.size()) +
                                " boxes for a tree of " + std::to_string(size()) +
                                " primitives (call build() when the primitives change)");
  }
  const Aabb bounds = checkedUnion(boxes, "refit");
  if (boxes.empty()) return;
  Impl& t = *m_impl;

  // New leaf volumes, then each internal volume as the union of its children's, children first.
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    t.boxes[i] = boxes[i];
    t.leaves[i]->volume = volumeOf(boxes[i]);
  }
  double areas = 0;
  for (btDbvtNode* node : t.internalsUpwards) {
    Merge(node->childs[0]->volume, node->childs[1]->volume, node->volume);
    areas += surfaceArea(node->volume);
  }

  // A tree whose cost has grown kReinsertionFactor times since it was made no longer follows
  // the primitives: every leaf is taken out and inserted again from the root (btDbvt::update,
  // which reuses the node it frees, so nothing is allocated).
  if (t.costOf(areas) > kReinsertionFactor * t.referenceCost) {
    for (btDbvtNode* leaf : t.leaves) t.tree.update(leaf, -1);
    t.collectInternals();
    t.referenceCost = t.cost();
    ++t.reinsertions;
  }
  t.bounds = bounds;
}

std::size_t PrimitiveTree::size() const { return m_impl ? m_impl->leaves.size() : 0; }

std::size_t PrimitiveTree::reinsertions() const { return m_impl ? m_impl->reinsertions : 0; }

Aabb PrimitiveTree::bounds() const { return m_impl ? m_impl->bounds : Aabb{}; }

void PrimitiveTree::overlappingPairs(const PrimitiveTree& other,
                                     std::vector<PrimitivePair>& pairs) const {
  pairs.clear();
  if (empty() || other.empty()) return;
  if (&other == this) {
    // Bullet traverses a tree against itself as a self-collision (each unordered pair of
    // distinct leaves once): add the mirrored pairs and every non-empty box with itself.
    selfOverlappingPairs(pairs);
    const std::size_t distinct = pairs.size();
    for (std::size_t k = 0; k < distinct; ++k) pairs.emplace_back(pairs[k].second, pairs[k].first);
    for (std::uint32_t i = 0; i < size(); ++i) {
      if (!m_impl->boxes[i].empty()) pairs.emplace_back(i, i);
    }
    return;
  }
  PairCollector collector;
  collector.boxes0 = &m_impl->boxes;
  collector.boxes1 = &other.m_impl->boxes;
  collector.pairs = &pairs;
  collector.self = false;
  traversalStack().collideTTpersistentStack(m_impl->tree.m_root, other.m_impl->tree.m_root,
                                            collector);
}

void PrimitiveTree::selfOverlappingPairs(std::vector<PrimitivePair>& pairs) const {
  pairs.clear();
  if (size() < 2) return;
  PairCollector collector;
  collector.boxes0 = &m_impl->boxes;
  collector.boxes1 = &m_impl->boxes;
  collector.pairs = &pairs;
  collector.self = true;
  traversalStack().collideTTpersistentStack(m_impl->tree.m_root, m_impl->tree.m_root, collector);
}

}  // namespace stroma::collision
