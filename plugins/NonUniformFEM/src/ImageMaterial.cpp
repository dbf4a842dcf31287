// SPDX-License-Identifier: MIT
#include "ImageMaterial.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace stroma::nonuniform {

double meanImageValue(const image::VolumeImage& image, const Vec3d& lower, const Vec3d& upper) {
  // Voxel i is centred at origin + i spacing: the centres in [lower, upper) are the i with
  // ceil((lower - origin) / spacing) <= i < ceil((upper - origin) / spacing).
  std::array<int, 3> first{}, last{};
  for (int a = 0; a < 3; ++a) {
    const double lo = std::ceil((lower[a] - image.origin[a]) / image.spacing[a]);
    const double hi = std::ceil((upper[a] - image.origin[a]) / image.spacing[a]);
    first[a] = int(std::clamp(lo, 0.0, double(image.size[a])));
    last[a] = int(std::clamp(hi, 0.0, double(image.size[a])));
  }
  double sum = 0;
  std::size_t count = 0;
  for (int k = first[2]; k < last[2]; ++k)
    for (int j = first[1]; j < last[1]; ++j)
      for (int i = first[0]; i < last[0]; ++i) {
        sum += image.at(i, j, k);
        ++count;
      }
  if (count > 0) return sum / double(count);
  std::array<int, 3> nearest{};
  const Vec3d centre = 0.5 * (lower + upper);
  for (int a = 0; a < 3; ++a)
    nearest[a] = int(std::clamp(std::round((centre[a] - image.origin[a]) / image.spacing[a]), 0.0,
                                double(image.size[a] - 1)));
  return image.at(nearest[0], nearest[1], nearest[2]);
}

}  // namespace stroma::nonuniform
