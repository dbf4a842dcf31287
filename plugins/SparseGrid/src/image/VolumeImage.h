// SPDX-License-Identifier: MIT
// A scalar volume image (a regular 3D grid of samples, one value per voxel) and its readers:
// MetaImage (.mhd with a separate data file, .mha with local data) and NRRD (.nrrd with
// attached data, .nhdr with a detached data file), and SOFA's headerless 8-bit .raw files.
// The SparseGrid plugin builds grids from them (ImageGrid.h); the non-uniform elements read
// per-voxel material values from them.
//
// Geometry (the convention of both formats): `origin` is the centre of voxel (0, 0, 0), voxel
// (i, j, k) is centred at origin + (i sx, j sy, k sz), and a voxel is the box of size `spacing`
// around its centre. So the image covers origin - spacing/2 to origin + (size - 1/2) spacing.
// Only axis-aligned images are accepted; an axis given with a negative direction (NRRD
// "space directions" (-1,0,0), MetaImage TransformMatrix -1 on the diagonal) is flipped on
// reading so that `spacing` is always positive and the voxels keep their place in space.
//
// Values are converted to double, whatever the stored type (exact for every type up to 32-bit
// integers and for float and double; 64-bit integers above 2^53 are rounded).
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "core/Types.h"

namespace stroma::image {

struct VolumeImage {
  std::array<int, 3> size{0, 0, 0};  ///< voxels along x, y and z
  Vec3d spacing = Vec3d::Ones();     ///< voxel size along x, y and z (> 0)
  Vec3d origin = Vec3d::Zero();      ///< centre of voxel (0, 0, 0)
  std::vector<double> values;        ///< size[0] size[1] size[2] values, x fastest, then y, then z

  std::size_t voxelCount() const { return std::size_t(size[0]) * size[1] * size[2]; }
  std::size_t index(int i, int j, int k) const {
    return std::size_t(i) + std::size_t(size[0]) * (std::size_t(j) + std::size_t(size[1]) * k);
  }
  double at(int i, int j, int k) const { return values[index(i, j, k)]; }
  double& at(int i, int j, int k) { return values[index(i, j, k)]; }
  Vec3d voxelCenter(int i, int j, int k) const {
    return origin + Vec3d(i, j, k).cwiseProduct(spacing);
  }
  /// Lower and upper corners of the box covered by the voxels.
  Vec3d lowerCorner() const { return origin - 0.5 * spacing; }
  Vec3d upperCorner() const {
    return origin + (Vec3d(size[0], size[1], size[2]) - Vec3d::Constant(0.5)).cwiseProduct(spacing);
  }
};

/// True when `path` ends with an extension readVolumeImage() reads (.mhd, .mha, .nrrd, .nhdr;
/// case-insensitive).
bool isVolumeImageFile(const std::string& path);

/// Reads a MetaImage or NRRD file, choosing the format by the extension. Returns false with
/// `error` naming the file, the header line and the field for: an unreadable or missing header or
/// data file, an unknown field value or element type, a dimension other than 2 or 3 (2 is read as
/// one slice), more than one channel, a non axis-aligned orientation, an unsupported encoding,
/// fewer data bytes than the header announces (expected vs found), zero voxels.
bool readVolumeImage(const std::string& path, VolumeImage& image, std::string& error);

/// Reads a headerless file of `size` 8-bit unsigned voxels (x fastest), as SOFA's
/// SparseGridTopology reads `.raw` with `dataResolution` and `voxelSize`. The voxel (0,0,0) is
/// centred at `origin`. Bytes after the image are ignored; too few bytes is an error.
bool readRawVoxels(const std::string& path, const std::array<int, 3>& size, const Vec3d& spacing,
                   const Vec3d& origin, VolumeImage& image, std::string& error);

}  // namespace stroma::image
