// SPDX-License-Identifier: MIT
// MechanicalObject's size: as SOFA, a state that nothing sizes has one degree of freedom at the
// origin (a rigid body's frame in SOFA's scenes), and anything that sizes it wins: positions,
// size, the points of a topology; rest positions alone still need their positions.
#include <gtest/gtest.h>

#include "core/Node.h"
#include "core/Runtime.h"
#include "plugins/TestPlugin/TestSupport.h"
#include "simulation/MechanicalState.h"
#include "simulation/Scene.h"

namespace stroma::test {
namespace {

std::vector<double> positionsOf(const BaseMechanicalState& state) {
  std::vector<double> x;
  state.copyPositions(x);
  return x;
}

struct Loaded {
  Runtime runtime;
  Scene scene{runtime};
  bool ok;
  explicit Loaded(const std::string& xml) : ok(scene.loadString(xml)) {}
  const BaseMechanicalState& state(const std::string& name = "dofs") {
    auto* s = dynamic_cast<const BaseMechanicalState*>(scene.root().findObject(name));
    EXPECT_NE(s, nullptr) << name;
    return *s;
  }
};

TEST(MechanicalObject, GivenNothingHasOneDegreeOfFreedomAtTheOrigin) {
  Loaded points(R"(<Node name="root"><MechanicalObject name="dofs"/></Node>)");
  ASSERT_TRUE(points.ok) << describe(points.scene.log());
  ASSERT_EQ(points.state().size(), 1u);
  EXPECT_EQ(positionsOf(points.state()), (std::vector<double>{0, 0, 0}));

  Loaded frame(R"(<Node name="root"><MechanicalObject name="dofs" template="Rigid3d"/></Node>)");
  ASSERT_TRUE(frame.ok) << describe(frame.scene.log());
  ASSERT_EQ(frame.state().size(), 1u);
  EXPECT_EQ(positionsOf(frame.state()), (std::vector<double>{0, 0, 0, 0, 0, 0, 1}));
  EXPECT_EQ(frame.scene.log().count(MessageLevel::warning), 0u) << describe(frame.scene.log());
}

TEST(MechanicalObject, WhatSizesItWins) {
  const char* cases[][2] = {
      {R"(<MechanicalObject name="dofs" position="1 2 3  4 5 6"/>)", "2"},
      {R"(<MechanicalObject name="dofs" position=""/>)", "0"},
      {R"(<MechanicalObject name="dofs" size="3"/>)", "3"},
      {R"(<MechanicalObject name="dofs" size="0"/>)", "0"},
      {R"(<RegularGridTopology n="2 2 3" min="0 0 0" max="1 1 1"/>
          <MechanicalObject name="dofs"/>)",
       "12"}};
  for (const auto& [object, size] : cases) {
    Loaded s(std::string(R"(<Node name="root">)") + object + "</Node>");
    ASSERT_TRUE(s.ok) << object << "\n" << describe(s.scene.log());
    EXPECT_EQ(std::to_string(s.state().size()), size) << object;
  }
  // Rest positions alone do not make a default state: they still need their positions.
  Loaded rest(R"(<Node name="root"><MechanicalObject name="dofs" rest_position="1 0 0  2 0 0"/>
      </Node>)");
  EXPECT_FALSE(rest.ok);
  EXPECT_NE(describe(rest.scene.log()).find("'rest_position': has 2 values for 0 positions"),
            std::string::npos)
      << describe(rest.scene.log());
}

// SOFA's rigid bodies: a frame given nothing and a surface mapped on it (BuiltConstraint-
// Correction.scn, AdvancedResponseConstraintBased.scn): the frame falls and carries the points.
TEST(MechanicalObject, ARigidFrameGivenNothingCarriesItsMappedPoints) {
  Loaded s(R"(<Node name="root" dt="0.01" gravity="0 -10 0">
      <Node name="Body">
        <EulerImplicitSolver/> <CGLinearSolver iterations="25" tolerance="1e-12" threshold="1e-20"/>
        <MechanicalObject name="dofs" template="Rigid3d"/>
        <UniformMass totalMass="2"/>
        <Node name="Surface">
          <MechanicalObject name="points" position="1 0 0  0 1 0"/>
          <RigidMapping/>
        </Node>
      </Node>
    </Node>)");
  ASSERT_TRUE(s.ok) << describe(s.scene.log());
  for (int n = 0; n < 10; ++n) ASSERT_TRUE(s.scene.step()) << describe(s.scene.log());
  const auto* points = dynamic_cast<const BaseMechanicalState*>(
      s.scene.root().findChild("Body")->findChild("Surface")->findObject("points"));
  ASSERT_NE(points, nullptr);
  const std::vector<double> x = positionsOf(*points);
  ASSERT_EQ(x.size(), 6u);
  EXPECT_LT(x[1], -0.05);  // fell
  EXPECT_NEAR(x[0], 1, 1e-12);
  EXPECT_NEAR(x[4] - x[1], 1, 1e-12);  // and kept its shape
  EXPECT_EQ(s.scene.log().errorCount(), 0u) << describe(s.scene.log());
}

}  // namespace
}  // namespace stroma::test
