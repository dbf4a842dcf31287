// SPDX-License-Identifier: MIT
// A collision step with oriented boxes allocates nothing once warm: their geometry, the GJK/EPA
// contacts (fixed-size buffers), and the penalty responses with lever arms reuse their storage
// while the contacts come and go (counted by replacing operator new in this program; the
// plugin's and Bullet's allocations through new go through it too).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <new>
#include <random>
#include <sstream>

#include "CollisionTestScenes.h"
#include "collision/CollisionPipeline.h"
#include "core/Runtime.h"
#include "core/StateTypes.h"
#include "plugins/TestPlugin/TestSupport.h"
#include "simulation/MechanicalState.h"
#include "simulation/Scene.h"

#include "support/AllocationCounter.h"

namespace stroma::test {
namespace {

TEST(BoxCollisionStep, AllocatesNothingOnceWarm) {
  // Twelve boxes on the frames of one Rigid3d state (against each other: selfCollision), over a
  // bumpy sheet with point, line and triangle models, beside spheres: their frames are moved
  // and turned at random so that contacts of every kind appear and vanish.
  Runtime runtime;
  Scene scene(runtime);
  std::ostringstream frames, extents;
  for (int i = 0; i < 12; ++i) {
    frames << 0.15 + 0.25 * (i % 4) << ' ' << 0.2 + 0.3 * (i / 4) << " 0.12  0 0 0 1  ";
    extents << "0.1 0.08 0.1  ";
  }
  const std::string xml =
      "<Node name=\"root\" dt=\"0.01\" gravity=\"0 0 0\">" +
      collisionPipeline(
          R"(<MinProximityIntersection alarmDistance="0.05" contactDistance="0.01"/>)") +
      surfaceNode("Sheet", sheetAttributes(10, 0.0, 0.03, 7, false)) +
      "<Node name=\"Boxes\"><MechanicalObject template=\"Rigid3d\" position=\"" + frames.str() +
      "\"/><OBBCollisionModel extents=\"" + extents.str() + "\" selfCollision=\"1\"/></Node>"
      "<Node name=\"Balls\"><MechanicalObject position=\"0.3 0.5 0.2  0.7 0.5 0.2\"/>"
      "<SphereCollisionModel radius=\"0.1\"/></Node></Node>";
  ASSERT_TRUE(scene.loadString(xml)) << describe(scene.log());
  auto* phase = scene.root().get<CollisionPhase>();
  Node* boxes = scene.root().children()[1].get();
  auto* state = boxes->get<MechanicalState<Rigid3Types>>();
  const std::vector<RigidCoord3> rest = state->readCoord(VecId::position());
  std::mt19937 random(3);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<std::vector<RigidCoord3>> configurations(10, rest);
  for (auto& c : configurations)
    for (RigidCoord3& x : c) {
      x.center += Vec3d(0.05 * u(random), 0.05 * u(random), 0.05 * u(random));
      x.orientation =
          Quat(Eigen::AngleAxisd(0.6 * u(random), Vec3d(u(random), u(random), 1).normalized()));
    }
  auto run = [&](const std::vector<RigidCoord3>& c) {
    state->writeCoord(VecId::position()) = c;
    phase->computeCollisions(scene.root(), scene.timing());
  };
  for (const auto& c : configurations) run(c);
  long contacts = 0, smallest = 1 << 30, largest = 0;
  for (const auto& c : configurations) {
    g_counting = true;
    run(c);
    g_counting = false;
    long here = 0;
    for (const ModelPairContacts& pair : phase->lastContacts())
      here += static_cast<long>(pair.contacts.size());
    contacts += here;
    smallest = std::min(smallest, here);
    largest = std::max(largest, here);
  }
  EXPECT_LT(smallest, largest) << "the contacts did not change";
  EXPECT_GT(contacts, 100) << "too few contacts to test anything";
  EXPECT_EQ(g_allocations, 0) << "allocations in 10 warm collision steps";
}

}  // namespace
}  // namespace stroma::test
