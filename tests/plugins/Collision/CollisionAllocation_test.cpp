// SPDX-License-Identifier: MIT
// The collision step allocates nothing once warm: models, trees (refitted), model pairs,
// contacts and penalty responses reuse their storage from step to step while the contacts
// come and go (counted by replacing operator new in this program; the plugin's allocations go
// through it too).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <new>
#include <random>

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

TEST(CollisionStep, AllocatesNothingOnceWarm) {
  // Two bumpy sheets whose points are moved by up to 1 cm, so that contacts appear and vanish
  // (every kind of MinProximityIntersection's pairs, self-collision included).
  Runtime runtime;
  Scene scene(runtime);
  const std::string xml =
      "<Node name=\"root\" dt=\"0.01\" gravity=\"0 0 0\">" +
      collisionPipeline(
          R"(<MinProximityIntersection alarmDistance="0.05" contactDistance="0.01"/>)") +
      surfaceNode("Lower", sheetAttributes(10, 0.0, 0.03, 7, false), "selfCollision=\"1\"") +
      surfaceNode("Upper", sheetAttributes(10, 0.06, 0.03, 11, true), "selfCollision=\"1\"") +
      "</Node>";
  ASSERT_TRUE(scene.loadString(xml)) << describe(scene.log());
  auto* phase = scene.root().get<CollisionPhase>();
  std::vector<MechanicalState<Vec3Types>*> states;
  for (const auto& child : scene.root().children())
    states.push_back(child->get<MechanicalState<Vec3Types>>());
  std::vector<std::vector<Vec3d>> rest;
  for (auto* s : states) rest.push_back(s->readCoord(VecId::position()));
  // Ten configurations, run once to warm up, then again counting: between two of them the
  // contacts change (pairs appear and vanish, counts go up and down).
  std::mt19937 random(1);
  std::uniform_real_distribution<double> u(-0.01, 0.01);
  std::vector<std::vector<std::vector<Vec3d>>> configurations(10, rest);
  for (auto& c : configurations)
    for (auto& points : c)
      for (Vec3d& x : points) x += Vec3d(u(random), u(random), u(random));
  auto run = [&](const std::vector<std::vector<Vec3d>>& c) {
    for (std::size_t k = 0; k < states.size(); ++k) states[k]->writeCoord(VecId::position()) = c[k];
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
