// SPDX-License-Identifier: MIT
#include "image/ImageData.h"

#include <algorithm>
#include <bit>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "formats/TextCursor.h"

#ifdef STROMA_HAS_ZLIB
#include <zlib.h>
#endif

namespace stroma::image::detail {

std::size_t sampleBytes(SampleType type) {
  switch (type) {
    case SampleType::int8:
    case SampleType::uint8:
      return 1;
    case SampleType::int16:
    case SampleType::uint16:
      return 2;
    case SampleType::int32:
    case SampleType::uint32:
    case SampleType::float32:
      return 4;
    case SampleType::int64:
    case SampleType::uint64:
    case SampleType::float64:
      return 8;
  }
  return 1;
}

std::string_view sampleTypeName(SampleType type) {
  static constexpr std::array<std::string_view, 10> names{
      "int8", "uint8", "int16", "uint16", "int32", "uint32", "int64", "uint64", "float", "double"};
  return names[std::size_t(type)];
}

std::string lowercase(std::string_view text) {
  std::string out(text);
  for (char& c : out) c = char(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

std::string_view trim(std::string_view text) {
  const auto space = [](char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; };
  while (!text.empty() && space(text.front())) text.remove_prefix(1);
  while (!text.empty() && space(text.back())) text.remove_suffix(1);
  return text;
}

bool parseNumbers(std::string_view text, int count, std::vector<double>& numbers,
                  std::string& why) {
  numbers.clear();
  std::size_t pos = 0;
  while (pos < text.size()) {
    const auto separator = [](char c) {
      return c == ',' || std::isspace(static_cast<unsigned char>(c)) != 0;
    };
    while (pos < text.size() && separator(text[pos])) ++pos;
    std::size_t end = pos;
    while (end < text.size() && !separator(text[end])) ++end;
    if (end == pos) break;
    const std::string_view token = text.substr(pos, end - pos);
    double value = 0;
    if (!meshio::parseNumber(token, value)) {
      why.assign(1, '\'').append(token).append("' is not a number");
      return false;
    }
    numbers.push_back(value);
    pos = end;
  }
  if (count >= 0 && int(numbers.size()) != count) {
    why = "expected " + std::to_string(count) + " numbers, got " + std::to_string(numbers.size()) +
          " ('" + std::string(text) + "')";
    return false;
  }
  return true;
}

bool parseBoolean(std::string_view text, bool& value) {
  const std::string word = lowercase(trim(text));
  if (word == "true" || word == "1") {
    value = true;
    return true;
  }
  if (word == "false" || word == "0") {
    value = false;
    return true;
  }
  return false;
}

bool readFileBytes(const std::string& path, std::string& bytes, std::string& error) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    error = "'" + path + "' is a folder, not a file";
    return false;
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    error = "cannot open '" + path + "'";
    return false;
  }
  std::ostringstream buffer;
  buffer << in.rdbuf();
  bytes = std::move(buffer).str();
  return true;
}

std::string siblingPath(const std::string& headerPath, const std::string& name) {
  const std::filesystem::path file(name);
  if (file.is_absolute()) return name;
  return (std::filesystem::path(headerPath).parent_path() / file).string();
}

namespace {

template <typename T>
void decodeAs(bool swap, const char* data, std::size_t count, std::vector<double>& values) {
  values.resize(count);
  for (std::size_t n = 0; n < count; ++n) {
    std::array<char, sizeof(T)> raw;
    std::memcpy(raw.data(), data + n * sizeof(T), sizeof(T));
    if (swap) std::reverse(raw.begin(), raw.end());
    T value;
    std::memcpy(&value, raw.data(), sizeof(T));
    values[n] = double(value);
  }
}

}  // namespace

bool decodeBinarySamples(std::string_view data, const std::string& dataName, SampleType type,
                         bool bigEndian, long long skip, VolumeImage& image, std::string& why) {
  const std::size_t count = image.voxelCount();
  const std::size_t bytes = count * sampleBytes(type);
  const std::size_t start = skip == -1 ? (data.size() >= bytes ? data.size() - bytes : 0)
                                       : std::size_t(skip);
  if (data.size() < start || data.size() - start < bytes) {
    why = "size mismatch: '" + dataName + "' holds " +
          std::to_string(data.size() > start ? data.size() - start : 0) +
          " bytes of data, expected " + std::to_string(bytes) + " (" +
          std::to_string(image.size[0]) + " x " + std::to_string(image.size[1]) + " x " +
          std::to_string(image.size[2]) + " voxels of " + std::string(sampleTypeName(type)) + ")";
    return false;
  }
  decodeBinary(type, bigEndian, data.data() + start, count, image.values);
  return true;
}

void decodeBinary(SampleType type, bool bigEndian, const char* data, std::size_t count,
                  std::vector<double>& values) {
  const bool swap = bigEndian != (std::endian::native == std::endian::big);
  switch (type) {
    case SampleType::int8:
      decodeAs<std::int8_t>(swap, data, count, values);
      break;
    case SampleType::uint8:
      decodeAs<std::uint8_t>(swap, data, count, values);
      break;
    case SampleType::int16:
      decodeAs<std::int16_t>(swap, data, count, values);
      break;
    case SampleType::uint16:
      decodeAs<std::uint16_t>(swap, data, count, values);
      break;
    case SampleType::int32:
      decodeAs<std::int32_t>(swap, data, count, values);
      break;
    case SampleType::uint32:
      decodeAs<std::uint32_t>(swap, data, count, values);
      break;
    case SampleType::int64:
      decodeAs<std::int64_t>(swap, data, count, values);
      break;
    case SampleType::uint64:
      decodeAs<std::uint64_t>(swap, data, count, values);
      break;
    case SampleType::float32:
      decodeAs<float>(swap, data, count, values);
      break;
    case SampleType::float64:
      decodeAs<double>(swap, data, count, values);
      break;
  }
}

bool decodeText(std::string_view text, std::size_t count, std::vector<double>& values,
                std::string& why) {
  if (!parseNumbers(text, -1, values, why)) return false;
  if (values.size() < count) {
    why = "expected " + std::to_string(count) + " values written as text, found " +
          std::to_string(values.size());
    return false;
  }
  values.resize(count);
  return true;
}

bool inflateBytes(std::string_view compressed, std::size_t maxBytes, std::string& out,
                  std::string& why) {
#ifdef STROMA_HAS_ZLIB
  z_stream stream{};
  // 32 + MAX_WBITS: zlib detects a gzip or a zlib header by itself.
  if (inflateInit2(&stream, 32 + MAX_WBITS) != Z_OK) {
    why = "zlib could not start";
    return false;
  }
  out.clear();
  std::array<char, 1 << 16> chunk;
  stream.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(compressed.data()));
  stream.avail_in = uInt(compressed.size());
  int status = Z_OK;
  while (status != Z_STREAM_END) {
    stream.next_out = reinterpret_cast<Bytef*>(chunk.data());
    stream.avail_out = uInt(chunk.size());
    status = inflate(&stream, Z_NO_FLUSH);
    if (status != Z_OK && status != Z_STREAM_END) {
      why = std::string("corrupt compressed data (zlib: ") +
            (stream.msg ? stream.msg : "truncated") + ")";
      inflateEnd(&stream);
      return false;
    }
    out.append(chunk.data(), chunk.size() - stream.avail_out);
    if (out.size() >= maxBytes) break;  // all that is needed
    if (status == Z_OK && stream.avail_in == 0 && stream.avail_out != 0) {
      why = "compressed data ends early (truncated file)";
      inflateEnd(&stream);
      return false;
    }
  }
  inflateEnd(&stream);
  return true;
#else
  (void)compressed;
  (void)maxBytes;
  out.clear();
  why =
      "compressed data needs zlib, which this build of Stroma was made without (install "
      "zlib1g-dev and rebuild)";
  return false;
#endif
}

bool placeAxes(const std::array<Vec3d, 3>& directions, const Vec3d& firstVoxel, VolumeImage& image,
               std::string& why) {
  static constexpr std::array<char, 3> axisName{'x', 'y', 'z'};
  Vec3d origin = firstVoxel;
  for (int a = 0; a < 3; ++a) {
    const Vec3d& d = directions[std::size_t(a)];
    const double along = d[a];
    const double across = std::hypot(d[(a + 1) % 3], d[(a + 2) % 3]);
    if (!(std::abs(along) > 0) || !std::isfinite(along) || across > 1e-9 * std::abs(along)) {
      std::ostringstream s;
      s << "axis " << a << " has direction (" << d.x() << ", " << d.y() << ", " << d.z()
        << "): only axis-aligned images are read (axis " << a << " along " << axisName[a]
        << ", with a non-zero spacing)";
      why = s.str();
      return false;
    }
    image.spacing[a] = std::abs(along);
  }
  // Flip the axes stored in decreasing coordinate: voxel i moves to n - 1 - i.
  for (int a = 0; a < 3; ++a) {
    if (directions[std::size_t(a)][a] > 0) continue;
    const int n = image.size[std::size_t(a)];
    origin[a] += (n - 1) * directions[std::size_t(a)][a];
    std::vector<double> flipped(image.values.size());
    for (int k = 0; k < image.size[2]; ++k)
      for (int j = 0; j < image.size[1]; ++j)
        for (int i = 0; i < image.size[0]; ++i) {
          std::array<int, 3> from{i, j, k};
          from[std::size_t(a)] = n - 1 - from[std::size_t(a)];
          flipped[image.index(i, j, k)] = image.at(from[0], from[1], from[2]);
        }
    image.values = std::move(flipped);
  }
  image.origin = origin;
  return true;
}

}  // namespace stroma::image::detail
