// SPDX-License-Identifier: MIT
// MetaImage (ITK's MetaIO): a text header of "Key = Value" lines ending with ElementDataFile,
// then the data, in this file (ElementDataFile = LOCAL, the .mha form) or in the file it names,
// relative to the header (the .mhd + .raw form).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <optional>

#include "image/ImageData.h"

namespace stroma::image::detail {
namespace {

std::optional<SampleType> metaType(const std::string& name) {
  if (name == "MET_CHAR") return SampleType::int8;
  if (name == "MET_UCHAR") return SampleType::uint8;
  if (name == "MET_SHORT") return SampleType::int16;
  if (name == "MET_USHORT") return SampleType::uint16;
  if (name == "MET_INT" || name == "MET_LONG") return SampleType::int32;
  if (name == "MET_UINT" || name == "MET_ULONG") return SampleType::uint32;
  if (name == "MET_LONG_LONG") return SampleType::int64;
  if (name == "MET_ULONG_LONG") return SampleType::uint64;
  if (name == "MET_FLOAT") return SampleType::float32;
  if (name == "MET_DOUBLE") return SampleType::float64;
  return std::nullopt;
}

/// The header's fields, as read.
struct MetaHeader {
  int ndims = 0;
  std::vector<double> dimSize, spacing, elementSize, offset, transform;
  std::optional<SampleType> type;
  bool bigEndian = false;
  bool compressed = false;
  bool binary = true;
  long long headerSize = 0;
  std::string dataFile;
  int dataFileLine = 0;
  std::size_t dataOffset = 0;         // where LOCAL data starts in the header file
  std::map<std::string, int> lineOf;  // line of each key read
  /// The line of `key` (of ElementDataFile, the last one, when `key` is absent).
  int line(const std::string& key) const {
    const auto found = lineOf.find(key);
    return found == lineOf.end() ? dataFileLine : found->second;
  }
};

}  // namespace

bool readMetaImage(const std::string& path, VolumeImage& image, std::string& error) {
  std::string text;
  if (!readFileBytes(path, text, error)) return false;
  const auto fail = [&](int line, std::string_view field, const std::string& why) {
    error = "MetaImage '" + path + "', line " + std::to_string(line) + ": " + std::string(field) +
            ": " + why;
    return false;
  };

  // 1. The header, up to and including ElementDataFile.
  MetaHeader h;
  std::size_t pos = 0;
  int line = 0;
  while (h.dataFile.empty()) {
    if (pos >= text.size())
      return fail(line, "ElementDataFile",
                  "missing (it must be the last header line, naming the data file or LOCAL)");
    std::size_t end = text.find('\n', pos);
    if (end == std::string::npos) end = text.size();
    const std::string_view raw = std::string_view(text).substr(pos, end - pos);
    pos = end + 1;
    ++line;
    const std::string_view content = trim(raw);
    if (content.empty()) continue;
    const std::size_t eq = content.find('=');
    if (eq == std::string_view::npos)
      return fail(line, trim(content.substr(0, 40)),
                  "expected 'Key = Value' (is this a MetaImage header?)");
    const std::string key(trim(content.substr(0, eq)));
    const std::string value(trim(content.substr(eq + 1)));
    std::string why;
    h.lineOf[key] = line;
    if (key == "ObjectType") {
      if (lowercase(value) != "image")
        return fail(line, key, "'" + value + "': only Image objects are read");
    } else if (key == "NDims") {
      std::vector<double> v;
      if (!parseNumbers(value, 1, v, why) || (v[0] != 2 && v[0] != 3))
        return fail(line, key,
                    "'" + value + "': only 3D images (or 2D, read as one slice) are read");
      h.ndims = int(v[0]);
    } else if (key == "DimSize") {
      if (!parseNumbers(value, -1, h.dimSize, why)) return fail(line, key, why);
    } else if (key == "ElementSpacing") {
      if (!parseNumbers(value, -1, h.spacing, why)) return fail(line, key, why);
    } else if (key == "ElementSize") {
      if (!parseNumbers(value, -1, h.elementSize, why)) return fail(line, key, why);
    } else if (key == "Offset" || key == "Position" || key == "Origin") {
      if (!parseNumbers(value, -1, h.offset, why)) return fail(line, key, why);
    } else if (key == "TransformMatrix" || key == "Rotation" || key == "Orientation") {
      if (!parseNumbers(value, -1, h.transform, why)) return fail(line, key, why);
    } else if (key == "ElementType") {
      h.type = metaType(value);
      if (!h.type)
        return fail(line, key,
                    "unknown type '" + value +
                        "' (expected MET_CHAR, MET_UCHAR, MET_SHORT, MET_USHORT, MET_INT, "
                        "MET_UINT, MET_LONG_LONG, MET_ULONG_LONG, MET_FLOAT or MET_DOUBLE)");
    } else if (key == "ElementByteOrderMSB" || key == "BinaryDataByteOrderMSB") {
      if (!parseBoolean(value, h.bigEndian))
        return fail(line, key, "'" + value + "': expected True or False");
    } else if (key == "CompressedData") {
      if (!parseBoolean(value, h.compressed))
        return fail(line, key, "'" + value + "': expected True or False");
    } else if (key == "BinaryData") {
      if (!parseBoolean(value, h.binary))
        return fail(line, key, "'" + value + "': expected True or False");
    } else if (key == "HeaderSize") {
      std::vector<double> v;
      if (!parseNumbers(value, 1, v, why) || v[0] < -1 || v[0] != std::floor(v[0]))
        return fail(line, key, "'" + value + "': expected a byte count >= 0, or -1");
      h.headerSize = (long long)v[0];
    } else if (key == "ElementNumberOfChannels") {
      std::vector<double> v;
      if (!parseNumbers(value, 1, v, why) || v[0] != 1)
        return fail(line, key, "'" + value + "': only single-channel (scalar) images are read");
    } else if (key == "ElementDataFile") {
      if (value.empty()) return fail(line, key, "empty: expected a file name or LOCAL");
      h.dataFile = value;
      h.dataFileLine = line;
      h.dataOffset = std::min(pos, text.size());
    }
    // Other keys (AnatomicalOrientation, CenterOfRotation, ElementMin, Comment...) do not
    // change the voxels.
  }

  // 2. Check the geometry against NDims.
  if (h.ndims == 0) return fail(h.line("NDims"), "NDims", "missing");
  const auto nd = std::size_t(h.ndims);
  if (h.dimSize.size() != nd)
    return fail(h.line("DimSize"), "DimSize",
                h.dimSize.empty() ? "missing"
                                  : "expected NDims = " + std::to_string(nd) + " sizes, got " +
                                        std::to_string(h.dimSize.size()));
  for (double s : h.dimSize)
    if (s < 0 || s != std::floor(s) || s > std::numeric_limits<int>::max())
      return fail(h.line("DimSize"), "DimSize", "sizes must be whole numbers >= 0");
  if (h.spacing.empty()) h.spacing = h.elementSize;
  if (h.spacing.empty()) h.spacing.assign(nd, 1.0);
  if (h.spacing.size() != nd)
    return fail(h.line("ElementSpacing"), "ElementSpacing",
                "expected NDims = " + std::to_string(nd) + " spacings, got " +
                    std::to_string(h.spacing.size()));
  if (h.offset.empty()) h.offset.assign(nd, 0.0);
  if (h.offset.size() != nd)
    return fail(h.line("Offset"), "Offset",
                "expected NDims = " + std::to_string(nd) + " coordinates, got " +
                    std::to_string(h.offset.size()));
  if (!h.transform.empty() && h.transform.size() != nd * nd)
    return fail(h.line("TransformMatrix"), "TransformMatrix",
                "expected NDims^2 = " + std::to_string(nd * nd) + " numbers, got " +
                    std::to_string(h.transform.size()));
  if (!h.type) return fail(h.line("ElementType"), "ElementType", "missing");

  const double voxels = h.dimSize[0] * h.dimSize[1] * (nd == 3 ? h.dimSize[2] : 1.0);
  if (voxels > kMaxVoxels)
    return fail(h.line("DimSize"), "DimSize",
                "an image of " + std::to_string(voxels) + " voxels is beyond what can be read");
  image = VolumeImage{};
  image.size = {int(h.dimSize[0]), int(h.dimSize[1]), nd == 3 ? int(h.dimSize[2]) : 1};
  const std::size_t count = image.voxelCount();
  if (count == 0) return fail(h.line("DimSize"), "DimSize", "empty image (zero voxels)");

  // 3. The data bytes.
  std::string external;
  std::string_view data;
  std::string dataName = path;
  if (lowercase(h.dataFile) == "local") {
    data = std::string_view(text).substr(h.dataOffset);
  } else {
    if (lowercase(h.dataFile) == "list" || h.dataFile.find('%') != std::string::npos ||
        h.dataFile.find(' ') != std::string::npos)
      return fail(
          h.dataFileLine, "ElementDataFile",
          "'" + h.dataFile + "': only one data file (or LOCAL) is read, not a list of slices");
    dataName = siblingPath(path, h.dataFile);
    std::string why;
    if (!readFileBytes(dataName, external, why))
      return fail(h.dataFileLine, "ElementDataFile", "data file: " + why);
    data = external;
  }
  std::string inflated;
  if (h.compressed) {
    std::string why;
    const std::size_t needed =
        h.binary ? count * sampleBytes(*h.type) + std::size_t(std::max(0LL, h.headerSize))
                 : std::string::npos;  // text: as long as the values are written
    if (!inflateBytes(data, needed, inflated, why))
      return fail(h.line("CompressedData"), "CompressedData", "'" + dataName + "': " + why);
    data = inflated;
  }
  if (!h.binary) {
    std::string why;
    if (!decodeText(data, count, image.values, why))
      return fail(h.dataFileLine, "ElementDataFile", "'" + dataName + "': " + why);
  } else {
    std::string why;
    if (!decodeBinarySamples(data, dataName, *h.type, h.bigEndian, h.headerSize, image, why))
      return fail(h.dataFileLine, "ElementDataFile", why);
  }

  // 4. Place the axes: spacing times the direction cosines (the diagonal only).
  std::array<Vec3d, 3> directions{Vec3d::UnitX(), Vec3d::UnitY(), Vec3d::UnitZ()};
  Vec3d first = Vec3d::Zero();
  for (std::size_t a = 0; a < 3; ++a) {
    if (a < nd) {
      first[Eigen::Index(a)] = h.offset[a];
      if (!h.transform.empty())
        for (std::size_t b = 0; b < nd; ++b)
          directions[a][Eigen::Index(b)] = h.transform[a * nd + b];
      directions[a] *= h.spacing[a];
    }
  }
  if (nd == 2) directions[2] = Vec3d::UnitZ() * (h.spacing[0] + h.spacing[1]) / 2;
  std::string why;
  if (!placeAxes(directions, first, image, why))
    return h.transform.empty() ? fail(h.line("ElementSpacing"), "ElementSpacing", why)
                               : fail(h.line("TransformMatrix"), "TransformMatrix", why);
  return true;
}

}  // namespace stroma::image::detail
