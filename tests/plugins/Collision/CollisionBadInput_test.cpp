// SPDX-License-Identifier: MIT
// Bad input to the collision components: each is an error naming the component and the field,
// and the scene does not load. Also: the Collision plugin registers exactly the components its
// components.txt names (what a build without Bullet lists as unavailable).
#include <gtest/gtest.h>

#include <fstream>
#include <set>

#include "CollisionTestScenes.h"
#include "collision/CollisionModel.h"
#include "core/PluginManager.h"
#include "core/Runtime.h"
#include "plugins/TestPlugin/TestSupport.h"
#include "simulation/Scene.h"
#include "support/TestNames.h"

namespace stroma::test {
namespace {

struct BadCollisionInput {
  const char* what;
  std::string xml;    ///< inside the root node, after a valid pipeline
  const char* path;   ///< the component the error names
  const char* field;  ///< the field it names ("" for none)
  const char* text;   ///< part of the error
};
void PrintTo(const BadCollisionInput& c, std::ostream* out) { *out << c.what; }

const std::string kPipeline = collisionPipeline("<MinProximityIntersection/>");

class CollisionBadInput : public ::testing::TestWithParam<BadCollisionInput> {};

TEST_P(CollisionBadInput, IsAnErrorNamingTheComponentAndField) {
  const BadCollisionInput& c = GetParam();
  Runtime runtime;
  Scene scene(runtime);
  EXPECT_FALSE(scene.loadString("<Node name=\"root\">" + c.xml + "</Node>"));
  EXPECT_TRUE(hasError(scene.log(), c.path, c.field, c.text))
      << c.what << ":\n" << describe(scene.log());
}

INSTANTIATE_TEST_SUITE_P(
    Collision, CollisionBadInput,
    ::testing::Values(
        BadCollisionInput{
            "a model without a state",
            kPipeline + "<Node name=\"A\"><PointCollisionModel name=\"points\"/></Node>",
            "/root/A/points", "", "needs a mechanical state of template Vec3d"},
        BadCollisionInput{"a triangle model without triangles",
                          kPipeline +
                              "<Node name=\"A\"><MechanicalObject position=\"0 0 0 1 0 0\"/>"
                              "<MeshTopology edges=\"0 1\"/>"
                              "<TriangleCollisionModel name=\"triangles\"/></Node>",
                          "/root/A/triangles", "topology", "needs triangles"},
        BadCollisionInput{"a line model without a topology",
                          kPipeline + "<Node name=\"A\"><MechanicalObject position=\"0 0 0\"/>"
                                      "<LineCollisionModel name=\"lines\"/></Node>",
                          "/root/A/lines", "topology", "needs edges"},
        BadCollisionInput{"a triangle index past the points",
                          kPipeline +
                              "<Node name=\"A\"><MechanicalObject position=\"0 0 0 1 0 0\"/>"
                              "<MeshTopology triangles=\"0 1 5\"/>"
                              "<TriangleCollisionModel name=\"triangles\"/></Node>",
                          "/root/A/triangles", "", "triangle 0 uses point 5"},
        BadCollisionInput{"alarmDistance below contactDistance",
                          collisionPipeline("<MinProximityIntersection name=\"proximity\" "
                                            "alarmDistance=\"0.1\" contactDistance=\"0.2\"/>"),
                          "/root/proximity", "alarmDistance", "is above alarmDistance"},
        BadCollisionInput{"a negative radius",
                          kPipeline +
                              "<Node name=\"A\"><MechanicalObject position=\"0 0 0\"/>"
                              "<SphereCollisionModel name=\"spheres\" radius=\"-1\"/></Node>",
                          "/root/A/spheres", "radius", ">= 0"},
        BadCollisionInput{
            "an unknown response",
            "<CollisionPipeline/><BruteForceBroadPhase/><BVHNarrowPhase/>"
            "<MinProximityIntersection/>"
            "<CollisionResponse name=\"response\" response=\"PenaltyContactForceField\"/>",
            "/root/response", "response",
            "unknown response 'PenaltyContactForceField'; did you mean "
            "'PenalityContactForceField'?"},
        BadCollisionInput{
            "a constraint response without FreeMotionAnimationLoop",
            "<CollisionPipeline/><BruteForceBroadPhase/><BVHNarrowPhase/>"
            "<MinProximityIntersection/>"
            "<CollisionResponse name=\"response\" response=\"FrictionContactConstraint\"/>",
            "/root/response", "response", "which only FreeMotionAnimationLoop solves"},
        BadCollisionInput{"a pipeline without its phases", "<CollisionPipeline name=\"pipeline\"/>",
                          "/root/pipeline", "",
                          "needs, in its node /root, a broad phase (BruteForceBroadPhase), an "
                          "intersection method"}),
    NameFromWhat());

TEST(CollisionBadInput, ARadiusListOfTheWrongLengthIsAWarningAndCompletedAsInSofa) {
  // SOFA pads a short listRadius with `radius` (Tutorials/Mappings/TutorialMappingLiverBarycentric
  // has 34 radii for 181 points): a warning, and the run goes on.
  Runtime runtime;
  Scene scene(runtime);
  ASSERT_TRUE(scene.loadString("<Node name=\"root\">" + kPipeline +
                               "<Node name=\"A\"><MechanicalObject position=\"0 0 0 1 0 0\"/>"
                               "<SphereCollisionModel name=\"spheres\" radius=\"0.5\" "
                               "listRadius=\"2\"/></Node></Node>"))
      << describe(scene.log());
  bool warned = false;
  for (const Message& m : scene.log().messages())
    warned |=
        m.level == MessageLevel::warning && m.componentPath == "/root/A/spheres" &&
        m.field == "listRadius" &&
        m.text.find(
            "has 1 radii for the 2 points of /root/A/mechanicalObject: the others take radius "
            "0.5") != std::string::npos;
  EXPECT_TRUE(warned) << describe(scene.log());
  const auto* model =
      dynamic_cast<const CollisionModel*>(scene.root().children().front()->findObject("spheres"));
  ASSERT_NE(model, nullptr);
  ASSERT_EQ(model->geometry().radii.size(), 2u);
  EXPECT_EQ(model->geometry().radii[0], 2.0);
  EXPECT_EQ(model->geometry().radii[1], 0.5);
}

TEST(CollisionPlugin, RegistersExactlyTheComponentsOfItsList) {
  std::ifstream list(std::string(STROMA_SOURCE_DIR) + "/plugins/Collision/components.txt");
  ASSERT_TRUE(list) << "plugins/Collision/components.txt";
  std::set<std::string> listed, registered;
  for (std::string line; std::getline(list, line);)
    if (!line.empty() && line[0] != '#') listed.insert(line);
  Runtime runtime;
  std::string error;
  ASSERT_TRUE(runtime.plugins().load("Collision", error)) << error;
  for (const PluginIndexEntry& entry : runtime.plugins().available())
    if (entry.name == "Collision")
      registered.insert(entry.components.begin(), entry.components.end());
  EXPECT_EQ(listed, registered);
}

TEST(CollisionPlugin, AComponentOfAPluginLeftOutSaysWhatToInstall) {
  // The index a build without Bullet writes (stroma_add_unavailable_plugin).
  TempDir dir;
  dir.write("Collision.stroma-plugin",
            "plugin Collision\nunavailable it needs Bullet (the Debian package libbullet-dev)\n"
            "component CollisionPipeline\n");
  Runtime runtime;
  runtime.plugins().setSearchPath({dir.path()});
  Scene scene(runtime);
  EXPECT_FALSE(scene.loadString("<Node name=\"root\"><CollisionPipeline name=\"p\"/></Node>"));
  const Message m = findError(scene.log(), "CollisionPipeline");
  EXPECT_NE(m.text.find("is in plugin Collision, which this build left out: it needs Bullet (the "
                        "Debian package libbullet-dev)"),
            std::string::npos)
      << describe(scene.log());
}

}  // namespace
}  // namespace stroma::test
