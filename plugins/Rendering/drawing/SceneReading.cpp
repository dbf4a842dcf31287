// SPDX-License-Identifier: MIT
#include "SceneReading.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <sstream>

#include "core/Base.h"
#include "core/Node.h"

namespace stroma::rendering {

void forEachObject(const Node& node, const std::function<void(Base&)>& visit) {
  if (!node.d_activated.value()) return;
  for (const auto& object : node.objects()) visit(*object);
  for (const auto& child : node.children()) forEachObject(*child, visit);
}

Base* findByClass(const Node& root, std::string_view className) {
  Base* found = nullptr;
  forEachObject(root, [&](Base& object) {
    if (!found && object.className() == className) found = &object;
  });
  return found;
}

bool readNumbers(const Base& object, std::string_view dataName, std::vector<double>& numbers) {
  const BaseData* data = object.findData(dataName);
  if (!data) return false;
  numbers.clear();
  std::istringstream in(data->valueText());
  std::string token;
  while (in >> token) {
    double value = 0;
    auto [ptr, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
    if (ec != std::errc() || ptr != token.data() + token.size()) return false;
    numbers.push_back(value);
  }
  return true;
}

std::string readText(const Base& object, std::string_view dataName) {
  const BaseData* data = object.findData(dataName);
  return data ? data->valueText() : std::string();
}

bool isDataSet(const Base& object, std::string_view dataName) {
  const BaseData* data = object.findData(dataName);
  return data && data->isSet();
}

bool parseColor(std::string_view text, Vec4d& color) {
  std::string word(text);
  word.erase(std::remove_if(word.begin(), word.end(), [](unsigned char c) { return std::isspace(c); }),
             word.end());
  std::transform(word.begin(), word.end(), word.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  struct Named {
    const char* name;
    Vec4d rgba;
  };
  static const Named kNames[] = {
      {"white", {1, 1, 1, 1}},   {"black", {0, 0, 0, 1}},   {"red", {1, 0, 0, 1}},
      {"green", {0, 1, 0, 1}},   {"blue", {0, 0, 1, 1}},    {"cyan", {0, 1, 1, 1}},
      {"magenta", {1, 0, 1, 1}}, {"yellow", {1, 1, 0, 1}},  {"gray", {0.5, 0.5, 0.5, 1}},
      {"grey", {0.5, 0.5, 0.5, 1}}};
  for (const Named& n : kNames)
    if (word == n.name) {
      color = n.rgba;
      return true;
    }
  std::istringstream in{std::string(text)};
  std::vector<double> values;
  std::string token;
  while (in >> token) {
    double value = 0;
    auto [ptr, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
    if (ec != std::errc() || ptr != token.data() + token.size()) return false;
    values.push_back(value);
  }
  if (values.size() != 3 && values.size() != 4) return false;
  color = Vec4d(values[0], values[1], values[2], values.size() == 4 ? values[3] : 1.0);
  return true;
}

}  // namespace stroma::rendering
