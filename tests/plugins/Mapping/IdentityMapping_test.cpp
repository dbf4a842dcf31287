// SPDX-License-Identifier: MIT
// IdentityMapping: J = I for points and rigid frames; the output takes the input's size and
// state; forces on the output act on the input as if applied there; SOFA's scene forms (input
// "@..", a visual output, "Vec3,Vec3" and deduced templates) load.
#include "plugins/Mapping/MappingChecks.h"

namespace stroma::test {
namespace {

using PointMapping = Mapping<Vec3Types, Vec3Types>;
using FrameMapping = Mapping<Rigid3Types, Rigid3Types>;

TEST(IdentityMapping, PointsAreCopiedAndJIsTheIdentity) {
  Runtime runtime;
  Scene scene(runtime);
  ASSERT_TRUE(scene.loadString(R"(<Node name="root">
      <MechanicalObject name="dofs" position="0 0 0  1 2 3  -1 0.5 2" velocity="1 0 0  0 1 0  0 0 1"/>
      <Node name="Mapped">
        <MechanicalObject name="copy"/>
        <IdentityMapping template="Vec3,Vec3" input="@.." output="@."/>
      </Node>
    </Node>)"))
      << problems(scene.log());
  EXPECT_EQ(problems(scene.log()), "");
  auto* mapping = findInScene<PointMapping>(scene.root());
  ASSERT_NE(mapping, nullptr);
  EXPECT_EQ(mapping->templateName(), "Vec3d,Vec3d");
  // The output was empty: it now has the input's points, velocities and rest shape.
  const auto& out = *mapping->output();
  ASSERT_EQ(out.size(), 3u);
  EXPECT_EQ(out.readCoord(VecId::position())[1], Vec3d(1, 2, 3));
  EXPECT_EQ(out.readCoord(VecId::restPosition())[2], Vec3d(-1, 0.5, 2));
  EXPECT_EQ(out.readDeriv(VecId::velocity())[2], Vec3d(0, 0, 1));
  expectConsistentMapping(*mapping);
  const Eigen::MatrixXd J = mapping->jacobian();
  EXPECT_TRUE(J.isIdentity(0.0));
}

TEST(IdentityMapping, RigidFramesAreCopiedWithTheirOrientation) {
  Runtime runtime;
  Scene scene(runtime);
  // No template on the mapping: deduced from the Rigid3d state beside it.
  ASSERT_TRUE(scene.loadString(R"(<Node name="root">
      <MechanicalObject template="Rigid3" name="frames"
          position="0 0 0  0.2 0.3 0.1 0.927362  1 2 3  0 0.6 0 0.8"/>
      <Node name="Mapped">
        <MechanicalObject template="Rigid3" name="copy"/>
        <IdentityMapping/>
      </Node>
    </Node>)"))
      << problems(scene.log());
  EXPECT_EQ(problems(scene.log()), "");
  auto* mapping = findInScene<FrameMapping>(scene.root());
  ASSERT_NE(mapping, nullptr);
  EXPECT_EQ(mapping->templateName(), "Rigid3d,Rigid3d");
  ASSERT_EQ(mapping->output()->size(), 2u);
  const RigidCoord3& second = mapping->output()->readCoord(VecId::position())[1];
  EXPECT_EQ(second.center, Vec3d(1, 2, 3));
  EXPECT_TRUE(second.orientation.coeffs().isApprox(Vec4d(0, 0.6, 0, 0.8)));
  expectConsistentMapping(*mapping);
}

/// Points with a mass, integrated by backward Euler; the load is either on the points or on an
/// identity-mapped copy of them.
std::string loadedScene(bool loadOnTheCopy) {
  const std::string load = R"(<ConstantForceField indices="0 2" forces="1 2 3  -4 0 1"/>)";
  return R"(<Node name="root" gravity="0 -9.81 0" dt="0.01">
      <EulerImplicitSolver rayleighMass="0" rayleighStiffness="0"/>
      <CGLinearSolver iterations="100" tolerance="1e-14" threshold="1e-30"/>
      <MechanicalObject name="dofs" position="0 0 0  1 0 0  0 1 0"/>
      <UniformMass totalMass="3"/>
      )" +
         (loadOnTheCopy ? "" : load) + R"(
      <Node name="Mapped">
        <MechanicalObject name="copy"/>
        <IdentityMapping input="@../dofs" output="@copy"/>
        )" +
         (loadOnTheCopy ? load : "") + R"(
      </Node>
    </Node>)";
}

TEST(IdentityMapping, AForceOnTheOutputMovesTheInputAsTheSameForceOnIt) {
  Runtime runtime;
  Scene mapped(runtime), direct(runtime);
  ASSERT_TRUE(mapped.loadString(loadedScene(true))) << problems(mapped.log());
  ASSERT_TRUE(direct.loadString(loadedScene(false))) << problems(direct.log());
  for (int i = 0; i < 10; ++i) ASSERT_TRUE(mapped.step() && direct.step());
  const auto a = positionsAt(mapped, "/root/dofs"), b = positionsAt(direct, "/root/dofs");
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t k = 0; k < a.size(); ++k) EXPECT_NEAR(a[k], b[k], 1e-12) << k;
  // The copy follows: it is where the points are.
  EXPECT_EQ(positionsAt(mapped, "/root/Mapped/copy"), a);
  // And it moved: 10 steps of an accelerated fall.
  EXPECT_LT(a[1], -0.04);
}

TEST(IdentityMapping, MapsToAVisualModelWithoutCostInBatchRuns) {
  Runtime runtime;
  Scene scene(runtime);
  // SOFA's TutorialMappingCubeSurface form: a visual output named by link.
  ASSERT_TRUE(scene.loadString(R"(<Node name="root" dt="0.01">
      <EulerImplicitSolver/>
      <CGLinearSolver/>
      <MechanicalObject name="Particles" position="0 0 1  1 0 1  0 1 1"/>
      <UniformMass totalMass="1"/>
      <Node name="Visual">
        <OglModel name="Surface" color="red"/>
        <IdentityMapping input="@../Particles" output="@Surface"/>
      </Node>
    </Node>)"))
      << problems(scene.log());
  auto* mapping = findInScene<PointMapping>(scene.root());
  ASSERT_NE(mapping, nullptr);
  EXPECT_EQ(mapping->output(), nullptr);
  EXPECT_NE(mapping->visualOutput(), nullptr);
  EXPECT_EQ(mapping->toState(), nullptr);  // not part of the mechanical system
  for (int i = 0; i < 3; ++i) ASSERT_TRUE(scene.step());
  EXPECT_EQ(problems(scene.log()), "");
}

TEST(IdentityMapping, ReportsAMissingOrWrongInput) {
  Runtime runtime;
  Scene scene(runtime);
  EXPECT_FALSE(scene.loadString(R"(<Node name="root">
      <Node name="Mapped">
        <MechanicalObject name="copy"/>
        <IdentityMapping/>
      </Node>
    </Node>)"));
  EXPECT_NE(problems(scene.log()).find("no mechanical state of template Vec3d in the parent"),
            std::string::npos)
      << problems(scene.log());

  Scene wrong(runtime);
  EXPECT_FALSE(wrong.loadString(R"(<Node name="root">
      <MechanicalObject template="Rigid3" name="frames" position="0 0 0 0 0 0 1"/>
      <Node name="Mapped">
        <MechanicalObject name="copy"/>
        <IdentityMapping input="@../frames"/>
      </Node>
    </Node>)"));
  EXPECT_NE(problems(wrong.log())
                .find("/root/frames is a MechanicalObject Rigid3d, not a "
                      "mechanical state of template Vec3d"),
            std::string::npos)
      << problems(wrong.log());
}

}  // namespace
}  // namespace stroma::test
