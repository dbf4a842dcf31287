// SPDX-License-Identifier: MIT
#include "image/VolumeImage.h"

#include <filesystem>

#include "image/ImageData.h"

namespace stroma::image {
namespace {

std::string extensionOf(const std::string& path) {
  return detail::lowercase(std::filesystem::path(path).extension().string());
}

}  // namespace

bool isVolumeImageFile(const std::string& path) {
  const std::string ext = extensionOf(path);
  return ext == ".mhd" || ext == ".mha" || ext == ".nrrd" || ext == ".nhdr";
}

bool readVolumeImage(const std::string& path, VolumeImage& image, std::string& error) {
  const std::string ext = extensionOf(path);
  if (ext == ".mhd" || ext == ".mha") return detail::readMetaImage(path, image, error);
  if (ext == ".nrrd" || ext == ".nhdr") return detail::readNrrd(path, image, error);
  error = "'" + path + "': unknown volume image extension '" + ext +
          "' (expected .mhd, .mha, .nrrd or .nhdr)";
  return false;
}

bool readRawVoxels(const std::string& path, const std::array<int, 3>& size, const Vec3d& spacing,
                   const Vec3d& origin, VolumeImage& image, std::string& error) {
  if (size[0] <= 0 || size[1] <= 0 || size[2] <= 0) {
    error = "raw voxels '" + path + "': empty image (zero voxels): the resolution is " +
            std::to_string(size[0]) + " x " + std::to_string(size[1]) + " x " +
            std::to_string(size[2]);
    return false;
  }
  if (!(spacing.minCoeff() > 0) || !spacing.allFinite()) {
    error = "raw voxels '" + path + "': the voxel size must be > 0 along each axis";
    return false;
  }
  if (double(size[0]) * size[1] * size[2] > detail::kMaxVoxels) {
    error = "raw voxels '" + path + "': " + std::to_string(double(size[0]) * size[1] * size[2]) +
            " voxels is beyond what can be read";
    return false;
  }
  std::string bytes;
  if (!detail::readFileBytes(path, bytes, error)) return false;
  image = VolumeImage{};
  image.size = size;
  image.spacing = spacing;
  image.origin = origin;
  const std::size_t count = image.voxelCount();
  if (bytes.size() < count) {
    error = "raw voxels '" + path + "': size mismatch: the file holds " +
            std::to_string(bytes.size()) + " bytes, expected " + std::to_string(count) + " (" +
            std::to_string(size[0]) + " x " + std::to_string(size[1]) + " x " +
            std::to_string(size[2]) + " 8-bit voxels)";
    return false;
  }
  detail::decodeBinary(detail::SampleType::uint8, false, bytes.data(), count, image.values);
  return true;
}

}  // namespace stroma::image
