// SPDX-License-Identifier: MIT
// Where the frames of `stroma render` go: numbered PNG files in a folder, and a video made by
// ffmpeg reading raw frames from a pipe.
#pragma once

#include <cstdio>
#include <filesystem>
#include <string>

#include "stroma/rendering/PngImage.h"

namespace stroma::rendering {

/// The executable `name` in the folders of PATH, or empty.
std::filesystem::path findOnPath(const std::string& name);

/// Creates `dir` (and its parents) if needed and checks that a file can be written in it.
/// Returns false with `error` naming the folder and the reason.
bool prepareOutputFolder(const std::filesystem::path& dir, std::string& error);

/// "frame_00012.png"
std::string frameFileName(long long frame);

/// Frames piped to `ffmpeg` as raw RGB (H.264, yuv420p, 25 frames/s).
class VideoPipe {
 public:
  ~VideoPipe();
  /// Starts ffmpeg writing `file`. False with `error` when it cannot be started.
  bool open(const std::filesystem::path& ffmpeg, const std::filesystem::path& file, int width,
            int height, std::string& error);
  /// Sends one frame (rows from the top). False when ffmpeg stopped reading.
  bool write(const Image& image);
  /// Waits for ffmpeg to finish. False with `error` when it failed.
  bool close(std::string& error);

 private:
  std::FILE* m_pipe = nullptr;
  std::string m_rgb;
};

}  // namespace stroma::rendering
