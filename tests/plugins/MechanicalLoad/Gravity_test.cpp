// SPDX-License-Identifier: MIT
// Gravity (SOFA's context object): bodies in its node and below fall with its acceleration
// (v = n h g after n backward Euler steps, no other force), a node below with its own gravity
// keeps it, and a non-finite value is an error naming the field.
#include <gtest/gtest.h>

#include "plugins/Spring/MechanicsTestSupport.h"

namespace stroma::test {
namespace {

std::string body(const std::string& name, const std::string& nodeAttributes = "") {
  return "<Node name=\"" + name + "\" " + nodeAttributes + R"(>
    <EulerImplicitSolver/><CGLinearSolver iterations="10" tolerance="1e-14" threshold="0"/>
    <MechanicalObject name="dofs" position="0 0 0"/>
    <UniformMass vertexMass="2"/>
  </Node>)";
}

TEST(Gravity, SetsTheGravityOfItsNodeAndTheNodesBelow) {
  SceneHolder s;
  ASSERT_TRUE(s.load(R"(<Node name="root" dt="0.01">
  <Gravity gravity="1 -3 2"/>)" + body("inherits") + body("own", "gravity=\"0 0 -5\"") +
                     "</Node>"));
  ASSERT_TRUE(s.step(10));
  const auto v = numbers(s.text("@inherits/dofs.velocity"));
  ASSERT_EQ(v.size(), 3u);
  EXPECT_NEAR(v[0], 10 * 0.01 * 1, 1e-13);
  EXPECT_NEAR(v[1], 10 * 0.01 * -3, 1e-13);
  EXPECT_NEAR(v[2], 10 * 0.01 * 2, 1e-13);
  const auto w = numbers(s.text("@own/dofs.velocity"));
  ASSERT_EQ(w.size(), 3u);
  EXPECT_NEAR(w[0], 0, 1e-15);
  EXPECT_NEAR(w[2], 10 * 0.01 * -5, 1e-13);
}

TEST(Gravity, NonFiniteValueIsAnError) {
  SceneHolder s;
  s.loadFailing(R"(<Node name="root"><Gravity gravity="0 nan 0"/></Node>)", {"finite"});
}

}  // namespace
}  // namespace stroma::test
