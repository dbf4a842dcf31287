// SPDX-License-Identifier: MIT
// groupEqualElements: finds the elements whose per-element constants (Ke, rest frame, centre
// gradients, volume) are the same, so that one copy serves them all. In a regular or sparse
// grid every hexahedron is the same rest shape moved by a translation, with the same material:
// one Ke (4.6 KB for a hexahedron) then serves 32768 elements instead of being streamed from
// memory 32768 times by every force, product and assembly.
//
// Equal means: the same Young modulus (exactly) and the same rest positions relative to the
// first node, D_i = X_i - X_0, within
//
//   |D_i(a) - D_i(b)| <= kTolerance * max(s(a), s(b))   for every node i and coordinate,
//
// s the largest absolute coordinate of an element's rest positions. Why this bound: the
// constants depend on D only (they are translation invariant), and each stored coordinate is
// already a rounding of the intended one (a grid point min + i h carries an error of a few
// eps |X|), so two translated copies of one shape give D that differ by a few eps s: equal
// shapes as far as the input can tell. kTolerance = 16 eps covers these roundings and nothing
// that a mesh could mean (a change of 1e-14 s in a node position); the constants of two
// elements so grouped differ from their own by O(kTolerance s / h) relatively (h the element
// size), round-off amplified by the ratio of the coordinates to the element size.
//
// Found by hashing D quantized on one grid for all elements (a power of two near 2^-24 times
// the largest |D|), then comparing with each group's first element (its representative) in the
// hash bucket. Two elements equal within the tolerance that fall in different quantization
// cells (probability about kTolerance s / quantum, nil for the exact grid coordinates of
// generated meshes) are merely not shared. Elements with non-finite coordinates are never
// shared. Sequential; the result does not depend on the thread count.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <span>
#include <unordered_map>
#include <vector>

#include "SolidMechanics/kernels/FemTypes.h"

namespace stroma::fem {

struct ElementGroups {
  std::vector<std::uint32_t> groupOf;        ///< (elements) the group of each element
  std::vector<std::uint32_t> representative;  ///< (groups) its first element, increasing
};

/// Relative tolerance of the rest positions (see above).
inline constexpr double kEqualElementTolerance = 16 * std::numeric_limits<double>::epsilon();

/// Groups the elements of rest positions `rest` and Young modulus `youngModulus` (one value,
/// or one per element) whose constants are equal (see above). Groups are numbered in the order
/// of their first element.
template <int N>
ElementGroups groupEqualElements(std::span<const NodalVectors<N>> rest,
                                 std::span<const double> youngModulus) {
  using Offsets = Eigen::Matrix<double, 3, N - 1>;
  const std::size_t count = rest.size();
  const auto offsets = [&rest](std::size_t e) -> Offsets {
    return rest[e].template rightCols<N - 1>().colwise() - rest[e].col(0);
  };
  const auto modulus = [&youngModulus](std::size_t e) {
    return youngModulus[youngModulus.size() == 1 ? 0 : e];
  };
  // The quantum: a power of two, so that D / quantum is exact.
  double largest = 0;
  for (std::size_t e = 0; e < count; ++e) {
    const double size = offsets(e).cwiseAbs().maxCoeff();
    if (std::isfinite(size)) largest = std::max(largest, size);
  }
  const double quantum = largest > 0 ? std::ldexp(1.0, std::ilogb(largest) - 24) : 1.0;
  const auto hashOf = [&](const Offsets& D, double E) {
    std::uint64_t h = 1469598103934665603ull;  // FNV-1a over the cells and the modulus bits
    const auto mix = [&h](std::uint64_t word) {
      h ^= word;
      h *= 1099511628211ull;
    };
    for (int k = 0; k < D.size(); ++k) mix(static_cast<std::uint64_t>(std::llround(D(k) / quantum)));
    std::uint64_t bits = 0;
    std::memcpy(&bits, &E, sizeof bits);
    mix(bits);
    return h;
  };

  ElementGroups groups;
  groups.groupOf.resize(count);
  std::vector<double> scale;                      // (groups) s of the representative
  std::vector<std::uint32_t> nextInBucket;        // (groups) chain of a hash bucket
  std::unordered_map<std::uint64_t, std::uint32_t> bucketHead;
  const auto newGroup = [&](std::size_t e, double s) {
    const auto g = static_cast<std::uint32_t>(groups.representative.size());
    groups.representative.push_back(static_cast<std::uint32_t>(e));
    scale.push_back(s);
    nextInBucket.push_back(std::numeric_limits<std::uint32_t>::max());
    groups.groupOf[e] = g;
    return g;
  };
  for (std::size_t e = 0; e < count; ++e) {
    const Offsets D = offsets(e);
    const double s = rest[e].cwiseAbs().maxCoeff(), E = modulus(e);
    if (!std::isfinite(s) || !std::isfinite(E)) {
      newGroup(e, s);
      continue;
    }
    const std::uint64_t h = hashOf(D, E);
    const auto head = bucketHead.find(h);
    std::uint32_t found = std::numeric_limits<std::uint32_t>::max();
    if (head != bucketHead.end()) {
      for (std::uint32_t g = head->second; g != std::numeric_limits<std::uint32_t>::max();
           g = nextInBucket[g]) {
        const std::size_t r = groups.representative[g];
        const double tolerance = kEqualElementTolerance * std::max(s, scale[g]);
        if (modulus(r) == E && (offsets(r) - D).cwiseAbs().maxCoeff() <= tolerance) {
          found = g;
          break;
        }
      }
    }
    if (found != std::numeric_limits<std::uint32_t>::max()) {
      groups.groupOf[e] = found;
      continue;
    }
    const std::uint32_t g = newGroup(e, s);
    if (head != bucketHead.end()) {
      nextInBucket[g] = head->second;
      head->second = g;
    } else {
      bucketHead.emplace(h, g);
    }
  }
  return groups;
}

}  // namespace stroma::fem
