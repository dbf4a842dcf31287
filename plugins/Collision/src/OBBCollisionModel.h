// SPDX-License-Identifier: MIT
#pragma once

#include <vector>

#include "ModelSupport.h"
#include "core/StateTypes.h"

namespace stroma {

/// Oriented boxes on rigid frames (SOFA's OBBCollisionModel, template Rigid3d): one box per frame
/// of the node's Rigid3d state (or the nearest above), centred on the frame's origin and turned
/// with it, of half extents `extents` along the frame's x, y and z axes. A box without an entry
/// in `extents` takes `defaultExtent` on every axis (as SOFA completes the list); a list of
/// another length than the frames is warned about. The extents are read at init.
///
/// Its contacts come from GJK/EPA against boxes, spheres, points, segments and triangles
/// (BoxIntersection.h); the penalty response applies each contact force at its point on the box,
/// so off the frame's origin it also gives a torque.
class OBBCollisionModel final : public CollisionModel {
 public:
  Data<std::vector<Vec3d>> d_extents{this,
                                     "extents",
                                     {},
                                     "Half extents of each box along its frame's x, y and z axes "
                                     "(nbFrames x 3); empty: defaultExtent for every box.",
                                     {.unit = "m", .min = 0.0}};
  Data<double> d_defaultExtent{this,
                               "defaultExtent",
                               1.0,
                               "Half extent on each axis of the boxes that extents leaves out.",
                               {.unit = "m", .min = 0.0}};

  void init() override;
  void reinit() override { init(); }
  BaseMechanicalState* state() const override { return m_state; }
  void updateGeometry() override;

 private:
  MechanicalState<Rigid3Types>* m_state = nullptr;
  std::vector<Vec3d> m_halfExtents;  // one per frame
  std::vector<Vec3d> m_centers;
  std::vector<OrientedBox> m_boxes;
};

}  // namespace stroma
