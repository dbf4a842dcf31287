// SPDX-License-Identifier: MIT
// Sphere files (.sph): the format is described in SphereData.h. Read line by line, so that each
// error names its line and the field of that line that is wrong.
#include <algorithm>

#include "FormatParsers.h"
#include "SphereData.h"
#include "TextCursor.h"

namespace stroma {

namespace {

using meshio::parseNumber;
using meshio::quoted;
using meshio::TextCursor;

/// The shortest sphere line, "sphe 0 0 0 0 0\n": the cap on what 'nums' may reserve.
constexpr std::size_t kShortestSphereLine = 15;

class SphereReader {
 public:
  SphereReader(std::string_view bytes, SphereData& spheres, std::string& error)
      : m_text(bytes), m_spheres(spheres), m_error(error) {}

  bool read() {
    if (m_text.text().empty()) return fail(1, "the file is empty (expected the header 'sph 1.0')");
    if (!readHeader()) return false;
    int lastLine = 1;
    while (m_text.offset() < m_text.text().size()) {
      const int line = m_line++;
      lastLine = line;
      TextCursor in(withoutComment(m_text.restOfLine()));
      const std::string_view keyword = in.next();
      if (keyword.empty()) continue;  // a blank or comment line
      bool ok = false;
      if (keyword == "sphe")
        ok = readSphere(in, line);
      else if (keyword == "nums")
        ok = readAnnouncedCount(in, line);
      else
        ok = fail(line, "expected 'sphe', 'nums' or a comment '#', got " + quoted(keyword));
      if (!ok) return false;
    }
    // What the whole file must satisfy.
    if (m_spheres.centers.empty())
      return fail(lastLine,
                  "no sphere in the file (expected lines 'sphe index x y z radius' after the "
                  "header)");
    if (m_numsLine > 0 && m_announced != m_spheres.centers.size())
      return fail(m_numsLine, "'nums' announces " + std::to_string(m_announced) +
                                  " spheres, the file has " +
                                  std::to_string(m_spheres.centers.size()));
    return true;
  }

 private:
  bool fail(int line, const std::string& text) {
    m_error = "line " + std::to_string(line) + ": " + text;
    m_spheres = SphereData{};
    return false;
  }

  static std::string_view withoutComment(std::string_view line) {
    const auto hash = line.find('#');
    return hash == std::string_view::npos ? line : line.substr(0, hash);
  }

  /// Line 1: "sph 1.0" (after a UTF-8 byte order mark, if any).
  bool readHeader() {
    std::string_view first = m_text.restOfLine();
    const int line = m_line++;
    if (first.starts_with("\xEF\xBB\xBF")) first.remove_prefix(3);
    TextCursor in(withoutComment(first));
    const std::string_view keyword = in.next();
    if (keyword != "sph")
      return fail(line, "expected the header 'sph 1.0', got " +
                            (keyword.empty() ? std::string("an empty line") : quoted(keyword)));
    const std::string_view version = in.next();
    double number = 0;
    if (!parseNumber(version, number) || number != 1.0)
      return fail(line, "unsupported version " +
                            (version.empty() ? std::string("(none)") : quoted(version)) +
                            " in the header (expected 'sph 1.0')");
    if (const std::string_view extra = in.next(); !extra.empty())
      return fail(line, "expected the end of the header 'sph 1.0', got " + quoted(extra));
    return true;
  }

  /// "sphe index x y z radius".
  bool readSphere(TextCursor& in, int line) {
    std::string_view tokens[5];
    std::size_t count = 0;
    for (std::string_view token = in.next(); !token.empty(); token = in.next()) {
      if (count < 5) tokens[count] = token;
      ++count;
    }
    if (count != 5)
      return fail(line, "expected 5 numbers after 'sphe' (index x y z radius), got " +
                            std::to_string(count));
    long long index = 0;
    if (!parseNumber(tokens[0], index))
      return fail(line, "expected the index of the sphere, an integer, got " + quoted(tokens[0]));
    Vec3d center;
    static constexpr const char* kAxes[] = {"x", "y", "z"};
    for (int axis = 0; axis < 3; ++axis)
      if (!parseNumber(tokens[1 + axis], center[axis]))
        return fail(line, std::string("expected the ") + kAxes[axis] +
                              " coordinate of the center, a finite number, got " +
                              quoted(tokens[1 + axis]));
    double radius = 0;
    if (!parseNumber(tokens[4], radius))
      return fail(line, "expected the radius of the sphere, a finite number >= 0, got " +
                            quoted(tokens[4]));
    if (radius < 0)
      return fail(line, "the radius of the sphere " + quoted(tokens[4]) +
                            " is negative (expected a finite number >= 0)");
    m_spheres.centers.push_back(center);
    m_spheres.radii.push_back(radius);
    return true;
  }

  /// "nums count": checked against the spheres at the end.
  bool readAnnouncedCount(TextCursor& in, int line) {
    if (m_numsLine > 0)
      return fail(line,
                  "a second 'nums' line (the first is line " + std::to_string(m_numsLine) + ")");
    const std::string_view token = in.next();
    long long count = 0;
    if (!parseNumber(token, count) || count < 0)
      return fail(line, "expected the number of spheres after 'nums', an integer >= 0, got " +
                            (token.empty() ? std::string("nothing") : quoted(token)));
    if (const std::string_view extra = in.next(); !extra.empty())
      return fail(line, "expected one number after 'nums', got also " + quoted(extra));
    m_numsLine = line;
    m_announced = static_cast<unsigned long long>(count);
    // Reserve no more than the bytes can hold.
    const std::size_t cap = meshio::maxItems(m_text.text(), kShortestSphereLine);
    const std::size_t reserve =
        static_cast<std::size_t>(std::min<unsigned long long>(m_announced, cap));
    m_spheres.centers.reserve(reserve);
    m_spheres.radii.reserve(reserve);
    return true;
  }

  TextCursor m_text;
  SphereData& m_spheres;
  std::string& m_error;
  int m_line = 1;
  int m_numsLine = 0;  // 0: no nums line
  unsigned long long m_announced = 0;
};

}  // namespace

bool parseSpheres(std::string_view bytes, SphereData& spheres, std::string& error) {
  spheres = SphereData{};
  error.clear();
  SphereReader reader(bytes, spheres, error);
  if (reader.read()) return true;
  if (error.empty()) error = "unreadable file";
  return false;
}

bool readSphereFile(const std::string& path, SphereData& spheres, std::string& error) {
  std::string bytes;
  if (!meshio::readFileBytes(path, bytes, error)) return false;
  return parseSpheres(bytes, spheres, error);
}

}  // namespace stroma
