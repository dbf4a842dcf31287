// SPDX-License-Identifier: MIT
// Model files that are scenes by themselves: `stroma run robot.urdf` (and render, view, every
// tool that loads a scene through Scene::loadFile) wraps the model in a default scene, as
// MuJoCo opens a URDF directly.
#pragma once

#include <filesystem>
#include <string>

namespace stroma {

/// The text of a default scene holding the model `file` when its extension is a model format
/// the scene loader wraps (.urdf: gravity 0 0 -9.81 as URDF expects, dt 1 ms,
/// EulerImplicitSolver with SparseLDLSolver, a URDFLoader with the robot's base fixed unless
/// its root joint is floating); empty for any other file (a scene file).
std::string wrapModelInScene(const std::filesystem::path& file);

}  // namespace stroma
