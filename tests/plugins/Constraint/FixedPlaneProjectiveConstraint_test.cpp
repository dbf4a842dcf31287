// SPDX-License-Identifier: MIT
// FixedPlaneProjectiveConstraint: the points between dmin and dmax along the direction are
// selected; they fall with gravity minus its component along the direction, the others with
// gravity; the assembled path agrees for an axis direction; bad input is reported.
#include <gtest/gtest.h>

#include "plugins/Spring/MechanicsTestSupport.h"
#include "simulation/ProjectiveConstraint.h"

namespace stroma::test {
namespace {

std::string scene(const std::string& solver, const std::string& constraint) {
  return R"(<Node name="root" gravity="1 -10 2" dt="0.01">)" + solver + R"(
  <MechanicalObject name="dofs" position="0 0 -1  0 0 0  0 1 0.5  0 0 2"/>
  <UniformMass vertexMass="1"/>
  )" + constraint +
         "\n</Node>";
}

Vec3d point(const std::vector<double>& x, int i) { return {x[3 * i], x[3 * i + 1], x[3 * i + 2]}; }

// Backward Euler from rest under a constant acceleration a.
Vec3d fallen(const Vec3d& x0, const Vec3d& a, int n, double h = 0.01) {
  return x0 + h * h * n * (n + 1) / 2.0 * a;
}

void expectSlabFalls(SceneHolder& s, const Vec3d& d) {
  const Vec3d g(1, -10, 2);
  EXPECT_EQ(s.text("@c.indices"), "1 2");  // d.x in [-0.5, 1]: the points at z = 0 and 0.5
  ASSERT_TRUE(s.step(10));
  const auto x = numbers(s.text("@dofs.position"));
  const std::vector<Vec3d> x0{{0, 0, -1}, {0, 0, 0}, {0, 1, 0.5}, {0, 0, 2}};
  for (int i : {1, 2}) {
    EXPECT_LT((point(x, i) - fallen(x0[i], g - d.dot(g) * d, 10)).norm(), 1e-12) << i;
    EXPECT_NEAR(d.dot(point(x, i)), d.dot(x0[i]), 1e-14) << i;  // no displacement along d
  }
  for (int i : {0, 3}) EXPECT_LT((point(x, i) - fallen(x0[i], g, 10)).norm(), 1e-12) << i;
}

TEST(FixedPlaneProjectiveConstraint, SelectedPointsKeepTheirCoordinateAlongTheDirection) {
  SceneHolder s;
  ASSERT_TRUE(s.load(scene(R"(
  <EulerImplicitSolver rayleighMass="0" rayleighStiffness="0"/>
  <CGLinearSolver iterations="100" tolerance="1e-14" threshold="0"/>)",
                           R"(<FixedPlaneProjectiveConstraint name="c" direction="0 0 2"
      dmin="-0.5" dmax="1"/>)")));
  expectSlabFalls(s, Vec3d(0, 0, 1));
}

TEST(FixedPlaneProjectiveConstraint, AssembledSolveAgreesForAnAxisDirection) {
  SceneHolder s;
  ASSERT_TRUE(s.load(scene(R"(
  <EulerImplicitSolver rayleighMass="0" rayleighStiffness="0"/>
  <SparseLDLSolver/>)",
                           R"(<FixedPlaneProjectiveConstraint name="c" direction="0 0 1"
      dmin="-0.5" dmax="1"/>)")));
  expectSlabFalls(s, Vec3d(0, 0, 1));
  std::vector<std::size_t> rows;
  s.get<BaseProjectiveConstraint>("@c")->fixedRows(rows);
  EXPECT_EQ(rows, (std::vector<std::size_t>{5, 8}));
}

TEST(FixedPlaneProjectiveConstraint, GivenIndicesAndAnObliqueDirection) {
  const Vec3d g(1, -10, 2), d = Vec3d(0, 3, 4) / 5;
  SceneHolder s;
  ASSERT_TRUE(s.load(scene(R"(
  <EulerImplicitSolver rayleighMass="0" rayleighStiffness="0"/>
  <CGLinearSolver iterations="100" tolerance="1e-14" threshold="0"/>)",
                           R"(<FixedPlaneProjectiveConstraint name="c" indices="3"
      direction="0 3 4"/>)")));
  ASSERT_TRUE(s.step(10));
  const auto x = numbers(s.text("@dofs.position"));
  EXPECT_LT((point(x, 3) - fallen(Vec3d(0, 0, 2), g - d.dot(g) * d, 10)).norm(), 1e-12);
}

TEST(FixedPlaneProjectiveConstraint, BadInputIsReported) {
  const char* solver = "<EulerImplicitSolver/><CGLinearSolver/>";
  SceneHolder s;
  EXPECT_EQ(s.loadFailing(scene(solver, R"(<FixedPlaneProjectiveConstraint direction="0 0 0"
      dmin="-1" dmax="1"/>)"),
                          {"direction is zero"})
                .field,
            "direction");
  SceneHolder t;
  EXPECT_EQ(t.loadFailing(scene(solver, R"(<FixedPlaneProjectiveConstraint dmin="1" dmax="-1"/>)"),
                          {"dmin (1.000000) is above dmax (-1.000000)"})
                .field,
            "dmin");
  SceneHolder u;
  EXPECT_EQ(u.loadFailing(scene(solver, R"(<FixedPlaneProjectiveConstraint indices="1 4"/>)"),
                          {"1 index out of range of the 4 points", "4"})
                .field,
            "indices");
}

}  // namespace
}  // namespace stroma::test
