// SPDX-License-Identifier: MIT
// What a picture shows, in SOFA's VisualStyle words.
#pragma once

#include <string>
#include <string_view>

namespace stroma {
class Node;
}

namespace stroma::rendering {

/// The parts of a scene that are drawn. The default, as SOFA's, shows the visual models only.
struct DisplayFlags {
  bool visualModels = true;
  bool behaviorModels = false;   ///< mechanical states as points, fixed points
  bool forceFields = false;      ///< FEM meshes (the surface of their elements)
  bool collisionModels = false;  ///< collision models and the current contacts
  bool wireframe = false;        ///< surfaces as their edges

  /// Applies SOFA's displayFlags words in order: showVisual (visual models), showVisualModels,
  /// showBehavior (behaviour models and force fields), showBehaviorModels, showForceFields,
  /// showCollision / showCollisionModels, showWireframe / showWireFrame, showAll, and each
  /// with "hide" instead of "show". Unknown words that SOFA knows (showMappings,
  /// showInteractionForceFields, showBoundingCollisionModels, showNormals, ...) are accepted
  /// without effect; other words are added to `unknown` (space separated).
  void apply(std::string_view words, std::string& unknown);

  bool anything() const { return visualModels || behaviorModels || forceFields || collisionModels; }
};

/// The flags that hold at `node`: SOFA's defaults changed by the words of every VisualStyle
/// from the root down to `node`, in that order (a style in a child node changes what it names
/// and inherits the rest). `unknown` gets the words that were not understood.
DisplayFlags sceneDisplayFlags(const Node& node, std::string& unknown);

}  // namespace stroma::rendering
