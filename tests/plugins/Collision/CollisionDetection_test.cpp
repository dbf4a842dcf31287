// SPDX-License-Identifier: MIT
// Collision detection (plugins/Collision) is exact: the contacts the pipeline finds through its
// trees (Bullet's btDbvt, refitted as the surfaces deform) are those of testing every pair of
// primitives of every pair of models, and a refitted tree finds what a rebuilt one does.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <map>
#include <random>
#include <tuple>

#include "CollisionTestScenes.h"
#include "collision/CollisionPipeline.h"
#include "core/Runtime.h"
#include "core/StateTypes.h"
#include "plugins/TestPlugin/TestSupport.h"
#include "simulation/MechanicalState.h"
#include "simulation/Scene.h"

namespace stroma::test {
namespace {

// A contact as a comparable record: the two model paths and primitives in a fixed order, with
// where each point is on its primitive (a pair of triangles may touch at several features),
// mapped to the gap.
using Weights = std::array<double, 3>;
using ContactKey =
    std::tuple<std::string, std::uint32_t, Weights, std::string, std::uint32_t, Weights>;

void addContacts(std::map<ContactKey, double>& out, const CollisionModel& a,
                 const CollisionModel& b, const std::vector<Contact>& contacts) {
  auto w = [](const Vec3d& v) { return Weights{v[0], v[1], v[2]}; };
  for (const Contact& c : contacts) {
    ContactKey key{a.path(), c.primitive[0], w(c.weights[0]),
                   b.path(), c.primitive[1], w(c.weights[1])};
    if (b.path() < a.path())
      key = {b.path(), c.primitive[1], w(c.weights[1]), a.path(), c.primitive[0], w(c.weights[0])};
    EXPECT_EQ(out.count(key), 0u) << "a pair of primitives reported twice";
    out[key] = c.distance;
  }
}

std::vector<CollisionModel*> modelsOf(Node& node) {
  std::vector<CollisionModel*> models;
  for (const auto& o : node.objects())
    if (auto* m = dynamic_cast<CollisionModel*>(o.get())) models.push_back(m);
  for (const auto& c : node.children()) {
    auto below = modelsOf(*c);
    models.insert(models.end(), below.begin(), below.end());
  }
  return models;
}

// Every pair of primitives of every pair of models that may collide, through the scene's own
// intersection method: the O(n^2) reference.
std::map<ContactKey, double> bruteForceContacts(Scene& scene) {
  const auto* pipeline = scene.root().get<CollisionPhase>();
  const Intersection& intersection = *pipeline->intersection();
  std::vector<CollisionModel*> models = modelsOf(scene.root());
  std::map<ContactKey, double> out;
  std::vector<PrimitivePair> all;
  std::vector<Contact> contacts;
  for (std::size_t i = 0; i < models.size(); ++i)
    for (std::size_t j = i; j < models.size(); ++j) {
      CollisionModel &a = *models[i], &b = *models[j];
      if (!a.canCollideWith(b)) continue;
      if (!intersection.supports(a.geometry().kind, b.geometry().kind)) continue;
      all.clear();
      const auto na = static_cast<std::uint32_t>(a.geometry().primitiveCount());
      const auto nb = static_cast<std::uint32_t>(b.geometry().primitiveCount());
      for (std::uint32_t p = 0; p < na; ++p)
        for (std::uint32_t q = (&a == &b ? p + 1 : 0); q < nb; ++q) all.push_back({p, q});
      contacts.clear();
      intersection.intersect(a, b, all, contacts);
      addContacts(out, a, b, contacts);
    }
  return out;
}

std::map<ContactKey, double> pipelineContacts(Scene& scene) {
  std::map<ContactKey, double> out;
  for (const ModelPairContacts& pair : scene.root().get<CollisionPhase>()->lastContacts())
    addContacts(out, *pair.first, *pair.second, pair.contacts);
  return out;
}

void expectSameContacts(const std::map<ContactKey, double>& found,
                        const std::map<ContactKey, double>& expected, const std::string& what) {
  EXPECT_EQ(found.size(), expected.size()) << what;
  for (const auto& [key, gap] : expected) {
    auto it = found.find(key);
    if (it == found.end()) {
      ADD_FAILURE() << what << ": missing " << std::get<0>(key) << " #" << std::get<1>(key) << " - "
                    << std::get<3>(key) << " #" << std::get<4>(key) << " (gap " << gap << ")";
      continue;
    }
    EXPECT_EQ(it->second, gap) << what;  // the same test on the same pair: bit for bit
  }
}

// Moves every point of the scene's states by a random amount (a deforming surface).
void deform(Scene& scene, std::mt19937& random, double amount) {
  std::uniform_real_distribution<double> u(-amount, amount);
  for (CollisionModel* m : modelsOf(scene.root()))
    if (auto* s = dynamic_cast<MechanicalState<Vec3Types>*>(m->state()))
      for (Vec3d& x : s->writeCoord(VecId::position())) x += Vec3d(u(random), u(random), u(random));
}

std::string twoSheets(const std::string& intersection, const std::string& narrowPhase,
                      bool selfCollision) {
  const std::string self = selfCollision ? "selfCollision=\"1\"" : "";
  return "<Node name=\"root\" dt=\"0.01\" gravity=\"0 0 0\">" +
         collisionPipeline(intersection, narrowPhase) +
         surfaceNode("Lower", sheetAttributes(12, 0.0, 0.03, 7, false), self) +
         surfaceNode("Upper", sheetAttributes(12, 0.06, 0.03, 11, true), self) + "</Node>";
}

class ExactDetection : public ::testing::TestWithParam<std::string> {};

TEST_P(ExactDetection, PipelineContactsAreThoseOfEveryPairOnDeformingSheets) {
  // Two bumpy 12 x 12 sheets 0.06 apart, +-0.03 bumps, alarm distance 0.05: a few hundred
  // contacts of every kind; then 10 steps moving every point by up to 0.02 (refits).
  for (const bool self : {false, true}) {
    Runtime runtime;
    Scene scene(runtime);
    ASSERT_TRUE(scene.loadString(twoSheets(GetParam(), "<BVHNarrowPhase/>", self)))
        << describe(scene.log());
    std::mt19937 random(3);
    std::size_t total = 0;
    for (int step = 0; step < 10; ++step) {
      ASSERT_TRUE(scene.step()) << describe(scene.log());
      const auto expected = bruteForceContacts(scene);
      total += expected.size();
      expectSameContacts(pipelineContacts(scene), expected,
                         "step " + std::to_string(step) + (self ? " (self)" : ""));
      deform(scene, random, 0.02);
    }
    EXPECT_GT(total, 300u) << "too few contacts to test anything";
  }
}

TEST_P(ExactDetection, RefittedTreesFindWhatRebuiltTreesFind) {
  // The same deformations in two scenes: trees refitted for 30 steps, and rebuilt every step.
  Runtime runtime;
  Scene refitted(runtime), rebuilt(runtime);
  ASSERT_TRUE(
      refitted.loadString(twoSheets(GetParam(), "<BVHNarrowPhase rebuildInterval=\"0\"/>", true)))
      << describe(refitted.log());
  ASSERT_TRUE(
      rebuilt.loadString(twoSheets(GetParam(), "<BVHNarrowPhase rebuildInterval=\"1\"/>", true)))
      << describe(rebuilt.log());
  std::mt19937 r1(5), r2(5);
  for (int step = 0; step < 30; ++step) {
    ASSERT_TRUE(refitted.step());
    ASSERT_TRUE(rebuilt.step());
    expectSameContacts(pipelineContacts(refitted), pipelineContacts(rebuilt),
                       "step " + std::to_string(step));
    deform(refitted, r1, 0.03);
    deform(rebuilt, r2, 0.03);
  }
}

INSTANTIATE_TEST_SUITE_P(
    Collision, ExactDetection,
    ::testing::Values("<MinProximityIntersection alarmDistance=\"0.05\" contactDistance=\"0.01\"/>",
                      "<NewProximityIntersection alarmDistance=\"0.05\" contactDistance=\"0.01\"/>",
                      "<LocalMinDistance alarmDistance=\"0.05\" contactDistance=\"0.01\"/>"),
    [](const auto& info) {
      const std::string& xml = info.param;
      return xml.substr(1, xml.find(' ') - 1);
    });

}  // namespace
}  // namespace stroma::test
