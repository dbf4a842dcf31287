// SPDX-License-Identifier: MIT
// The bundled contact scenes (scenes/contact): every solved problem of each meets its laws (no
// penetration beyond the solver's tolerance, forces that push, friction in its cone), and the
// stack of five cubes stays standing for 10 s with the floor carrying the five weights.
#include <gtest/gtest.h>

#include <filesystem>

#include "core/Runtime.h"
#include "core/StateTypes.h"
#include "plugins/TestPlugin/TestSupport.h"
#include "simulation/Constraints.h"
#include "simulation/MechanicalState.h"
#include "simulation/Scene.h"
#include "support/TestNames.h"

namespace stroma::test {
namespace {

namespace fs = std::filesystem;

const fs::path kScenes = fs::path(STROMA_SOURCE_DIR) / "scenes" / "contact";

struct SceneCase {
  const char* what;
  const char* file;
  int steps;
};
void PrintTo(const SceneCase& c, std::ostream* out) { *out << c.what; }

class ContactScene : public ::testing::TestWithParam<SceneCase> {};

TEST_P(ContactScene, EverySolvedProblemMeetsItsLaws) {
  // Each step's problem, checked by lawResiduals (independent of the solver): penetration and
  // complementarity within 1e-6 m (the scenes' tolerances are 1e-9 to 1e-12 per sweep), forces
  // never pulling, friction inside its cone.
  Runtime runtime;
  Scene scene(runtime);
  ASSERT_TRUE(scene.loadFile(kScenes / GetParam().file)) << describe(scene.log());
  const auto* solver = scene.root().get<BaseConstraintSolver>();
  ASSERT_NE(solver, nullptr);
  int solved = 0;
  for (int n = 0; n < GetParam().steps; ++n) {
    ASSERT_TRUE(scene.step()) << "step " << n << '\n' << describe(scene.log());
    const ConstraintProblem* p = solver->lastProblem();
    if (!p || p->groups.empty()) continue;
    ++solved;
    const double scale = std::max(1.0, p->lambda.cwiseAbs().maxCoeff());
    const ConstraintLawResiduals r = lawResiduals(*p);
    ASSERT_LE(r.negativeForce, 0.0) << "step " << n;
    ASSERT_LT(r.penetration, 1e-6) << "step " << n;
    ASSERT_LT(r.complementarity, 1e-6 * scale) << "step " << n;
    ASSERT_LT(r.outsideCone, 1e-9 * scale) << "step " << n;
    ASSERT_LT(r.bilateral, 1e-6) << "step " << n;
  }
  EXPECT_GT(solved, GetParam().steps / 2) << "too few steps with constraints to check";
  EXPECT_EQ(scene.log().count(MessageLevel::warning), 0u) << describe(scene.log());
}

INSTANTIATE_TEST_SUITE_P(Lagrangian, ContactScene,
                         ::testing::Values(SceneCase{"block on a slope", "BlockOnSlope.scn", 500},
                                           SceneCase{"stack of cubes", "CubeStack.scn", 200},
                                           SceneCase{"organ grasped", "OrganGrasped.scn", 150},
                                           SceneCase{"probe sliding on the organ",
                                                     "ProbeSlidingOnOrgan.scn", 160}),
                         NameFromWhat());

TEST(ContactScene, AStackOfFiveCubesStaysStandingForTenSeconds) {
  // 2000 steps of 5 ms: no cube moves more than a millimetre from where it settled after the
  // first 0.2 s, none turns more than a milliradian, and the floor carries the five weights
  // (its constraintForce, the sum of the contact forces on it, is -5 m g).
  Runtime runtime;
  Scene scene(runtime);
  ASSERT_TRUE(scene.loadFile(kScenes / "CubeStack.scn")) << describe(scene.log());
  auto frameOf = [&](int i) -> const RigidCoord3& {
    return scene.root()
        .findChild("Cube" + std::to_string(i))
        ->get<MechanicalState<Rigid3Types>>()
        ->readCoord(VecId::position())[0];
  };
  for (int n = 0; n < 40; ++n) ASSERT_TRUE(scene.step()) << describe(scene.log());
  std::vector<RigidCoord3> settled;
  for (int i = 0; i < 5; ++i) settled.push_back(frameOf(i));
  for (int n = 40; n < 2000; ++n) ASSERT_TRUE(scene.step()) << "step " << n << '\n' << describe(scene.log());
  for (int i = 0; i < 5; ++i) {
    EXPECT_LT((frameOf(i).center - settled[i].center).norm(), 1e-3) << "cube " << i;
    EXPECT_LT(frameOf(i).orientation.angularDistance(settled[i].orientation), 1e-3) << "cube " << i;
    EXPECT_NEAR(frameOf(i).center.y(), 0.1 + 0.2 * i, 1e-3) << "cube " << i;
  }
  const auto& floorForce = scene.root()
                               .findChild("Floor")
                               ->get<MechanicalState<Rigid3Types>>()
                               ->readDeriv(VecId::constraintForce());
  ASSERT_EQ(floorForce.size(), 1u);
  EXPECT_NEAR(floorForce[0].linear.y(), -5 * 9.81, 1e-3 * 5 * 9.81) << floorForce[0].linear.transpose();
}

TEST(ContactScene, GraspingJawsFeelTheTissuePullBack) {
  // The jaws move by an imposed motion (their dofs are fixed in the solve), yet their
  // constraintForce is the force of the tissue on them: the opposite of what the bilateral
  // constraints apply to the organ (Newton's third law, 1e-9 relative), and against the pull
  // (-x, -y) once the lobe is drawn out.
  Runtime runtime;
  Scene scene(runtime);
  ASSERT_TRUE(scene.loadFile(kScenes / "OrganGrasped.scn")) << describe(scene.log());
  for (int n = 0; n < 100; ++n) ASSERT_TRUE(scene.step()) << describe(scene.log());
  Vec3d onJaws = Vec3d::Zero(), onOrgan = Vec3d::Zero();
  for (const char* jaw : {"JawA", "JawB"})
    onJaws += scene.root().findChild(jaw)->get<MechanicalState<Rigid3Types>>()->readDeriv(
        VecId::constraintForce())[0].linear;
  for (const char* grasp : {"graspA", "graspB"})
    for (const Vec3d& f : dynamic_cast<const Data<std::vector<Vec3d>>*>(
                              scene.root().findObject(grasp)->findData("forces"))
                              ->value())
      onOrgan += f;
  EXPECT_LT((onJaws + onOrgan).norm(), 1e-9 * onOrgan.norm()) << onJaws.transpose();
  EXPECT_LT(onJaws.x(), -1.0) << onJaws.transpose();
  EXPECT_LT(onJaws.y(), -1.0) << onJaws.transpose();
}

}  // namespace
}  // namespace stroma::test
