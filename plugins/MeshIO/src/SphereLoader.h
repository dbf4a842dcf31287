// SPDX-License-Identifier: MIT
#pragma once

#include <vector>

#include "core/Base.h"
#include "core/Types.h"

namespace stroma {

/// Reads a sphere file (.sph, SOFA's SphereLoader): the centers and radii of the spheres of a
/// SphereCollisionModel (`position="@loader.position"`, `listRadius="@loader.listRadius"`).
/// A DataEngine: the file is read at init and again whenever an input changes.
///
/// The centers are transformed as the mesh loaders transform points: scale (`scale3d` times
/// `scale`), then rotation about x then y then z, then translation. The radii are multiplied by
/// the scale, so that a scaled file gives the same spheres as a file written at that size: a
/// uniform scale s gives radius |s| r; a non-uniform one (an ellipsoid, which a sphere cannot
/// represent) gives the radius of the smallest sphere around the ellipsoid, max |s_i| r, with a
/// warning. SOFA's help text says the scale applies to the radii but its code leaves them
/// unchanged; no SOFA scene sets a scale on a SphereLoader.
class SphereLoader final : public Base, public DataEngine {
 public:
  Data<FileName> d_filename{this,
                            "filename",
                            {},
                            "Sphere file (.sph) to read, relative to the scene's folder or the "
                            "data path.",
                            {.autoLink = false}};
  Data<Vec3d> d_translation{this,
                            "translation",
                            Vec3d::Zero(),
                            "Translation of the centers, applied last.",
                            {.unit = "m", .autoLink = false}};
  Data<Vec3d> d_rotation{this,
                         "rotation",
                         Vec3d::Zero(),
                         "Rotation of the centers, about x then y then z, after the scale.",
                         {.unit = "deg", .autoLink = false}};
  Data<Vec3d> d_scale3d{this,
                        "scale3d",
                        Vec3d::Ones(),
                        "Scale of the centers along x, y and z, and of the radii (by the "
                        "largest of the three).",
                        {.autoLink = false}};
  Data<std::vector<double>> d_scale{
      this,
      "scale",
      {},
      "Uniform scale factor (one number) multiplying scale3d; three numbers scale x, y and z.",
      {.autoLink = false}};

  Data<std::vector<Vec3d>> d_position{this,
                                      "position",
                                      {},
                                      "Centers of the spheres (nbSpheres x 3).",
                                      {.unit = "m", .output = true}};
  Data<std::vector<double>> d_listRadius{
      this, "listRadius", {}, "Radius of each sphere (nbSpheres).", {.unit = "m", .output = true}};

  SphereLoader();

  void init() override;

 protected:
  void doUpdate() override;

 private:
  void clearOutputs();
};

}  // namespace stroma
