// SPDX-License-Identifier: MIT
// What the MetaImage and NRRD readers share (internal to the VolumeImage library): header lines,
// the sample types, decoding binary, text and compressed data into doubles, and placing the
// axes (flipping those given with a negative direction).
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "image/VolumeImage.h"

namespace stroma::image::detail {

enum class SampleType {
  int8,
  uint8,
  int16,
  uint16,
  int32,
  uint32,
  int64,
  uint64,
  float32,
  float64
};

std::size_t sampleBytes(SampleType type);
std::string_view sampleTypeName(SampleType type);

/// One "key <separator> value" line of a header: 1-based line number, key and value trimmed.
struct HeaderLine {
  int line = 0;
  std::string key;
  std::string value;
};

/// Splits `text` on whitespace and commas into numbers; false (with `why`) on a token that is
/// not a number or a count other than `count` (when count >= 0).
bool parseNumbers(std::string_view text, int count, std::vector<double>& numbers, std::string& why);
/// True for "true"/"1" and false for "false"/"0" (case-insensitive); false on anything else.
bool parseBoolean(std::string_view text, bool& value);
std::string lowercase(std::string_view text);
std::string_view trim(std::string_view text);

/// The whole file; false with "cannot open '<path>'" when it cannot be read.
bool readFileBytes(const std::string& path, std::string& bytes, std::string& error);
/// `name` relative to the folder of `headerPath` (unless absolute).
std::string siblingPath(const std::string& headerPath, const std::string& name);

/// Converts `count` samples of `type` starting at `data` (native order unless `bigEndian`
/// differs from the machine's) into `values`.
void decodeBinary(SampleType type, bool bigEndian, const char* data, std::size_t count,
                  std::vector<double>& values);
/// Decodes the binary samples of `image.size` after skipping `skip` bytes of `data` (-1: the
/// samples end the data, as MetaImage's HeaderSize and NRRD's byte skip say) into
/// `image.values`; false with a "size mismatch" `why` (bytes found and expected, the voxel
/// counts and type) when `data` is too short.
bool decodeBinarySamples(std::string_view data, const std::string& dataName, SampleType type,
                         bool bigEndian, long long skip, VolumeImage& image, std::string& why);
/// Reads `count` numbers written as text (whitespace or commas between them).
bool decodeText(std::string_view text, std::size_t count, std::vector<double>& values,
                std::string& why);
/// Inflates gzip or zlib data, stopping after `maxBytes` (what the header announces: more is
/// never needed, and a corrupt or hostile stream cannot exhaust the memory); false with `why`
/// when zlib is not built in or the data is bad.
bool inflateBytes(std::string_view compressed, std::size_t maxBytes, std::string& out,
                  std::string& why);

/// Voxels above this count (2^40, 8 TB of doubles) are refused before anything is allocated:
/// a header announcing more is corrupt or beyond any machine.
constexpr double kMaxVoxels = 1099511627776.0;

/// Sets the image's spacing and origin from one direction vector per axis (spacing times the
/// axis' unit direction) and the centre of the first voxel, flipping axes given with a negative
/// direction. False with `why` when a direction is not along its own axis (x, y, z in order) or
/// is zero. The values must be read already.
bool placeAxes(const std::array<Vec3d, 3>& directions, const Vec3d& firstVoxel, VolumeImage& image,
               std::string& why);

/// The readers of each format (path already known to have their extension).
bool readMetaImage(const std::string& path, VolumeImage& image, std::string& error);
bool readNrrd(const std::string& path, VolumeImage& image, std::string& error);

}  // namespace stroma::image::detail
