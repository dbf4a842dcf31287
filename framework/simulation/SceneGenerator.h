// SPDX-License-Identifier: MIT
#pragma once

#include "simulation/SceneXml.h"

namespace stroma {

/// A component that writes part of the scene itself, as a loader of a model format that
/// describes a whole subgraph (URDFLoader: a robot's joints, links, masses and meshes). The
/// scene loader calls generateScene once the component's attributes are set (its files
/// resolved), and builds the elements it returns in the component's node, after it, exactly as
/// if the scene file had held them: the components are the regular ones, created through the
/// factory (plugins loaded on demand), and links between them resolve as in a scene file.
class SceneGenerator {
 public:
  virtual ~SceneGenerator() = default;
  /// Fills `node` (a "Node" element standing for the component's node: its children, nodes or
  /// components, are added there). Returns false after reporting the error with msgError.
  virtual bool generateScene(SceneElement& node) = 0;
};

}  // namespace stroma
