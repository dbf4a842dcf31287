// SPDX-License-Identifier: MIT
#include "FrameSink.h"

#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace stroma::rendering {

namespace fs = std::filesystem;

namespace {

/// Single-quotes a word for /bin/sh.
std::string shellQuoted(const std::string& word) {
  std::string out = "'";
  for (char c : word) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

}  // namespace

fs::path findOnPath(const std::string& name) {
  const char* path = std::getenv("PATH");
  if (!path) return {};
  std::istringstream dirs(path);
  std::string dir;
  while (std::getline(dirs, dir, ':')) {
    const fs::path candidate = fs::path(dir.empty() ? "." : dir) / name;
    std::error_code ec;
    if (fs::is_regular_file(candidate, ec) && ::access(candidate.c_str(), X_OK) == 0)
      return candidate;
  }
  return {};
}

bool prepareOutputFolder(const fs::path& dir, std::string& error) {
  std::error_code ec;
  if (fs::exists(dir, ec) && !fs::is_directory(dir, ec)) {
    error = "--out " + dir.string() + ": exists and is not a folder";
    return false;
  }
  fs::create_directories(dir, ec);
  if (ec) {
    error = "--out " + dir.string() + ": cannot create the folder (" + ec.message() + ")";
    return false;
  }
  // Permissions alone do not tell (root, read-only mounts): try writing.
  const fs::path probe = dir / ".stroma-render-probe";
  {
    std::ofstream out(probe);
    out << "probe\n";
    if (!out.flush()) {
      error = "--out " + dir.string() + ": cannot write files in this folder";
      return false;
    }
  }
  fs::remove(probe, ec);
  return true;
}

std::string frameFileName(long long frame) {
  char name[32];
  std::snprintf(name, sizeof name, "frame_%05lld.png", frame);
  return name;
}

VideoPipe::~VideoPipe() {
  if (m_pipe) pclose(m_pipe);
}

bool VideoPipe::open(const fs::path& ffmpeg, const fs::path& file, int width, int height,
                     std::string& error) {
  // A dead ffmpeg must not kill us through SIGPIPE: write() then fails and says so.
  std::signal(SIGPIPE, SIG_IGN);
  const std::string size = std::to_string(width) + "x" + std::to_string(height);
  // yuv420p (what players expect) needs even sides: the scale filter rounds them down.
  const std::string command = shellQuoted(ffmpeg.string()) +
                              " -hide_banner -loglevel error -y -f rawvideo -pix_fmt rgb24 -s " +
                              size +
                              " -framerate 25 -i - -vf 'scale=trunc(iw/2)*2:trunc(ih/2)*2' "
                              "-c:v libx264 -pix_fmt yuv420p " +
                              shellQuoted(file.string());
  m_pipe = popen(command.c_str(), "w");
  if (!m_pipe) {
    error = "cannot start " + ffmpeg.string();
    return false;
  }
  return true;
}

bool VideoPipe::write(const Image& image) {
  if (!m_pipe) return false;
  const std::size_t pixels = static_cast<std::size_t>(image.width) * image.height;
  m_rgb.resize(pixels * 3);
  for (std::size_t i = 0; i < pixels; ++i)
    for (int c = 0; c < 3; ++c) m_rgb[3 * i + c] = static_cast<char>(image.rgba[4 * i + c]);
  return std::fwrite(m_rgb.data(), 1, m_rgb.size(), m_pipe) == m_rgb.size();
}

bool VideoPipe::close(std::string& error) {
  if (!m_pipe) return true;
  const int status = pclose(m_pipe);
  m_pipe = nullptr;
  if (status == -1 || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    error = "ffmpeg failed (exit status " +
            std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : -1) +
            "); its messages are above";
    return false;
  }
  return true;
}

}  // namespace stroma::rendering
