// SPDX-License-Identifier: MIT
// PrimitiveTree: the bounding-volume hierarchy over the primitive boxes of one collision model
// (triangles, edges, points, spheres), on Bullet's dynamic AABB tree btDbvt. It answers the
// broad/mid-phase question "which primitive boxes overlap", between two models or within one
// (self-collision), exactly: the pairs are those of the O(n^2) test of every box against every
// other, not a superset.
//
// Overlap convention (Aabb::overlaps in Proximity.h): boxes are closed sets, and a and b overlap
// when they share a point: neither is empty and, on each axis k,
//   a.min(k) <= b.max(k)  and  b.min(k) <= a.max(k);
// boxes that touch at a face, an edge or a corner overlap (as in Bullet's Intersect). An empty
// box (min > max on some axis, such as the default Aabb) overlaps nothing.
//
// Exactness: Debian's Bullet stores volumes in single precision (btScalar = float). Leaf
// volumes are the boxes rounded to float (coordinates first clamped to +-2^40); the rounding is
// monotone, so overlapping boxes keep overlapping volumes and the traversal misses no pair. Each
// leaf pair it meets is then tested on the double boxes kept here, which drops the pairs that
// the rounding made touch (boxes apart by less than a float's precision).
//
// Refit against rebuild (measured in README-tree.md): refit() writes the new leaf volumes and
// re-merges every internal volume from its children, children first: O(n), the topology
// unchanged, 0.2 ms for 10,000 boxes against 7.8 ms for build(). A surface deforming by steps
// keeps a tree as good as a rebuilt one. Motions that reorder the primitives in space (a large
// random motion, a surface folding through itself) would leave a valid tree whose queries visit
// far more nodes (47 ms instead of 2.3 ms for the self pairs of a 10,000-triangle sphere whose
// triangles moved randomly by half its radius), so refit() watches the tree's surface-area cost
// and, when it has doubled since the tree was made, takes every leaf out and inserts it again
// from the root (btDbvt::update): 3 ms, once, then queries 1.2 to 5 times slower than on a
// rebuilt tree. Neither allocates.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include "Collision/kernels/Proximity.h"

namespace stroma::collision {

/// A primitive index pair: (i, j) is primitive i of one model and primitive j of the other.
using PrimitivePair = std::pair<std::uint32_t, std::uint32_t>;

/// Bounding-volume hierarchy over the boxes of one collision model; leaf i is primitive i.
///
/// Preconditions (checked, std::invalid_argument naming the box): no coordinate is NaN; at
/// most 2^31 - 1 boxes. Empty boxes are allowed (a primitive that collides with nothing).
///
/// Queries are const and may run concurrently on the same trees from several threads; each
/// thread keeps one traversal stack (Bullet's) that grows to the deepest traversal it has run
/// and is reused. build() and refit() must not run concurrently with a query on the same tree.
/// Pairs come in traversal order, deterministic for a given tree, not sorted.
class PrimitiveTree {
 public:
  PrimitiveTree();
  ~PrimitiveTree();
  PrimitiveTree(PrimitiveTree&&) noexcept;
  PrimitiveTree& operator=(PrimitiveTree&&) noexcept;
  PrimitiveTree(const PrimitiveTree&) = delete;
  PrimitiveTree& operator=(const PrimitiveTree&) = delete;

  /// Builds the tree from scratch over `boxes` (leaf i = boxes[i]): Bullet's incremental
  /// insertion in a shuffled (fixed) order, then its top-down rebuild
  /// (btDbvt::optimizeTopDown). Allocates the 2n - 1 nodes.
  void build(const std::vector<Aabb>& boxes);

  /// The same primitives moved or deformed: `boxes` has size() boxes, boxes[i] the new box of
  /// primitive i. Refits the tree in place (O(n)), and reinserts every leaf when its cost has
  /// doubled since it was made (see above). Allocates nothing.
  /// Throws std::invalid_argument when the count differs from size().
  void refit(const std::vector<Aabb>& boxes);

  /// How many times refit() has reinserted every leaf since the last build().
  std::size_t reinsertions() const;

  /// Number of primitives (leaves).
  std::size_t size() const;
  bool empty() const { return size() == 0; }

  /// Exact union of the non-empty boxes; the empty box (Aabb{}) when there are none.
  Aabb bounds() const;

  /// Every pair (i, j), i a primitive of this tree and j one of `other`, whose boxes overlap.
  /// `pairs` is cleared first; it does not allocate when its capacity holds the pairs. With
  /// `other` this very tree, the pairs are every ordered (i, j) that overlap, (i, i) included
  /// for each non-empty box.
  void overlappingPairs(const PrimitiveTree& other, std::vector<PrimitivePair>& pairs) const;

  /// Every pair (i, j), i < j, of primitives of this tree whose boxes overlap (self-collision).
  /// `pairs` is cleared first; it does not allocate when its capacity holds the pairs.
  void selfOverlappingPairs(std::vector<PrimitivePair>& pairs) const;

 private:
  struct Impl;  // the btDbvt and its leaves: Bullet types stay in PrimitiveTree.cpp
  std::unique_ptr<Impl> m_impl;
};

}  // namespace stroma::collision
