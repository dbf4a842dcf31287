// SPDX-License-Identifier: MIT
// RegularGridSpringForceField: the spring count of an nx x ny x nz grid against its closed form,
// which pairs are joined, stiffness and damping per unit length, SOFA's forces on a deformed
// cell (measured with runSofa), the generic force-field test, and bad input.
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

TEST(RegularGridSpringForceField, DampsTheWholeRelativeVelocity) {
  // As SOFA: point 0 of a resting cell moving at (0, 0, 0.1) pulls each neighbour j with
  // (damping / L_0j) (0, 0, 0.1), whatever the spring's direction.
  SceneHolder s;
  ASSERT_TRUE(s.load(gridScene("2 2 2", "2 3 4", R"(<RegularGridSpringForceField
      name="springs" linesStiffness="0" quadsStiffness="0" cubesStiffness="0"/>)")));
  s.set("@dofs.velocity", "0 0 0.1  0 0 0  0 0 0  0 0 0  0 0 0  0 0 0  0 0 0  0 0 0");
  ForceFieldChecker check(s.scene(), s.root());
  const Eigen::VectorXd f = check.force();
  // Neighbour 1 at (2, 0, 0): an x line spring, default damping 5 per unit length.
  EXPECT_NEAR(f[5], 5 * 0.1 / 2, 1e-14);
  EXPECT_NEAR(f[3 * 4 + 2], 5 * 0.1 / 4, 1e-14);                // (0, 0, 4)
  EXPECT_NEAR(f[3 * 7 + 2], 5 * 0.1 / std::sqrt(29.0), 1e-14);  // the opposite corner
  EXPECT_NEAR(f.sum(), 0, 1e-14);
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
