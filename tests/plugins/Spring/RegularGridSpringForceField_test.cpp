// SPDX-License-Identifier: MIT
// RegularGridSpringForceField: the spring count of an nx x ny x nz grid against its closed form,
// which pairs are joined, stiffness and damping per unit length, SOFA's forces on a deformed
// cell, elastic and damping (measured with runSofa), the generic force-field test, and bad input.
#include <gtest/gtest.h>

#include "plugins/Spring/MechanicsTestSupport.h"
#include "support/ForceFieldTest.h"

namespace stroma::test {
namespace {

std::string gridScene(const std::string& n, const std::string& max, const std::string& field,
                      const std::string& position = "@grid.position") {
  return R"(<Node name="root" gravity="0 0 0">
  <RegularGridTopology name="grid" n=")" +
         n + R"(" min="0 0 0" max=")" + max + R"("/>
  <MechanicalObject name="dofs" position=")" +
         position + R"("/>
  )" + field +
         R"(
</Node>)";
}

std::size_t springCount(SceneHolder& s) { return numbers(s.text("@springs.spring")).size() / 5; }

TEST(RegularGridSpringForceField, SpringCountIsTheClosedForm) {
  for (const auto& [nx, ny, nz] : {std::array{4, 3, 2}, std::array{2, 2, 2}, std::array{5, 3, 1},
                                   std::array{6, 1, 1}, std::array{3, 3, 3}}) {
    const std::size_t lines = (nx - 1) * ny * nz + nx * (ny - 1) * nz + nx * ny * (nz - 1);
    const std::size_t faces =
        (nx - 1) * (ny - 1) * nz + (nx - 1) * ny * (nz - 1) + nx * (ny - 1) * (nz - 1);
    const std::size_t cells = (nx - 1) * (ny - 1) * (nz - 1);
    const std::string n = std::to_string(nx) + " " + std::to_string(ny) + " " + std::to_string(nz);
    SceneHolder all, linesOnly, facesOnly;
    ASSERT_TRUE(
        all.load(gridScene(n, "3 2 1", R"(<RegularGridSpringForceField name="springs"/>)")));
    EXPECT_EQ(springCount(all), lines + 2 * faces + 4 * cells) << n;
    ASSERT_TRUE(linesOnly.load(gridScene(n, "3 2 1", R"(<RegularGridSpringForceField
        name="springs" quadsStiffness="0" quadsDamping="0" cubesStiffness="0"
        cubesDamping="0"/>)")));
    EXPECT_EQ(springCount(linesOnly), lines) << n;
    ASSERT_TRUE(facesOnly.load(gridScene(n, "3 2 1", R"(<RegularGridSpringForceField
        name="springs" linesStiffness="0" linesDamping="0" cubesStiffness="0"
        cubesDamping="0"/>)")));
    EXPECT_EQ(springCount(facesOnly), 2 * faces) << n;
  }
}

TEST(RegularGridSpringForceField, StiffnessAndDampingArePerUnitLength) {
  SceneHolder s;
  ASSERT_TRUE(s.load(gridScene("2 2 2", "2 3 4", R"(<RegularGridSpringForceField
      name="springs" stiffness="60" damping="12"/>)")));
  const auto v = numbers(s.text("@springs.spring"));
  ASSERT_EQ(v.size(), (12u + 12 + 4) * 5);
  for (std::size_t k = 0; k < v.size(); k += 5) {
    EXPECT_NEAR(v[k + 2] * v[k + 4], 60, 1e-12);
    EXPECT_NEAR(v[k + 3] * v[k + 4], 12, 1e-12);
  }
  // The cell diagonals (the last 4) are sqrt(4 + 9 + 16) long.
  EXPECT_NEAR(v[v.size() - 1], std::sqrt(29.0), 1e-12);
}

// SOFA (runSofa, one explicit step of unit masses and dt = 1 from rest velocities) on the cell
// [0,2]x[0,3]x[0,4] with points 0, 3 and 6 moved: the force on each point.
TEST(RegularGridSpringForceField, MatchesSofaOnADeformedCell) {
  SceneHolder s;
  ASSERT_TRUE(s.load(gridScene("2 2 2", "2 3 4",
                               R"(<RegularGridSpringForceField name="springs" stiffness="100"/>)",
                               "0 0 0.1  2 0 0  0 3 0  2.2 3 0   0 0 4  2 0 4  0 3 4.1  2 3 4"),
                     true));  // a warning-free scene
  ForceFieldChecker check(s.scene(), s.root());
  const Eigen::VectorXd f = check.force();
  // clang-format off
  const double sofa[24] = {0.600034, 1.8745, -5.37669,  -0.618048, 0.983556, 1.04774,
                           10, -0.0555093, 2.50185,     -14.417, -3.65277, 4.89084,
                           0.579113, 0.845209, 1.44892, 0.892179, 0.079926, 1.71224,
                           2.56586, -0.849565, -7.11341, 0.397907, 0.774653, 0.888521};
  // clang-format on
  // SOFA prints 6 significant digits.
  for (int i = 0; i < 24; ++i) EXPECT_NEAR(f[i], sofa[i], 5e-6 * std::abs(sofa[i]) + 1e-9) << i;
}

TEST(RegularGridSpringForceField, DampsAlongTheSpringsAsSofa) {
  // SOFA (runSofa, as above) on a deformed cell with random velocities, damping only.
  SceneHolder s;
  ASSERT_TRUE(s.load(gridScene("2 2 2", "2 3 4", R"(<RegularGridSpringForceField name="springs"
      linesStiffness="0" quadsStiffness="0" cubesStiffness="0" damping="10"/>)",
                               "-0.157 0.027 -0.078  2.062 0.075 -0.261  -0.292 3.202 -0.144 "
                               "1.841 3.297 -0.018  0.202 -0.014 4.083  1.790 0.081 4.221 "
                               "0.014 3.145 4.103  1.738 3.155 4.055")));
  // clang-format off
  const double v[24] = {-0.397, -0.938, 0.731, -0.055, 0.438, 0.758, 0.428, 0.842, -0.210,
                        0.602, -0.111, 0.871, 0.758, -0.805, -0.728, -0.566, 0.931, -0.128,
                        0.253, -0.398, 0.014, -0.228, -0.298, 0.170};
  // SOFA's velocities after one step of unit masses and dt = 1: v + f.
  const double sofa[24] = {1.89193, 7.61473, -4.92568, 0.688898, -3.62016, -7.83189,
                           1.64333, -5.39092, 1.15806, -1.18558, 1.59721, -5.44797,
                           -6.8182, 0.0889779, 5.72861, 8.29692, -8.66487, 7.30319,
                           -5.60462, 3.23259, 2.61989, 1.88232, 4.80344, 2.87379};
  // clang-format on
  std::string velocity;
  for (double c : v) velocity += std::to_string(c) + " ";
  s.set("@dofs.velocity", velocity);
  ForceFieldChecker check(s.scene(), s.root());
  const Eigen::VectorXd f = check.force();
  for (int i = 0; i < 24; ++i)
    EXPECT_NEAR(v[i] + f[i], sofa[i], 5e-6 * std::abs(sofa[i]) + 1e-9) << i;
}

TEST(RegularGridSpringForceField, PassesTheForceFieldTest) {
  checkForceField(gridScene("3 2 2", "2 1 1.5", R"(<RegularGridSpringForceField name="springs"
      linesStiffness="150" quadsStiffness="80" cubesStiffness="40" damping="0"/>)"),
                  {.rotationInvariant = true});
}

TEST(RegularGridSpringForceField, PassesTheForceFieldTestWithDamping) {
  checkForceField(gridScene("2 3 1", "1 2 0", R"(<RegularGridSpringForceField name="springs"
      stiffness="120" damping="3"/>)"),
                  {.rotationInvariant = true});
}

TEST(RegularGridSpringForceField, BadInputIsReported) {
  {
    SceneHolder s;
    EXPECT_EQ(s.loadFailing(R"(<Node><MechanicalObject position="0 0 0"/>
<RegularGridSpringForceField/></Node>)",
                            {"needs a topology"})
                  .field,
              "topology");
  }
  {
    SceneHolder s;
    EXPECT_EQ(s.loadFailing(gridScene("2 2 2", "1 1 1",
                                      R"(<RegularGridSpringForceField linesStiffness="-1"/>)"),
                            {})
                  .field,
              "linesStiffness");
  }
  {
    SceneHolder s;
    EXPECT_EQ(s.loadFailing(gridScene("3 3 3", "1 1 1", "<RegularGridSpringForceField/>",
                                      "0 0 0  1 0 0  0 1 0"),
                            {"out of range"})
                  .field,
              "topology");
  }
}

TEST(RegularGridSpringForceField, CommonStiffnessReplacingAKindsOwnIsAWarning) {
  SceneHolder s;
  ASSERT_TRUE(s.load(gridScene("2 2 2", "1 1 1", R"(<RegularGridSpringForceField name="springs"
      stiffness="100" linesStiffness="50"/>)"),
                     true));
  bool warned = false;
  for (const Message& m : s.scene().log().messages())
    warned |= m.level == MessageLevel::warning && m.field == "linesStiffness";
  EXPECT_TRUE(warned);
  const auto v = numbers(s.text("@springs.spring"));
  EXPECT_NEAR(v[2] * v[4], 100, 1e-12);  // SOFA's rule: the common value wins
}

}  // namespace
}  // namespace stroma::test
