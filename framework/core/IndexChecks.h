// SPDX-License-Identifier: MIT
// Reports indices that are out of range of a state, naming the field and the first offenders.
#pragma once

#include <string>
#include <vector>

#include "core/Base.h"

namespace stroma {

/// Reports, as an error of `owner` on `field`, every index >= n (the first ten are listed).
/// Returns true when all indices are in range.
template <class IndexList>
bool reportIndicesOutOfRange(Base& owner, const IndexList& indices, std::size_t n,
                             const std::string& field, const std::string& what = "points") {
  std::string bad;
  std::size_t count = 0;
  for (const auto i : indices)
    if (static_cast<std::size_t>(i) >= n && count++ < 10) {
      if (!bad.empty()) bad += ' ';
      bad += std::to_string(i);
    }
  if (count == 0) return true;
  owner.msgError(std::to_string(count) + (count == 1 ? " index" : " indices") +
                     " out of range of the " + std::to_string(n) + " " + what + ": " + bad +
                     (count > 10 ? " ..." : ""),
                 field);
  return false;
}

}  // namespace stroma
