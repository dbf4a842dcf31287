// SPDX-License-Identifier: MIT
#include "core/NameSuggestions.h"

#include <algorithm>
#include <cctype>

namespace stroma {

namespace {
std::string lowered(const std::string& s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}
}  // namespace

std::size_t editDistance(const std::string& a0, const std::string& b0) {
  const std::string a = lowered(a0), b = lowered(b0);
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] != b[j - 1])});
      diagonal = up;
    }
  }
  return row[b.size()];
}

std::vector<std::string> nearestNames(const std::string& name,
                                      const std::vector<std::string>& candidates,
                                      std::size_t maxCount) {
  const std::string key = lowered(name);
  struct Scored {
    std::size_t score;
    const std::string* name;
  };
  std::vector<Scored> scored;
  const std::size_t limit = std::max<std::size_t>(2, key.size() / 3);
  for (const auto& candidate : candidates) {
    const std::string c = lowered(candidate);
    if (candidate == name) continue;  // a name differing only by case is the best hint
    std::size_t d = editDistance(key, c);
    const bool related = key.size() >= 4 && (c.find(key) != std::string::npos ||
                                            (c.size() >= 4 && key.find(c) != std::string::npos));
    if (related) d = std::min(d, limit);  // containment counts as close
    if (d <= limit) scored.push_back({d, &candidate});
  }
  std::stable_sort(scored.begin(), scored.end(), [](const Scored& x, const Scored& y) {
    return x.score != y.score ? x.score < y.score : *x.name < *y.name;
  });
  std::vector<std::string> result;
  for (const auto& s : scored) {
    if (result.size() >= maxCount) break;
    if (std::find(result.begin(), result.end(), *s.name) == result.end()) result.push_back(*s.name);
  }
  return result;
}

std::string quotedList(const std::vector<std::string>& names) {
  std::string text;
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (i) text += i + 1 == names.size() ? " or " : ", ";
    text += '\'' + names[i] + '\'';
  }
  return text;
}

}  // namespace stroma
