// SPDX-License-Identifier: MIT
// Reading a material from a volume image: the mean image value over a cell, then the transfer
// functions (TransferFunction.h) from that value to Young's modulus and density.
#pragma once

#include "core/Types.h"
#include "image/VolumeImage.h"

namespace stroma::nonuniform {

/// Mean of the values of the voxels whose centres lie in the box [lower, upper) (grid frame).
/// When no voxel centre does (a cell smaller than a voxel, or outside the image), the value of
/// the voxel nearest to the box's centre.
double meanImageValue(const image::VolumeImage& image, const Vec3d& lower, const Vec3d& upper);

}  // namespace stroma::nonuniform
