// SPDX-License-Identifier: MIT
#include "RenderOptions.h"

#include <charconv>

#include "stroma/rendering/Camera.h"

namespace stroma::rendering {

const std::vector<std::string>& renderValueOptions() {
  static const std::vector<std::string> options = {
      "-n",      "--steps", "--every",   "--out",       "--size",     "--camera", "--color-map",
      "--video", "--dt",    "--threads", "--data-path", "--log-json", "--show"};
  return options;
}

const std::vector<std::string>& renderFlagOptions() {
  static const std::vector<std::string> flags = {"--verbose", "--no-legend"};
  return flags;
}

bool parseSize(const std::string& text, int& width, int& height, std::string& error) {
  const std::size_t split = text.find_first_of("xX* ");
  auto number = [](std::string_view s, long long& v) {
    auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    return ec == std::errc() && ptr == s.data() + s.size();
  };
  long long w = 0, h = 0;
  if (split == std::string::npos || !number(std::string_view(text).substr(0, split), w) ||
      !number(std::string_view(text).substr(split + 1), h)) {
    error = "--size expects WIDTHxHEIGHT in pixels (e.g. 1280x720), got '" + text + "'";
    return false;
  }
  if (w < 1 || h < 1 || w > kMaxPictureSide || h > kMaxPictureSide) {
    error = "--size " + text + ": each side must be 1 to " + std::to_string(kMaxPictureSide) +
            " pixels (OSMesa's largest buffer)";
    return false;
  }
  width = static_cast<int>(w);
  height = static_cast<int>(h);
  return true;
}

bool parseRenderOptions(const cli::Arguments& a, RenderOptions& o, std::string& error) {
  cli::Arguments numbers = a;
  if (const std::string* s = a.value("--steps")) numbers.options["-n"].push_back(*s);
  if (!cli::readInteger(numbers, "-n", 0, o.steps, error) ||
      !cli::readInteger(numbers, "--every", 1, o.every, error) ||
      !cli::readInteger(numbers, "--threads", 0, o.threads, error) ||
      !cli::readReal(numbers, "--dt", o.dt, error))
    return false;
  if (const std::string* out = a.value("--out")) {
    if (out->empty()) {
      error = "--out needs a folder name";
      return false;
    }
    o.outputDir = *out;
    o.outputDirGiven = true;
  }
  if (const std::string* size = a.value("--size"))
    if (!parseSize(*size, o.width, o.height, error)) return false;
  if (const std::string* camera = a.value("--camera")) {
    Vec3d eye, target;
    std::string why;
    if (!parseEyeAndTarget(*camera, eye, target, why)) {
      error = "--camera \"" + *camera + "\": " + why;
      return false;
    }
    o.eyeAndTarget = std::make_pair(eye, target);
  }
  if (const std::string* map = a.value("--color-map")) {
    std::string why;
    if (!parseColorMapKind(*map, o.colorMap, why)) {
      error = "--color-map: " + why;
      return false;
    }
  }
  if (const std::string* video = a.value("--video")) {
    if (video->empty()) {
      error = "--video needs a file name (FILE.mp4)";
      return false;
    }
    o.video = *video;
  }
  o.legend = !a.has("--no-legend");
  if (const std::string* show = a.value("--show")) o.show = *show;
  return true;
}

}  // namespace stroma::rendering
