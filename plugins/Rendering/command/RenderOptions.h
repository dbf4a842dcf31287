// SPDX-License-Identifier: MIT
// The command line of `stroma render` (usage text: applications/stroma/Usage.cpp).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "CommandLine.h"
#include "core/Types.h"
#include "stroma/rendering/ColorMap.h"

namespace stroma::rendering {

/// The largest picture side accepted: OSMesa's own limit (MAX_WIDTH/MAX_HEIGHT in Mesa) and
/// 1 GiB of pixels at that size.
constexpr int kMaxPictureSide = 16384;

struct RenderOptions {
  long long steps = 100;
  long long every = 0;  ///< 0: only the first and the last frame (every = steps)
  std::filesystem::path outputDir = "frames";
  bool outputDirGiven = false;
  int width = 640, height = 480;
  std::optional<std::pair<Vec3d, Vec3d>> eyeAndTarget;
  ColorMapKind colorMap = ColorMapKind::none;
  std::string video;  ///< empty: no video
  double dt = 0;
  long long threads = 0;
  bool legend = true;
  std::string show;  ///< displayFlags words applied over the scene's (--show)
};

/// Parses the arguments after `render`. Returns false with `error` (the message for
/// cli::usageError) on bad input.
bool parseRenderOptions(const cli::Arguments& args, RenderOptions& options, std::string& error);

/// The options `stroma render` takes (with a value, and flags).
const std::vector<std::string>& renderValueOptions();
const std::vector<std::string>& renderFlagOptions();

/// Parses "WxH" (also "W*H", "W H") within 1..kMaxPictureSide.
bool parseSize(const std::string& text, int& width, int& height, std::string& error);

}  // namespace stroma::rendering
