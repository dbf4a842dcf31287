// SPDX-License-Identifier: MIT
// The placement Data every mesh loader component has (MeshLoader and its formats,
// MeshAssimpLoader): scale, then rotation about x then y then z, then translation, or a whole
// 4x4 matrix; and flipNormals.
#pragma once

#include <string>
#include <vector>

#include "core/Base.h"
#include "core/Data.h"
#include "formats/MeshProcessing.h"

namespace stroma {

/// The placement Data, as Data of the loader that holds this struct.
struct LoaderTransform {
  explicit LoaderTransform(Base* owner)
      : translation{owner,
                    "translation",
                    Vec3d::Zero(),
                    "Translation of the points, applied last.",
                    {.unit = "m", .autoLink = false}},
        rotation{owner,
                 "rotation",
                 Vec3d::Zero(),
                 "Rotation of the points, about x then y then z, after the scale.",
                 {.unit = "deg", .autoLink = false}},
        scale3d{owner, "scale3d", Vec3d::Ones(), "Scale of the points along x, y and z.",
                {.autoLink = false}},
        scale{owner,
              "scale",
              {},
              "Uniform scale factor (one number) multiplying scale3d; three numbers scale x, y "
              "and z.",
              {.autoLink = false}},
        transformation{owner,
                       "transformation",
                       {},
                       "4x4 homogeneous matrix, row by row (16 numbers); when given, it "
                       "replaces translation, rotation and scale.",
                       {.autoLink = false}},
        flipNormals{owner,
                    "flipNormals",
                    false,
                    "Reverse the orientation of triangles and quads, and the normals.",
                    {.autoLink = false}} {}

  Data<Vec3d> translation;
  Data<Vec3d> rotation;
  Data<Vec3d> scale3d;
  Data<std::vector<double>> scale;
  Data<std::vector<double>> transformation;
  Data<bool> flipNormals;

  /// The 4x4 transform these Data give. False after reporting, as an error of `owner` naming
  /// the field, a matrix that is not 16 numbers or a scale that is not one or three.
  bool matrix(Base& owner, Eigen::Matrix4d& transform) const {
    const std::vector<double>& m = transformation.value();
    if (!m.empty()) {
      if (m.size() != 16) {
        owner.msgError(
            "expected 16 numbers (a 4x4 matrix, row by row), got " + std::to_string(m.size()),
            "transformation");
        return false;
      }
      for (std::size_t i = 0; i < 16; ++i) transform(i / 4, i % 4) = m[i];
      return true;
    }
    const std::vector<double>& s = scale.value();
    Vec3d factors = scale3d.value();
    if (s.size() == 1) {
      factors *= s[0];
    } else if (s.size() == 3) {
      factors = factors.cwiseProduct(Vec3d(s[0], s[1], s[2]));
    } else if (!s.empty()) {
      owner.msgError("expected one number (or three), got " + std::to_string(s.size()),
                     "scale");
      return false;
    }
    transform = makeTransform(factors, rotation.value(), translation.value());
    return true;
  }
};

}  // namespace stroma
