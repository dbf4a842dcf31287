// SPDX-License-Identifier: MIT
#include "BVHNarrowPhase.h"
#include "BruteForceBroadPhase.h"
#include "CollisionPipeline.h"
#include "CollisionResponse.h"
#include "CubeCollisionModel.h"
#include "DiscreteIntersection.h"
#include "LineCollisionModel.h"
#include "LocalMinDistance.h"
#include "MinProximityIntersection.h"
#include "NewProximityIntersection.h"
#include "OBBCollisionModel.h"
#include "PointCollisionModel.h"
#include "SphereCollisionModel.h"
#include "TriangleCollisionModel.h"
#include "core/Plugin.h"

namespace {

void registerComponents(stroma::PluginRegistry& registry) {
  using namespace stroma;
  registry
      .add("CollisionPipeline",
           "The collision step: models, broad and narrow phases, "
           "intersection, response")
      .with<CollisionPipeline>()
      .alias("DefaultPipeline");
  registry.add("BruteForceBroadPhase", "Pairs of collision models whose bounds overlap")
      .with<BruteForceBroadPhase>()
      .alias("BruteForceDetection");
  registry
      .add("BVHNarrowPhase",
           "Pairs of primitives whose boxes overlap, on a Bullet tree "
           "per model")
      .with<BVHNarrowPhase>();
  registry.add("MinProximityIntersection", "Contacts of primitives closer than alarmDistance")
      .with<MinProximityIntersection>();
  registry.add("NewProximityIntersection", "MinProximityIntersection with triangle pairs")
      .with<NewProximityIntersection>();
  registry.add("LocalMinDistance", "Proximity contacts at local minima of the distance only")
      .with<LocalMinDistance>();
  registry.add("DiscreteIntersection", "Contacts of interpenetrating primitives")
      .with<DiscreteIntersection>();
  registry.add("CollisionResponse", "Contacts to responses (penalty forces)")
      .with<CollisionResponse>()
      .alias("DefaultContactManager");
  registry.add("PointCollisionModel", "The points of a state as collision primitives")
      .with<PointCollisionModel>("Vec3d")
      .alias("PointModel");
  registry.add("LineCollisionModel", "The edges of a topology as collision segments")
      .with<LineCollisionModel>("Vec3d")
      .alias("LineModel");
  registry.add("TriangleCollisionModel", "The triangles of a topology as collision primitives")
      .with<TriangleCollisionModel>("Vec3d")
      .alias("TriangleModel");
  registry.add("SphereCollisionModel", "Spheres on the points or frames of a state")
      .with<SphereCollisionModel<Vec3Types>>("Vec3d")
      .with<SphereCollisionModel<Rigid3Types>>("Rigid3d")
      .alias("SphereModel");
  registry
      .add("OBBCollisionModel",
           "Oriented boxes on the frames of a Rigid3d state (extents, defaultExtent), their "
           "contacts by GJK/EPA")
      .with<OBBCollisionModel>("Rigid3d")
      .alias("OBBModel");
  registry
      .add("CubeCollisionModel",
           "Accepted for SOFA's scenes, adds no primitive: SOFA's bounding-volume hierarchy of "
           "a model, which here is BVHNarrowPhase's Bullet tree")
      .with<CubeCollisionModel>()
      .alias("CubeModel");
}

}  // namespace

extern "C" STROMA_PLUGIN_EXPORT const stroma::PluginEntry* stroma_plugin_entry() {
  static const stroma::PluginEntry entry = stroma::makePluginEntry(
      "Collision", "0.1.0", "Collision detection on Bullet and penalty contact",
      registerComponents);
  return &entry;
}
