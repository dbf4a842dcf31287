// SPDX-License-Identifier: MIT
#pragma once

#include <string>
#include <vector>

namespace stroma {

/// Edit distance (Levenshtein, case-insensitive) between two names.
std::size_t editDistance(const std::string& a, const std::string& b);

/// Up to `maxCount` candidates closest to `name`, best first: those that contain it or that it
/// contains, then those within an edit distance of about a third of the name's length. Used for
/// "did you mean" in every error about an unknown name.
std::vector<std::string> nearestNames(const std::string& name,
                                      const std::vector<std::string>& candidates,
                                      std::size_t maxCount = 3);

/// "'a', 'b' or 'c'"
std::string quotedList(const std::vector<std::string>& names);

}  // namespace stroma
