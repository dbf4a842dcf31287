// SPDX-License-Identifier: MIT
// A sparse hexahedral grid from a volume image (Nesme 2008, seed 001, ch. 3 sec. 1: "the
// voxels of a segmented image tell directly which cells are full, empty or at the boundary").
//
// The voxels are boxes (image/VolumeImage.h: voxel (i, j, k) is the box of size `spacing`
// centred at origin + (i, j, k) * spacing); those selected as inside (a threshold or a list of
// labels) fill their box, the others and everything outside the image are empty. Each cell of
// the grid's box is then
// - empty when no inside voxel overlaps it with a positive volume (it is dropped),
// - full when it lies inside the image and every voxel overlapping it is inside,
// - boundary otherwise, with its filled fraction = (volume of its intersection with the inside
//   voxels) / (cell volume), computed exactly: the intersection of two axis-aligned boxes is the
//   product of three interval overlaps, so the filled volume of every cell is the separable sum
//   sum_ijk Wx(ci, i) Wy(cj, j) Wz(ck, k) inside(i, j, k), done one axis at a time.
// The total filled volume (full cells + fractions x cell volume) is the volume of the inside
// voxels within the box, to round-off. An overlap shorter than 1e-9 of the smaller of the voxel
// and cell sizes counts as none (its length goes to the voxel's neighbouring piece), so that a
// grid aligned with the voxels does not see rounding slivers.
//
// Numbering of the kept cells and points: as buildSparseGrid (SparseGrid.h): boundary cells then
// full cells, each in increasing cell index.
//
// Cost: each voxel is visited once per axis pass (times the cells it overlaps along that axis);
// measured in ImageGrid_test. Memory: estimateImageBuildBytes().
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "image/VolumeImage.h"
#include "topology/SparseGridLevels.h"

namespace stroma::sparsegrid {

/// Which voxels are inside: those whose value is one of `labels` when labels are given, else
/// those >= `threshold` when it is given, else those > 0.
struct VoxelSelection {
  std::vector<double> labels;
  std::optional<double> threshold;

  bool inside(double value) const;
  /// "voxel >= 0.5", "voxel > 0", "voxel with label 2 or 5": for messages.
  std::string describe() const;
};

/// 1 per inside voxel, 0 per other one (image order).
std::vector<std::uint8_t> selectVoxels(const image::VolumeImage& image,
                                       const VoxelSelection& selection);

/// About how many bytes buildSparseGridFromVoxels() allocates for `image` on a box of `cells`
/// cells per axis (reals, so that a huge request is estimated, not wrapped).
double estimateImageBuildBytes(const image::VolumeImage& image, const std::array<double, 3>& cells);

/// Classifies the cells of `box` by the inside voxels (`inside`: image.voxelCount() flags, as
/// selectVoxels gives) and keeps the non-empty ones (see the file comment). Returns false with
/// `error` for a bad box, a flag count that does not match the image, or when no inside voxel
/// overlaps the box.
bool buildSparseGridFromVoxels(const image::VolumeImage& image,
                               const std::vector<std::uint8_t>& inside, const GridBox& box,
                               SparseGrid& grid, std::string& error);

}  // namespace stroma::sparsegrid
