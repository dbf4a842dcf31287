// SPDX-License-Identifier: MIT
// Reading scene components the drawer knows only by class and Data names: the visual-only
// components live in the Visual plugin, which nothing links, so their fields are read as the
// scene writes them (BaseData::valueText) rather than through their C++ types.
#pragma once

#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "core/Types.h"

namespace stroma {
class Base;
class Node;
}  // namespace stroma

namespace stroma::rendering {

/// Calls `visit` for every object under `node` (depth first, scene order), skipping the
/// subtrees of nodes whose `activated` is false.
void forEachObject(const Node& node, const std::function<void(Base&)>& visit);

/// The first object under `root` (depth first) whose class name is `className`, or nullptr.
Base* findByClass(const Node& root, std::string_view className);

/// The numbers of a Data's value text; false when the object has no such Data or a token is
/// not a number.
bool readNumbers(const Base& object, std::string_view dataName, std::vector<double>& numbers);
/// A Data's value text, or empty when there is no such Data.
std::string readText(const Base& object, std::string_view dataName);
/// Whether the Data exists and was given a value (by the scene, a link or code).
bool isDataSet(const Base& object, std::string_view dataName);

/// A color as SOFA writes it (simulation/Color.h: a name, #hex, "r g b [a]"). False,
/// unchanged, on anything else.
bool parseColor(std::string_view text, Vec4d& color);

}  // namespace stroma::rendering
