// SPDX-License-Identifier: MIT
// The lights of a frame.
#pragma once

namespace stroma {
class Node;
}

namespace stroma::rendering {

/// Enables OpenGL lighting with the scene's lights (DirectionalLight, PositionalLight,
/// SpotLight, read by their Data names, the first eight; LightManager's ambient), or, when the
/// scene has none, one white headlight shining along the view. Call with the camera's
/// modelview matrix loaded: scene lights are placed in world coordinates. Returns the number of
/// scene lights used (0: the headlight).
int setupLights(const Node& root);

}  // namespace stroma::rendering
