// SPDX-License-Identifier: MIT
// SubsetMapping: J selects points; the three ways of choosing them (indices, first..last, by
// position); forces on the subset act on the chosen input points; the J^T K J of springs on a
// subset; bad input is reported with the values.
#include "plugins/Mapping/MappingChecks.h"
#include "support/TestSprings.h"

namespace stroma::test {
namespace {

using PointMapping = Mapping<Vec3Types, Vec3Types>;

const char* kPoints = "0 0 0  1 0 0  0 1 0  0 0 1  1 1 1";

std::string subsetScene(const std::string& mappingAttributes,
                        const std::string& outputAttributes = "") {
  return std::string(R"(<Node name="root">
      <MechanicalObject name="dofs" position=")") +
         kPoints + R"("/>
      <Node name="Subset">
        <MechanicalObject name="subset" )" +
         outputAttributes + R"(/>
        <SubsetMapping )" +
         mappingAttributes + R"(/>
      </Node>
    </Node>)";
}

TEST(SubsetMapping, IndicesSelectPointsAndJSelectsRows) {
  Runtime runtime;
  Scene scene(runtime);
  ASSERT_TRUE(scene.loadString(subsetScene(R"(indices="3 0 4 0")"))) << problems(scene.log());
  EXPECT_EQ(problems(scene.log()), "");
  auto* mapping = findInScene<PointMapping>(scene.root());
  ASSERT_NE(mapping, nullptr);
  const auto& x = mapping->output()->readCoord(VecId::position());
  ASSERT_EQ(x.size(), 4u);
  EXPECT_EQ(x[0], Vec3d(0, 0, 1));
  EXPECT_EQ(x[1], Vec3d(0, 0, 0));
  EXPECT_EQ(x[2], Vec3d(1, 1, 1));
  expectConsistentMapping(*mapping);
  // J^T of a repeated index adds both forces to the point.
  std::vector<Vec3d> in(5, Vec3d::Zero());
  mapping->applyJT(in, {Vec3d(1, 0, 0), Vec3d(0, 2, 0), Vec3d(0, 0, 3), Vec3d(0, 5, 0)});
  EXPECT_EQ(in[0], Vec3d(0, 7, 0));
  EXPECT_EQ(in[3], Vec3d(1, 0, 0));
  EXPECT_EQ(in[1], Vec3d::Zero());
}

TEST(SubsetMapping, FirstAndLastSelectARange) {
  Runtime runtime;
  Scene scene(runtime);
  ASSERT_TRUE(scene.loadString(subsetScene(R"(first="1" last="3")"))) << problems(scene.log());
  auto* mapping = findInScene<PointMapping>(scene.root());
  ASSERT_NE(mapping, nullptr);
  const auto& x = mapping->output()->readCoord(VecId::position());
  ASSERT_EQ(x.size(), 3u);
  EXPECT_EQ(x[0], Vec3d(1, 0, 0));
  EXPECT_EQ(x[2], Vec3d(0, 0, 1));
}

TEST(SubsetMapping, WithoutIndicesOutputPointsAreMatchedByPosition) {
  Runtime runtime;
  Scene scene(runtime);
  ASSERT_TRUE(scene.loadString(subsetScene(R"(radius="0.01")", R"(position="1 1 1.005  0 1 0")")))
      << problems(scene.log());
  auto* mapping = findInScene<PointMapping>(scene.root());
  ASSERT_NE(mapping, nullptr);
  EXPECT_EQ(mapping->findData("indices")->valueText(), "4 2");

  Scene far(runtime);
  EXPECT_FALSE(far.loadString(subsetScene("", R"(position="1 1 1.005  0 1 0  7 7 7")")));
  EXPECT_NE(problems(far.log()).find("2 of the 3 output points (the first is 0) have no input "
                                     "point within radius=1e-05"),
            std::string::npos)
      << problems(far.log());
}

TEST(SubsetMapping, ReportsIndicesOutOfRange) {
  Runtime runtime;
  Scene scene(runtime);
  EXPECT_FALSE(scene.loadString(subsetScene(R"(indices="1 5 9")")));
  const std::string log = problems(scene.log());
  EXPECT_NE(log.find("indices out of range of the 5 input points: 5 9"), std::string::npos) << log;
  EXPECT_NE(log.find("indices"), std::string::npos) << log;
}

std::string loadedScene(bool loadOnTheSubset) {
  // Forces on subset points 0 and 1, that is input points 3 and 1.
  const std::string onSubset = R"(<ConstantForceField indices="0 1" forces="1 2 3  -4 0 1"/>)";
  const std::string onInput = R"(<ConstantForceField indices="3 1" forces="1 2 3  -4 0 1"/>)";
  return std::string(R"(<Node name="root" gravity="0 0 -1" dt="0.02">
      <EulerImplicitSolver/>
      <CGLinearSolver iterations="100" tolerance="1e-14" threshold="1e-30"/>
      <MechanicalObject name="dofs" position=")") +
         kPoints + R"("/>
      <UniformMass vertexMass="0.5"/>
      )" +
         (loadOnTheSubset ? "" : onInput) + R"(
      <Node name="Subset">
        <MechanicalObject name="subset"/>
        <SubsetMapping indices="3 1"/>
        )" +
         (loadOnTheSubset ? onSubset : "") + R"(
      </Node>
    </Node>)";
}

TEST(SubsetMapping, AForceOnTheSubsetMovesItsInputPointAsTheSameForceOnIt) {
  Runtime runtime;
  Scene mapped(runtime), direct(runtime);
  ASSERT_TRUE(mapped.loadString(loadedScene(true))) << problems(mapped.log());
  ASSERT_TRUE(direct.loadString(loadedScene(false))) << problems(direct.log());
  for (int i = 0; i < 10; ++i) ASSERT_TRUE(mapped.step() && direct.step());
  const auto a = positionsAt(mapped, "/root/dofs"), b = positionsAt(direct, "/root/dofs");
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t k = 0; k < a.size(); ++k) EXPECT_NEAR(a[k], b[k], 1e-12) << k;
  // Point 3 got (1, 2, 3) N on 0.5 kg plus gravity for 0.2 s: x = x0 + a t (t + h) / 2 with
  // backward Euler (v_n = n h a, x_n = h^2 a n (n + 1) / 2).
  const double t = 0.2, h = 0.02;
  EXPECT_NEAR(a[3 * 3 + 0], 0 + 2.0 * t * (t + h) / 2, 1e-12);
  EXPECT_NEAR(a[3 * 3 + 2], 1 + (6.0 - 1) * t * (t + h) / 2, 1e-12);
}

TEST(SubsetMapping, SpringsOnTheSubsetAssembleAsJTKJ) {
  Runtime runtime;
  runtime.factory().add("TestSprings", "test").with<CorrectSprings>();
  Scene scene(runtime);
  // Springs between subset points; the input points are moved off the springs' rest shape.
  ASSERT_TRUE(scene.loadString(R"(<Node name="root">
      <MechanicalObject name="dofs" position="0 0 0  1 0 0  0 1 0  0 0 1  1 1 1"
                        rest_position="0 0 0  1 0 0  0 1 0  0 0 1  1 1 1"/>
      <UniformMass vertexMass="0.5"/>
      <FixedProjectiveConstraint indices="2"/>
      <Node name="Subset">
        <MechanicalObject name="subset"/>
        <SubsetMapping indices="4 1 3 2"/>
        <UniformMass vertexMass="0.25"/>
        <TestSprings stiffness="50" edges="0 1  1 2  2 3  0 2  0 3"/>
      </Node>
    </Node>)"))
      << problems(scene.log());
  // Move the input away from the rest shape so that the springs pull.
  auto* mapping = findInScene<PointMapping>(scene.root());
  auto& x = mapping->input()->writeCoord(VecId::position());
  x[4] += Vec3d(0.1, -0.2, 0.05);
  x[1] += Vec3d(-0.05, 0.1, 0.1);
  const SystemCheckReport r = measureSystem(scene, 2.0, -0.3, true);
  EXPECT_LT(r.assembled, 1e-14);
  // A linear mapping: the mapped stiffness is exactly J^T K J.
  EXPECT_LT(r.stiffness, 1e-7);
}

}  // namespace
}  // namespace stroma::test
