// SPDX-License-Identifier: MIT
#include "stroma/rendering/DisplayFlags.h"

#include <sstream>
#include <vector>

#include "SceneReading.h"
#include "core/Node.h"

namespace stroma::rendering {

namespace {

/// SOFA's display words this drawer has nothing to draw for: accepted silently.
constexpr const char* kAcceptedWithoutEffect[] = {"Mappings",
                                                  "MechanicalMappings",
                                                  "InteractionForceFields",
                                                  "BoundingCollisionModels",
                                                  "Normals",
                                                  "Options",
                                                  "Advanced",
                                                  "RendererAdvanced",
                                                  "Rendering",
                                                  "BoundingTree",
                                                  "ProcessorColor"};

}  // namespace

void DisplayFlags::apply(std::string_view words, std::string& unknown) {
  std::istringstream in{std::string(words)};
  std::string word;
  while (in >> word) {
    bool show;
    std::string what;
    if (word.starts_with("show")) {
      show = true;
      what = word.substr(4);
    } else if (word.starts_with("hide")) {
      show = false;
      what = word.substr(4);
    } else {
      unknown += (unknown.empty() ? "" : " ") + word;
      continue;
    }
    if (what == "All") {
      visualModels = behaviorModels = forceFields = collisionModels = show;
    } else if (what == "Visual" || what == "VisualModels") {
      visualModels = show;
    } else if (what == "Behavior") {
      behaviorModels = forceFields = show;
    } else if (what == "BehaviorModels") {
      behaviorModels = show;
    } else if (what == "ForceFields") {
      forceFields = show;
    } else if (what == "Collision" || what == "CollisionModels") {
      collisionModels = show;
    } else if (what == "Wireframe" || what == "WireFrame") {
      wireframe = show;
    } else {
      bool known = false;
      for (const char* accepted : kAcceptedWithoutEffect) known = known || what == accepted;
      if (!known) unknown += (unknown.empty() ? "" : " ") + word;
    }
  }
}

DisplayFlags sceneDisplayFlags(const Node& node, std::string& unknown) {
  // SOFA's styles nest: each VisualStyle from the root down to the node changes the flags its
  // words name and keeps the others.
  std::vector<const Node*> path;
  for (const Node* n = &node; n; n = n->parent()) path.push_back(n);
  DisplayFlags flags;
  for (auto it = path.rbegin(); it != path.rend(); ++it)
    for (const auto& object : (*it)->objects())
      if (object->className() == "VisualStyle")
        flags.apply(readText(*object, "displayFlags"), unknown);
  return flags;
}

}  // namespace stroma::rendering
