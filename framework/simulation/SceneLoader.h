// SPDX-License-Identifier: MIT
// The second stage of scene loading: a tree of SceneElements to a graph of initialized objects.
#pragma once

#include <filesystem>
#include <memory>

#include "core/Node.h"
#include "simulation/SceneXml.h"

namespace stroma {

class Runtime;

/// Builds the graph of `root` (a "Node" element): creates every component through the
/// factory (loading plugins on demand), sets Data from attributes, resolves file names, then,
/// once the whole graph exists, resolves links (`@path`, `@path.field`, `src="@loader"`), and
/// finally calls init() top-down and bwdInit() bottom-up. Every problem is logged; the result
/// is false when any error was logged. `sceneFile` is the top-level scene file (its folder is
/// searched for relative file names).
bool buildSceneGraph(Runtime& runtime, const SceneElement& root,
                     const std::filesystem::path& sceneFile, MessageLog& log,
                     std::unique_ptr<Node>& graph, const ThreadPool* threads = nullptr);

}  // namespace stroma
