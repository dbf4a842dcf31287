// SPDX-License-Identifier: MIT
// NRRD (teem's "nearly raw raster data"): a first line NRRD000x, "field: value" lines, then a
// blank line and the data (.nrrd), or the data in the file named by "data file" (.nhdr).
// Only scalar 3D (or 2D) images are read, with raw, text or gzip encoding.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <optional>

#include "image/ImageData.h"

namespace stroma::image::detail {
namespace {

std::optional<SampleType> nrrdType(const std::string& spelled) {
  // The type names of the NRRD format, normalised to lower case with single spaces.
  static const std::map<std::string, SampleType> names{
      {"signed char", SampleType::int8},
      {"int8", SampleType::int8},
      {"int8_t", SampleType::int8},
      {"uchar", SampleType::uint8},
      {"unsigned char", SampleType::uint8},
      {"uint8", SampleType::uint8},
      {"uint8_t", SampleType::uint8},
      {"short", SampleType::int16},
      {"short int", SampleType::int16},
      {"signed short", SampleType::int16},
      {"signed short int", SampleType::int16},
      {"int16", SampleType::int16},
      {"int16_t", SampleType::int16},
      {"ushort", SampleType::uint16},
      {"unsigned short", SampleType::uint16},
      {"unsigned short int", SampleType::uint16},
      {"uint16", SampleType::uint16},
      {"uint16_t", SampleType::uint16},
      {"int", SampleType::int32},
      {"signed int", SampleType::int32},
      {"int32", SampleType::int32},
      {"int32_t", SampleType::int32},
      {"uint", SampleType::uint32},
      {"unsigned int", SampleType::uint32},
      {"uint32", SampleType::uint32},
      {"uint32_t", SampleType::uint32},
      {"longlong", SampleType::int64},
      {"long long", SampleType::int64},
      {"long long int", SampleType::int64},
      {"signed long long", SampleType::int64},
      {"signed long long int", SampleType::int64},
      {"int64", SampleType::int64},
      {"int64_t", SampleType::int64},
      {"ulonglong", SampleType::uint64},
      {"unsigned long long", SampleType::uint64},
      {"unsigned long long int", SampleType::uint64},
      {"uint64", SampleType::uint64},
      {"uint64_t", SampleType::uint64},
      {"float", SampleType::float32},
      {"double", SampleType::float64}};
  std::string words;
  for (char c : lowercase(spelled)) {
    if (c == ' ' || c == '\t') {
      if (!words.empty() && words.back() != ' ') words += ' ';
    } else {
      words += c;
    }
  }
  const auto found = names.find(std::string(trim(words)));
  if (found == names.end()) return std::nullopt;
  return found->second;
}

/// "(1,0,0) (0,2.5,0) none" -> one vector per axis; false on a malformed list.
bool parseDirections(std::string_view text, std::vector<std::optional<Vec3d>>& directions,
                     std::string& why) {
  directions.clear();
  std::size_t pos = 0;
  while (true) {
    while (pos < text.size() && (text[pos] == ' ' || text[pos] == '\t')) ++pos;
    if (pos >= text.size()) return true;
    if (text.substr(pos, 4) == "none") {
      directions.emplace_back(std::nullopt);
      pos += 4;
      continue;
    }
    if (text[pos] != '(') {
      why = "expected '(x,y,z)' or 'none', got '" + std::string(text.substr(pos)) + "'";
      return false;
    }
    const std::size_t close = text.find(')', pos);
    if (close == std::string_view::npos) {
      why = "missing ')'";
      return false;
    }
    std::vector<double> v;
    if (!parseNumbers(text.substr(pos + 1, close - pos - 1), -1, v, why)) return false;
    if (v.size() < 2 || v.size() > 3) {
      why = "expected vectors of 3 coordinates (space dimension 3)";
      return false;
    }
    directions.emplace_back(Vec3d(v[0], v[1], v.size() == 3 ? v[2] : 0.0));
    pos = close + 1;
  }
}

struct NrrdHeader {
  int dimension = 0;
  std::vector<double> sizes, spacings;
  std::vector<std::optional<Vec3d>> directions;
  std::optional<Vec3d> origin;
  std::optional<SampleType> type;
  std::optional<bool> bigEndian;
  std::string encoding = "raw";
  std::string dataFile;
  long long byteSkip = 0, lineSkip = 0;
  std::map<std::string, int> lineOf;  // line of each field read
  std::size_t dataOffset = 0;         // where attached data starts
};

}  // namespace

bool readNrrd(const std::string& path, VolumeImage& image, std::string& error) {
  std::string text;
  if (!readFileBytes(path, text, error)) return false;
  NrrdHeader h;
  const auto fail = [&](int line, std::string_view field, const std::string& why) {
    error = "NRRD '" + path + "', line " + std::to_string(line) + ": " + std::string(field) + ": " +
            why;
    return false;
  };
  const auto failField = [&](const std::string& field, const std::string& why) {
    const auto found = h.lineOf.find(field);
    return fail(found == h.lineOf.end() ? 1 : found->second, field, why);
  };

  // 1. The magic line, then the fields up to a blank line (or the end of a detached header).
  if (text.compare(0, 7, "NRRD000") != 0)
    return fail(1, "magic", "not a NRRD file (the first line must be NRRD0001 to NRRD0005)");
  std::size_t pos = text.find('\n');
  pos = pos == std::string::npos ? text.size() : pos + 1;
  int line = 1;
  while (pos < text.size()) {
    std::size_t end = text.find('\n', pos);
    if (end == std::string::npos) end = text.size();
    std::string_view raw = std::string_view(text).substr(pos, end - pos);
    pos = std::min(end + 1, text.size());
    ++line;
    if (!raw.empty() && raw.back() == '\r') raw.remove_suffix(1);
    if (raw.empty()) break;  // the data follows
    if (raw.front() == '#') continue;
    if (raw.find(":=") != std::string_view::npos) continue;  // key/value pairs: metadata only
    const std::size_t colon = raw.find(": ");
    if (colon == std::string_view::npos)
      return fail(line, trim(raw.substr(0, 40)), "expected 'field: value'");
    const std::string field = lowercase(trim(raw.substr(0, colon)));
    const std::string value(trim(raw.substr(colon + 2)));
    h.lineOf[field] = line;
    std::string why;
    std::vector<double> v;
    if (field == "dimension") {
      if (!parseNumbers(value, 1, v, why) || v[0] != std::floor(v[0]) || v[0] < 1)
        return fail(line, field, "'" + value + "': expected a whole number");
      h.dimension = int(v[0]);
      if (h.dimension == 4)
        return fail(line, field,
                    "4: a multi-channel or vector image; only scalar images (dimension 3, or 2 "
                    "read as one slice) are read");
      if (h.dimension != 2 && h.dimension != 3)
        return fail(line, field,
                    "'" + value + "': only 3D images (or 2D, read as one slice) are read");
    } else if (field == "type") {
      h.type = nrrdType(value);
      if (!h.type)
        return fail(line, field,
                    "unknown type '" + value +
                        "' (expected a NRRD type: int8, uint8, int16, uint16, int32, uint32, "
                        "int64, uint64, float, double or their C spellings)");
    } else if (field == "sizes") {
      if (!parseNumbers(value, -1, h.sizes, why)) return fail(line, field, why);
    } else if (field == "spacings") {
      // "nan" marks a non-spatial axis: read as spacing 1.
      if (!parseNumbers(value, -1, h.spacings, why)) return fail(line, field, why);
    } else if (field == "space directions") {
      if (!parseDirections(value, h.directions, why)) return fail(line, field, why);
    } else if (field == "space origin") {
      std::string inner = value;
      if (inner.size() >= 2 && inner.front() == '(' && inner.back() == ')')
        inner = inner.substr(1, inner.size() - 2);
      if (!parseNumbers(inner, -1, v, why) || v.size() < 2 || v.size() > 3)
        return fail(line, field, "'" + value + "': expected (x,y,z)");
      h.origin = Vec3d(v[0], v[1], v.size() == 3 ? v[2] : 0.0);
    } else if (field == "endian") {
      const std::string e = lowercase(value);
      if (e != "little" && e != "big")
        return fail(line, field, "'" + value + "': expected little or big");
      h.bigEndian = e == "big";
    } else if (field == "encoding") {
      h.encoding = lowercase(value);
    } else if (field == "data file" || field == "datafile") {
      h.dataFile = value;
    } else if (field == "byte skip" || field == "byteskip") {
      if (!parseNumbers(value, 1, v, why) || v[0] < -1 || v[0] != std::floor(v[0]))
        return fail(line, field, "'" + value + "': expected a byte count >= 0, or -1");
      h.byteSkip = (long long)v[0];
    } else if (field == "line skip" || field == "lineskip") {
      if (!parseNumbers(value, 1, v, why) || v[0] < 0 || v[0] != std::floor(v[0]))
        return fail(line, field, "'" + value + "': expected a line count >= 0");
      h.lineSkip = (long long)v[0];
    } else if (field == "kinds") {
      // A non-spatial axis (RGB-color, 3-vector, list...) makes a multi-channel image.
      std::size_t axis = 0, at = 0;
      while (at < value.size()) {
        const std::size_t end = std::min(value.find_first_of(" \t", at), value.size());
        const std::string kind = lowercase(value.substr(at, end - at));
        if (!kind.empty()) {
          if (kind != "domain" && kind != "space" && kind != "time" && kind != "none" &&
              kind != "???")
            return fail(line, field,
                        "axis " + std::to_string(axis) + " is '" + kind +
                            "': a multi-channel or vector image; only scalar images are read");
          ++axis;
        }
        at = end + 1;
      }
    } else if (field == "space dimension") {
      if (!parseNumbers(value, 1, v, why) || (v[0] != 3 && v[0] != 2))
        return fail(line, field, "'" + value + "': only 3D space is read");
    }
    // Other fields (space, kinds, centerings, content, units, min/max...) leave the voxels as
    // they are.
  }
  h.dataOffset = pos;

  // 2. Check the fields.
  if (h.dimension == 0) return failField("dimension", "missing");
  if (!h.type) return failField("type", "missing");
  const auto nd = std::size_t(h.dimension);
  if (h.sizes.size() != nd)
    return failField("sizes", h.sizes.empty()
                                  ? "missing"
                                  : "expected dimension = " + std::to_string(nd) + " sizes, got " +
                                        std::to_string(h.sizes.size()));
  for (double s : h.sizes)
    if (s < 0 || s != std::floor(s) || s > std::numeric_limits<int>::max())
      return failField("sizes", "sizes must be whole numbers >= 0");
  if (!h.spacings.empty() && h.spacings.size() != nd)
    return failField("spacings", "expected dimension = " + std::to_string(nd) + " spacings, got " +
                                     std::to_string(h.spacings.size()));
  if (!h.directions.empty() && h.directions.size() != nd)
    return failField("space directions", "expected dimension = " + std::to_string(nd) +
                                             " vectors, got " +
                                             std::to_string(h.directions.size()));
  const double voxels = h.sizes[0] * h.sizes[1] * (nd == 3 ? h.sizes[2] : 1.0);
  if (voxels > kMaxVoxels)
    return failField(
        "sizes", "an image of " + std::to_string(voxels) + " voxels is beyond what can be read");
  image = VolumeImage{};
  image.size = {int(h.sizes[0]), int(h.sizes[1]), nd == 3 ? int(h.sizes[2]) : 1};
  const std::size_t count = image.voxelCount();
  if (count == 0) return failField("sizes", "empty image (zero voxels)");
  const bool text_ = h.encoding == "ascii" || h.encoding == "text" || h.encoding == "txt";
  const bool gzip = h.encoding == "gzip" || h.encoding == "gz";
  if (!text_ && !gzip && h.encoding != "raw")
    return failField("encoding",
                     "'" + h.encoding + "' is not read (raw, ascii/text/txt and gzip/gz are)");
  if (!text_ && sampleBytes(*h.type) > 1 && !h.bigEndian)
    return failField("endian",
                     "missing: required for " + std::string(sampleTypeName(*h.type)) + " samples");

  // 3. The data bytes: lines skipped in the file, then decompressed, then bytes skipped.
  std::string external;
  std::string_view data;
  std::string dataName = path;
  if (h.dataFile.empty()) {
    if (h.dataOffset >= text.size() && h.lineOf.count("data file") == 0)
      return fail(line, "data",
                  "no data after the header (a .nrrd needs a blank line then the "
                  "data; a .nhdr needs 'data file:')");
    data = std::string_view(text).substr(h.dataOffset);
  } else {
    if (h.dataFile.rfind("LIST", 0) == 0 || h.dataFile.find('%') != std::string::npos ||
        h.dataFile.find(' ') != std::string::npos)
      return failField("data file",
                       "'" + h.dataFile + "': only one data file is read, not a list of slices");
    dataName = siblingPath(path, h.dataFile);
    std::string why;
    if (!readFileBytes(dataName, external, why)) return failField("data file", why);
    data = external;
  }
  for (long long n = 0; n < h.lineSkip; ++n) {
    const std::size_t next = data.find('\n');
    if (next == std::string_view::npos)
      return failField("line skip", "'" + dataName + "' has fewer lines than skipped");
    data.remove_prefix(next + 1);
  }
  std::string inflated;
  if (gzip) {
    std::string why;
    const std::size_t needed =
        count * sampleBytes(*h.type) + std::size_t(std::max(0LL, h.byteSkip));
    if (!inflateBytes(data, needed, inflated, why))
      return failField("encoding", "'" + dataName + "': " + why);
    data = inflated;
  }
  if (text_) {
    std::string why;
    if (!decodeText(data, count, image.values, why))
      return fail(h.lineOf.count("encoding") ? h.lineOf["encoding"] : line, "data",
                  "'" + dataName + "': " + why);
  } else {
    std::string why;
    if (!decodeBinarySamples(data, dataName, *h.type, h.bigEndian.value_or(false), h.byteSkip,
                             image, why))
      return failField(h.dataFile.empty() ? "sizes" : "data file", why);
  }

  // 4. Place the axes: space directions, else spacings, else unit spacing.
  std::array<Vec3d, 3> directions{Vec3d::UnitX(), Vec3d::UnitY(), Vec3d::UnitZ()};
  for (std::size_t a = 0; a < nd; ++a) {
    if (!h.directions.empty()) {
      if (!h.directions[a])
        return failField("space directions",
                         "axis " + std::to_string(a) + " is 'none': every axis must be spatial");
      directions[a] = *h.directions[a];
    } else if (!h.spacings.empty() && std::isfinite(h.spacings[a])) {
      directions[a][Eigen::Index(a)] = h.spacings[a];
    }
  }
  if (nd == 2) directions[2] = Vec3d::UnitZ() * (directions[0].norm() + directions[1].norm()) / 2;
  std::string why;
  if (!placeAxes(directions, h.origin.value_or(Vec3d::Zero()), image, why))
    return failField(h.directions.empty() ? "spacings" : "space directions", why);
  return true;
}

}  // namespace stroma::image::detail
