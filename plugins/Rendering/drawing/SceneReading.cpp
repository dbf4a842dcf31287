// SPDX-License-Identifier: MIT
#include "SceneReading.h"

#include <charconv>
#include <sstream>

#include "core/Base.h"
#include "core/Node.h"
#include "simulation/Color.h"

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
  std::string error;
  Vec4d parsed;
  if (!stroma::parseColor(text, parsed, error)) return false;
  color = parsed;
  return true;
}

}  // namespace stroma::rendering
