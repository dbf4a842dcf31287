// SPDX-License-Identifier: MIT
#include "SphereLoader.h"

#include <cmath>
#include <filesystem>

#include "formats/MeshProcessing.h"
#include "formats/SphereData.h"

namespace stroma {

SphereLoader::SphereLoader() {
  for (BaseData* input : std::initializer_list<BaseData*>{&d_filename, &d_translation, &d_rotation,
                                                          &d_scale3d, &d_scale})
    addInput(input);
  addOutput(&d_position);
  addOutput(&d_listRadius);
}

void SphereLoader::init() {
  // Read now, so that a bad file is reported by this loader even when nothing links to it.
  d_position.value();
}

void SphereLoader::clearOutputs() {
  d_position.setValue({});
  d_listRadius.setValue({});
}

void SphereLoader::doUpdate() {
  const FileName& file = d_filename.value();
  if (file.original.empty()) {
    msgError("no file given: set filename to a sphere file (.sph)", "filename");
    clearOutputs();
    return;
  }
  // The scale, checked before the file is read.
  Vec3d scale3d = d_scale3d.value();
  const std::vector<double>& scale = d_scale.value();
  if (scale.size() == 1) {
    scale3d *= scale[0];
  } else if (scale.size() == 3) {
    scale3d = scale3d.cwiseProduct(Vec3d(scale[0], scale[1], scale[2]));
  } else if (!scale.empty()) {
    msgError("expected one number (or three), got " + std::to_string(scale.size()), "scale");
    clearOutputs();
    return;
  }

  // A file the scene named but the scene loader could not find is already reported there.
  std::error_code ec;
  if (file.resolved.empty() && !sourceLocation().file.empty() &&
      !std::filesystem::exists(file.original, ec)) {
    setInvalid();
    clearOutputs();
    return;
  }
  SphereData spheres;
  std::string error;
  if (!readSphereFile(file.path(), spheres, error)) {
    msgError("cannot read sphere file '" + file.path() + "': " + error, "filename");
    clearOutputs();
    return;
  }

  // Centers: p -> R (s .* p) + t, as the mesh loaders. Radii: times the largest |s_i|.
  const Eigen::Matrix4d transform =
      makeTransform(scale3d, d_rotation.value(), d_translation.value());
  if (transform != Eigen::Matrix4d::Identity()) {
    const Mat3d linear = transform.topLeftCorner<3, 3>();
    const Vec3d shift = transform.topRightCorner<3, 1>();
    for (Vec3d& c : spheres.centers) c = linear * c + shift;
  }
  const Vec3d magnitude = scale3d.cwiseAbs();
  const double radiusScale = magnitude.maxCoeff();
  if (radiusScale - magnitude.minCoeff() > 1e-12 * radiusScale)
    msgWarning("a non-uniform scale (" + std::to_string(scale3d.x()) + ", " +
                   std::to_string(scale3d.y()) + ", " + std::to_string(scale3d.z()) +
                   ") turns spheres into ellipsoids: the radii are scaled by the largest "
                   "factor, " +
                   std::to_string(radiusScale) + ", so that each sphere covers its ellipsoid",
               scale.empty() ? "scale3d" : "scale");
  if (radiusScale != 1.0)
    for (double& r : spheres.radii) r *= radiusScale;

  d_position.setValue(std::move(spheres.centers));
  d_listRadius.setValue(std::move(spheres.radii));
}

}  // namespace stroma
