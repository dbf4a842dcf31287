// SPDX-License-Identifier: MIT
// PrimitiveTree: the overlapping pairs, between two trees and within one, are exactly those of
// the O(n^2) test of every box against every other, for fresh and refitted trees, on boxes
// spread, clustered, touching at faces and separated by one double ulp.
#include "Collision/kernels/PrimitiveTree.h"

#include <LinearMath/btAlignedAllocator.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <new>
#include <ostream>
#include <random>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

// Allocation counting: every operator new of this program, and Bullet's allocations (through
// btAlignedAllocSetCustom), while g_counting is set.
#include "support/AllocationCounter.h"

namespace stroma::collision {
namespace {

void* countedBulletAlloc(std::size_t size) {
  if (g_counting) ++g_allocations;
  return std::malloc(size);
}
void countedBulletFree(void* p) { std::free(p); }

using Pairs = std::vector<PrimitivePair>;

// The overlap convention, written out: two closed boxes share a point when neither is empty
// and, on every axis, each one's min is at most the other's max.
bool referenceOverlap(const Aabb& a, const Aabb& b) {
  for (int k = 0; k < 3; ++k) {
    if (a.min(k) > a.max(k) || b.min(k) > b.max(k)) return false;
    if (a.min(k) > b.max(k) || b.min(k) > a.max(k)) return false;
  }
  return true;
}

// The reference: every (i, j) whose boxes overlap, sorted.
Pairs bruteForcePairs(const std::vector<Aabb>& a, const std::vector<Aabb>& b) {
  Pairs pairs;
  for (std::uint32_t i = 0; i < a.size(); ++i) {
    for (std::uint32_t j = 0; j < b.size(); ++j) {
      if (referenceOverlap(a[i], b[j])) pairs.emplace_back(i, j);
    }
  }
  return pairs;
}

// The reference of self-collision: every i < j whose boxes overlap, sorted.
Pairs bruteForceSelfPairs(const std::vector<Aabb>& a) {
  Pairs pairs;
  for (std::uint32_t i = 0; i < a.size(); ++i) {
    for (std::uint32_t j = i + 1; j < a.size(); ++j) {
      if (referenceOverlap(a[i], a[j])) pairs.emplace_back(i, j);
    }
  }
  return pairs;
}

// How many of `pairs` (of boxes a[i], b[j]) only touch: equal coordinates on some axis.
std::size_t countTouching(const Pairs& pairs, const std::vector<Aabb>& a,
                          const std::vector<Aabb>& b) {
  std::size_t touching = 0;
  for (const auto& [i, j] : pairs) {
    if ((a[i].max.array() == b[j].min.array()).any() ||
        (b[j].max.array() == a[i].min.array()).any()) {
      ++touching;
    }
  }
  return touching;
}

Pairs sorted(Pairs pairs) {
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

Pairs pairsOf(const PrimitiveTree& a, const PrimitiveTree& b) {
  Pairs pairs;
  a.overlappingPairs(b, pairs);
  return sorted(pairs);
}

Pairs selfPairsOf(const PrimitiveTree& a) {
  Pairs pairs;
  a.selfOverlappingPairs(pairs);
  return sorted(pairs);
}

// How the random boxes are laid out.
enum class Layout {
  spread,      // uniform in a cube, sizes such that each box meets a few others
  clustered,   // a few tight clusters: many overlaps, deep subtrees of overlapping boxes
  grid,        // integer corners and sizes on a coarse grid: many boxes touch exactly at faces
  ulpApart,    // pairs touching at a face or separated by one double ulp, at decimal positions
  degenerate,  // flat, point and empty boxes, many sharing coordinates
};

const char* layoutName(Layout layout) {
  switch (layout) {
    case Layout::spread:
      return "spread";
    case Layout::clustered:
      return "clustered";
    case Layout::grid:
      return "grid";
    case Layout::ulpApart:
      return "ulpApart";
    case Layout::degenerate:
      return "degenerate";
  }
  return "?";
}

std::vector<Aabb> randomBoxes(std::size_t count, Layout layout, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::uniform_int_distribution<int> cell(0, 20);
  std::vector<Aabb> boxes(count);
  // Spread boxes: sides up to 2 domain / count^(1/3), so that each meets a handful of others.
  const double domain = 10.0;
  const double side =
      2.0 * domain / std::cbrt(static_cast<double>(std::max<std::size_t>(count, 1)));
  std::vector<Vec3d> centres;
  for (int c = 0; c < 5; ++c) centres.emplace_back(domain * unit(rng), domain * unit(rng), 0.0);
  for (std::size_t i = 0; i < count; ++i) {
    Aabb& box = boxes[i];
    switch (layout) {
      case Layout::spread: {
        box.min = domain * Vec3d(unit(rng), unit(rng), unit(rng));
        box.max = box.min + side * Vec3d(unit(rng), unit(rng), unit(rng));
        break;
      }
      case Layout::clustered: {
        const Vec3d& centre = centres[i % centres.size()];
        box.min = centre + 0.5 * Vec3d(unit(rng), unit(rng), unit(rng));
        box.max = box.min + 0.05 * Vec3d(unit(rng), unit(rng), unit(rng));
        break;
      }
      case Layout::grid: {
        box.min = Vec3d(cell(rng), cell(rng), cell(rng));
        box.max = box.min + Vec3d(1 + cell(rng) % 2, 1 + cell(rng) % 2, 1 + cell(rng) % 2);
        break;
      }
      case Layout::ulpApart: {
        // Box 2k spans [0.1 m, 0.1 m + 0.3] on x; box 2k + 1 starts at its max or one ulp
        // beyond: equal in single precision, different in double.
        const double x = 0.1 * cell(rng);
        const double y = 0.1 * cell(rng);
        const double z = 0.1 * cell(rng);
        if (i % 2 == 0) {
          box.min = Vec3d(x, y, z);
          box.max = Vec3d(x + 0.3, y + 0.3, z + 0.3);
        } else {
          const Aabb& previous = boxes[i - 1];
          const double gap =
              unit(rng) < 0.5 ? previous.max.x() : std::nextafter(previous.max.x(), 1e300);
          box.min = Vec3d(gap, previous.min.y(), previous.min.z());
          box.max = box.min + Vec3d(0.1 * (1 + cell(rng)), 0.3, 0.3);
        }
        break;
      }
      case Layout::degenerate: {
        box.min = Vec3d(cell(rng), cell(rng), cell(rng)) / 4.0;
        box.max = box.min;
        if (i % 3 == 1) box.max.x() += 0.25 * (cell(rng) % 3);
        if (i % 3 == 2) box.max.head<2>() += Vec2d(0.25, 0.5);
        if (i % 7 == 3) box.min.x() = box.max.x() + 0.25;  // empty: inverted on x only
        if (i % 11 == 5) box = Aabb{};                     // empty: the default box
        break;
      }
    }
  }
  return boxes;
}

// Moves every box: `amplitude` of 0 keeps them, small values deform, large ones reorder the
// boxes in space. Box sizes change too (growing, shrinking, flattening). With `grid` > 0 the
// boxes are then put back on the lattice of their layout (multiples of `grid`, in its domain of
// 21 cells a side, 1 or 2 cells wide), so that they touch exactly again.
void moveBoxes(std::vector<Aabb>& boxes, double amplitude, std::mt19937& rng, double grid = 0) {
  std::uniform_real_distribution<double> offset(-amplitude, amplitude);
  std::uniform_real_distribution<double> scale(0.0, 1.5);
  std::uniform_int_distribution<int> width(1, 2);
  for (Aabb& box : boxes) {
    if (box.empty()) continue;  // stays empty
    const Vec3d shift(offset(rng), offset(rng), offset(rng));
    const Vec3d centre = 0.5 * (box.min + box.max) + shift;
    const Vec3d half = 0.5 * (box.max - box.min) * scale(rng);
    box.min = centre - half;
    box.max = centre + half;
    if (grid > 0) {
      const double side = 21 * grid;
      for (int k = 0; k < 3; ++k) {
        const double wrapped = centre(k) - side * std::floor(centre(k) / side);
        box.min(k) = std::round(wrapped / grid) * grid;
        box.max(k) = box.min(k) + width(rng) * grid;
      }
    }
  }
}

// The grid of a layout whose boxes touch exactly, 0 for the others.
double gridOf(Layout layout) {
  return layout == Layout::grid ? 1.0 : layout == Layout::degenerate ? 0.25 : 0.0;
}

struct ExactnessCase {
  std::size_t count;
  Layout layout;
};

void PrintTo(const ExactnessCase& c, std::ostream* os) {
  *os << c.count << " boxes, " << layoutName(c.layout);
}

class PrimitiveTreeExactness : public ::testing::TestWithParam<ExactnessCase> {};
class PrimitiveTreeRefit : public ::testing::TestWithParam<ExactnessCase> {};

TEST_P(PrimitiveTreeExactness, PairsAreThoseOfBruteForce) {
  const auto [count, layout] = GetParam();
  const std::vector<Aabb> a = randomBoxes(count, layout, 11 + static_cast<std::uint32_t>(count));
  const std::vector<Aabb> b = randomBoxes(count / 3 + 1, layout, 23);
  PrimitiveTree treeA, treeB;
  treeA.build(a);
  treeB.build(b);
  ASSERT_EQ(treeA.size(), count);

  const Pairs expected = bruteForcePairs(a, b);
  EXPECT_EQ(pairsOf(treeA, treeB), expected);
  // Swapping the trees swaps the pairs.
  Pairs swapped;
  for (const auto& [i, j] : expected) swapped.emplace_back(j, i);
  EXPECT_EQ(pairsOf(treeB, treeA), sorted(swapped));

  const Pairs expectedSelf = bruteForceSelfPairs(a);
  EXPECT_EQ(selfPairsOf(treeA), expectedSelf);
  EXPECT_EQ(pairsOf(treeA, treeA), bruteForcePairs(a, a));
  // The layouts meant to touch do.
  if (layout != Layout::spread && layout != Layout::clustered && count >= 500) {
    EXPECT_GT(countTouching(expectedSelf, a, a), 0u);
  }
}

TEST_P(PrimitiveTreeRefit, RefittedTreeGivesThePairsOfARebuiltOne) {
  const auto [count, layout] = GetParam();
  std::vector<Aabb> a = randomBoxes(count, layout, 5 + static_cast<std::uint32_t>(count));
  std::vector<Aabb> b = randomBoxes(count / 2 + 1, layout, 7);
  PrimitiveTree refittedA, refittedB;
  refittedA.build(a);
  refittedB.build(b);
  std::mt19937 rng(99);
  // Rounds of small deformations, motions as large as the whole domain, and a new random set of
  // the same layout (touching boxes again, the leaves scattered across the tree).
  for (const double amplitude : {0.0, 0.01, 0.1, 0.01, 1.0, 5.0, 20.0, -1.0, 0.5}) {
    SCOPED_TRACE("motion amplitude " + std::to_string(amplitude));
    if (amplitude < 0) {
      a = randomBoxes(count, layout, 1000 + static_cast<std::uint32_t>(count));
      b = randomBoxes(count / 2 + 1, layout, 1001);
    } else {
      moveBoxes(a, amplitude, rng, gridOf(layout));
      moveBoxes(b, amplitude, rng, gridOf(layout));
    }
    refittedA.refit(a);
    refittedB.refit(b);
    PrimitiveTree rebuiltA, rebuiltB;
    rebuiltA.build(a);
    rebuiltB.build(b);

    const Pairs expected = bruteForcePairs(a, b);
    EXPECT_EQ(pairsOf(refittedA, refittedB), expected);
    EXPECT_EQ(pairsOf(rebuiltA, rebuiltB), expected);
    EXPECT_EQ(pairsOf(refittedA, rebuiltB), expected);
    const Pairs expectedSelf = bruteForceSelfPairs(a);
    EXPECT_EQ(selfPairsOf(refittedA), expectedSelf);
    EXPECT_EQ(selfPairsOf(rebuiltA), expectedSelf);
    if (gridOf(layout) > 0 && count >= 500) {
      EXPECT_GT(countTouching(expectedSelf, a, a), 0u);
    }

    const Aabb bounds = refittedA.bounds();
    const Aabb rebuiltBounds = rebuiltA.bounds();
    EXPECT_EQ(bounds.min, rebuiltBounds.min);
    EXPECT_EQ(bounds.max, rebuiltBounds.max);
  }
}

std::vector<ExactnessCase> casesUpTo(std::size_t largest) {
  std::vector<ExactnessCase> cases;
  for (const Layout layout :
       {Layout::spread, Layout::clustered, Layout::grid, Layout::ulpApart, Layout::degenerate}) {
    for (const std::size_t count : {1, 2, 3, 7, 64, 500, 2000, 5000}) {
      if (count <= largest) cases.push_back({count, layout});
    }
  }
  return cases;
}

std::string caseName(const ::testing::TestParamInfo<ExactnessCase>& info) {
  return std::string(layoutName(info.param.layout)) + std::to_string(info.param.count);
}

INSTANTIATE_TEST_SUITE_P(Layouts, PrimitiveTreeExactness, ::testing::ValuesIn(casesUpTo(5000)),
                         caseName);
// Eight rounds of brute force each: up to 2,000 boxes, and 5,000 boxes touching on a grid.
INSTANTIATE_TEST_SUITE_P(Layouts, PrimitiveTreeRefit, ::testing::ValuesIn([] {
                           std::vector<ExactnessCase> cases = casesUpTo(2000);
                           cases.push_back({5000, Layout::grid});
                           return cases;
                         }()),
                         caseName);

TEST(PrimitiveTree, EmptyTreeHasNoPairsAndEmptyBounds) {
  const std::vector<Aabb> some = randomBoxes(10, Layout::spread, 1);
  PrimitiveTree unbuilt, empty, full;
  empty.build({});
  full.build(some);
  for (const PrimitiveTree* tree : {&unbuilt, &empty}) {
    EXPECT_EQ(tree->size(), 0u);
    EXPECT_TRUE(tree->empty());
    EXPECT_TRUE(tree->bounds().empty());
    EXPECT_TRUE((tree->bounds().min.array() == std::numeric_limits<double>::infinity()).all());
    EXPECT_TRUE((tree->bounds().max.array() == -std::numeric_limits<double>::infinity()).all());
    Pairs pairs = {{1, 2}};  // cleared by every query
    tree->selfOverlappingPairs(pairs);
    EXPECT_TRUE(pairs.empty());
    pairs = {{1, 2}};
    tree->overlappingPairs(*tree, pairs);
    EXPECT_TRUE(pairs.empty());
    EXPECT_TRUE(pairsOf(*tree, full).empty());
    EXPECT_TRUE(pairsOf(full, *tree).empty());
  }
  empty.refit({});
  EXPECT_EQ(empty.size(), 0u);
}

TEST(PrimitiveTree, OneBox) {
  const Aabb box{Vec3d(0, 0, 0), Vec3d(1, 2, 3)};
  PrimitiveTree one, other;
  one.build({box});
  EXPECT_EQ(one.size(), 1u);
  EXPECT_EQ(one.bounds().min, box.min);
  EXPECT_EQ(one.bounds().max, box.max);
  EXPECT_TRUE(selfPairsOf(one).empty());
  EXPECT_EQ(pairsOf(one, one), (Pairs{{0, 0}}));

  // Touching at a face, at a corner, then one ulp apart.
  other.build({{Vec3d(1, 2, 3), Vec3d(4, 4, 4)}, {Vec3d(-1, 0.5, 0.5), Vec3d(0, 1, 1)}});
  EXPECT_EQ(pairsOf(one, other), (Pairs{{0, 0}, {0, 1}}));
  const double beyond = std::nextafter(1.0, 2.0);
  other.refit({{Vec3d(beyond, 0, 0), Vec3d(4, 4, 4)}, {Vec3d(-1, 0.5, 0.5), Vec3d(0, 1, 1)}});
  EXPECT_EQ(pairsOf(one, other), (Pairs{{0, 1}}));
  one.refit({{Vec3d(0, 0, 0), Vec3d(beyond, 2, 3)}});
  EXPECT_EQ(pairsOf(one, other), (Pairs{{0, 0}, {0, 1}}));
}

TEST(PrimitiveTree, SameTreeAgainstItselfGivesEveryOrderedPair) {
  const std::vector<Aabb> boxes = randomBoxes(300, Layout::grid, 3);
  PrimitiveTree tree;
  tree.build(boxes);
  EXPECT_EQ(pairsOf(tree, tree), bruteForcePairs(boxes, boxes));
  // A second tree over the same boxes gives the same pairs through the two-tree traversal.
  PrimitiveTree copy;
  copy.build(boxes);
  EXPECT_EQ(pairsOf(tree, copy), bruteForcePairs(boxes, boxes));
}

TEST(PrimitiveTree, PairsAreExactAtExtremeCoordinates) {
  // Beyond single precision (1e300, 1e-300 gaps), infinite extents and float's largest value.
  const double inf = std::numeric_limits<double>::infinity();
  const double fmax = std::numeric_limits<float>::max();
  const std::vector<Aabb> a = {
      {Vec3d(1e300, 0, 0), Vec3d(2e300, 1, 1)},   {Vec3d(-inf, -inf, -inf), Vec3d(-1e300, 0, 0)},
      {Vec3d(1e-300, 0, 0), Vec3d(2e-300, 1, 1)}, {Vec3d(fmax, fmax, fmax), Vec3d(inf, inf, inf)},
      {Vec3d(-1, -1, -1), Vec3d(-1e-300, 0, 0)},
  };
  const std::vector<Aabb> b = {
      {Vec3d(std::nextafter(2e300, inf), 0, 0), Vec3d(3e300, 1, 1)},
      {Vec3d(2e300, 1, 1), Vec3d(inf, 2, 2)},
      {Vec3d(std::nextafter(2e-300, 1.0), 0, 0), Vec3d(1, 1, 1)},
      {Vec3d(2e-300, 1, 1), Vec3d(1, 1, 1)},
      {Vec3d(0, 0, 0), Vec3d(0, 0, 0)},
      {Vec3d(std::nextafter(fmax, 0.0), 0, 0), Vec3d(std::nextafter(fmax, 0.0), fmax, fmax)},
      {Vec3d(-inf, -inf, -inf), Vec3d(inf, inf, inf)},
  };
  PrimitiveTree treeA, treeB;
  treeA.build(a);
  treeB.build(b);
  EXPECT_EQ(pairsOf(treeA, treeB), bruteForcePairs(a, b));
  EXPECT_EQ(selfPairsOf(treeB), bruteForceSelfPairs(b));
  EXPECT_EQ(treeB.bounds().min, Vec3d::Constant(-inf));
  EXPECT_EQ(treeB.bounds().max, Vec3d::Constant(inf));
}

TEST(PrimitiveTree, EmptyBoxesOverlapNothing) {
  // Empty leaves keep inverted volumes: the whole-space box meets them in the tree, and the
  // exact test drops them.
  const double inf = std::numeric_limits<double>::infinity();
  const std::vector<Aabb> a = {
      Aabb{},
      {Vec3d(0, 0, 0), Vec3d(1, 1, 1)},
      {Vec3d(2, 0, 0), Vec3d(1, 1, 1)},  // inverted on x
      {Vec3d(0.5, 0.5, 0.5), Vec3d(0.5, 0.5, 0.5)},
      {Vec3d(0, 0, 0), Vec3d(-inf, inf, inf)},
  };
  const std::vector<Aabb> b = {
      {Vec3d::Constant(-inf), Vec3d::Constant(inf)},
      Aabb{},
      {Vec3d(1.5, 0.5, 0.5), Vec3d(1.5, 0.5, 0.5)},
  };
  PrimitiveTree treeA, treeB;
  treeA.build(a);
  treeB.build(b);
  EXPECT_EQ(pairsOf(treeA, treeB), (Pairs{{1, 0}, {3, 0}}));
  EXPECT_EQ(selfPairsOf(treeA), (Pairs{{1, 3}}));
  EXPECT_EQ(pairsOf(treeA, treeA), (Pairs{{1, 1}, {1, 3}, {3, 1}, {3, 3}}));
  EXPECT_EQ(treeA.bounds().min, Vec3d(0, 0, 0));
  EXPECT_EQ(treeA.bounds().max, Vec3d(1, 1, 1));
  // A tree of empty boxes only.
  treeB.build({Aabb{}, Aabb{}});
  EXPECT_TRUE(treeB.bounds().empty());
  EXPECT_TRUE(selfPairsOf(treeB).empty());
  EXPECT_TRUE(pairsOf(treeA, treeB).empty());
}

TEST(PrimitiveTree, RejectsNanBoxesAndAWrongRefitCount) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  PrimitiveTree tree;
  try {
    tree.build({{Vec3d(0, 0, 0), Vec3d(1, 1, 1)}, {Vec3d(0, nan, 0), Vec3d(1, 1, 1)}});
    ADD_FAILURE() << "a NaN box did not throw";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("box 1 has a NaN coordinate"), std::string::npos)
        << error.what();
  }

  tree.build({{Vec3d(0, 0, 0), Vec3d(1, 1, 1)}, {Vec3d(1, 1, 1), Vec3d(2, 2, 2)}});
  try {
    tree.refit({{Vec3d(0, 0, 0), Vec3d(1, 1, 1)}});
    ADD_FAILURE() << "refit with one box for two primitives did not throw";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("1 boxes for a tree of 2"), std::string::npos)
        << error.what();
  }
  EXPECT_THROW(tree.refit({{Vec3d(0, 0, 0), Vec3d(1, 1, 1)}, {Vec3d(1, 1, 1), Vec3d(2, nan, 2)}}),
               std::invalid_argument);
  // A rejected refit leaves the tree as it was.
  EXPECT_EQ(selfPairsOf(tree), (Pairs{{0, 1}}));
}

TEST(PrimitiveTree, MovedTreeKeepsItsPairsAndTheMovedFromOneIsEmpty) {
  const std::vector<Aabb> boxes = randomBoxes(200, Layout::clustered, 4);
  PrimitiveTree tree;
  tree.build(boxes);
  PrimitiveTree moved(std::move(tree));
  EXPECT_EQ(selfPairsOf(moved), bruteForceSelfPairs(boxes));
  EXPECT_EQ(tree.size(), 0u);  // NOLINT(bugprone-use-after-move): a moved-from tree is empty
  EXPECT_TRUE(selfPairsOf(tree).empty());
  tree.build(boxes);
  EXPECT_EQ(selfPairsOf(tree), bruteForceSelfPairs(boxes));
  PrimitiveTree assigned;
  assigned = std::move(moved);
  EXPECT_EQ(pairsOf(assigned, tree), bruteForcePairs(boxes, boxes));
}

TEST(PrimitiveTree, ConcurrentQueriesOnTheSameTrees) {
  const std::vector<Aabb> a = randomBoxes(2000, Layout::clustered, 31);
  const std::vector<Aabb> b = randomBoxes(500, Layout::clustered, 32);
  PrimitiveTree treeA, treeB;
  treeA.build(a);
  treeB.build(b);
  const Pairs expected = bruteForcePairs(a, b);
  const Pairs expectedSelf = bruteForceSelfPairs(a);
  std::vector<Pairs> found(4), foundSelf(4);
  std::vector<std::thread> threads;
  for (std::size_t k = 0; k < found.size(); ++k) {
    threads.emplace_back([&, k] {
      for (int repeat = 0; repeat < 5; ++repeat) {
        treeA.overlappingPairs(treeB, found[k]);
        treeA.selfOverlappingPairs(foundSelf[k]);
      }
    });
  }
  for (std::thread& thread : threads) thread.join();
  for (std::size_t k = 0; k < found.size(); ++k) {
    EXPECT_EQ(sorted(found[k]), expected);
    EXPECT_EQ(sorted(foundSelf[k]), expectedSelf);
  }
}

TEST(PrimitiveTree, RebuildWithAnotherCount) {
  PrimitiveTree tree;
  for (const std::size_t count : {100, 3, 0, 1000, 1}) {
    const std::vector<Aabb> boxes = randomBoxes(count, Layout::spread, 8);
    tree.build(boxes);
    EXPECT_EQ(tree.size(), count);
    EXPECT_EQ(selfPairsOf(tree), bruteForceSelfPairs(boxes));
  }
}

TEST(PrimitiveTree, SmallMotionsKeepTheTreeAndLargeOnesReinsertItsLeaves) {
  std::vector<Aabb> boxes = randomBoxes(2000, Layout::spread, 21);
  PrimitiveTree tree;
  tree.build(boxes);
  std::mt19937 rng(3);
  for (int step = 0; step < 20; ++step) {
    moveBoxes(boxes, 0.002, rng);
    tree.refit(boxes);
  }
  EXPECT_EQ(tree.reinsertions(), 0u);
  EXPECT_EQ(selfPairsOf(tree), bruteForceSelfPairs(boxes));
  // Boxes scattered across the whole domain: the tree no longer follows them.
  moveBoxes(boxes, 10.0, rng);
  tree.refit(boxes);
  EXPECT_EQ(tree.reinsertions(), 1u);
  EXPECT_EQ(selfPairsOf(tree), bruteForceSelfPairs(boxes));
  // The reinserted tree is the reference of the next refits.
  moveBoxes(boxes, 0.002, rng);
  tree.refit(boxes);
  EXPECT_EQ(tree.reinsertions(), 1u);
  EXPECT_EQ(selfPairsOf(tree), bruteForceSelfPairs(boxes));
  tree.build(boxes);
  EXPECT_EQ(tree.reinsertions(), 0u);
}

TEST(PrimitiveTree, RefitAndQueriesAllocateNothingOnceWarm) {
  std::vector<Aabb> a = randomBoxes(3000, Layout::spread, 12);
  std::vector<Aabb> b = randomBoxes(1000, Layout::spread, 13);
  PrimitiveTree treeA, treeB;
  treeA.build(a);
  treeB.build(b);
  Pairs pairs, selfPairs;
  pairs.reserve(2 * bruteForcePairs(a, b).size() + 1000);
  selfPairs.reserve(2 * bruteForceSelfPairs(a).size() + 1000);
  std::mt19937 rng(5);
  btAlignedAllocSetCustom(countedBulletAlloc, countedBulletFree);
  treeA.overlappingPairs(treeB, pairs);  // warms this thread's traversal stack
  treeA.selfOverlappingPairs(selfPairs);
  // Small motions (refit in place), then one that scatters the boxes (every leaf reinserted).
  for (const double amplitude : {0.01, 0.01, 0.01, 10.0, 0.01}) {
    moveBoxes(a, amplitude, rng);
    g_allocations = 0;
    g_counting = true;
    treeA.refit(a);
    treeA.overlappingPairs(treeB, pairs);
    treeA.selfOverlappingPairs(selfPairs);
    g_counting = false;
    EXPECT_EQ(g_allocations, 0) << "motion amplitude " << amplitude;
    EXPECT_EQ(sorted(pairs), bruteForcePairs(a, b));
  }
  btAlignedAllocSetCustom(nullptr, nullptr);
  EXPECT_EQ(treeA.reinsertions(), 1u);
}

}  // namespace
}  // namespace stroma::collision
