// SPDX-License-Identifier: MIT
// PlaneProjectiveConstraint, LineProjectiveConstraint, DirectionProjectiveConstraint and
// PointProjectiveConstraint: a point under gravity slides on the plane (on the line, along the
// direction) with the projected acceleration P g, exactly as backward Euler gives it; a point
// off the plane is put on it; a point goes to `point`; the assembled path (SparseLDLSolver)
// agrees for axis-aligned constraints and warns for oblique ones; bad input is reported.
#include <gtest/gtest.h>

#include <functional>
#include <random>

#include "plugins/Spring/MechanicsTestSupport.h"
#include "simulation/ProjectiveConstraint.h"
#include "support/AllocationCounter.h"

namespace stroma::test {
namespace {

const char* kMatrixFree = R"(
  <EulerImplicitSolver rayleighMass="0" rayleighStiffness="0"/>
  <CGLinearSolver iterations="100" tolerance="1e-14" threshold="0"/>)";
const char* kAssembled = R"(
  <EulerImplicitSolver rayleighMass="0" rayleighStiffness="0"/>
  <SparseLDLSolver/>)";

// Two free points under gravity g, point 0 constrained by `constraint`.
std::string scene(const std::string& solver, const std::string& constraint,
                  const std::string& position = "0 0 0  1 1 1") {
  return R"(<Node name="root" gravity="1 -10 2" dt="0.01">)" + solver + R"(
  <MechanicalObject name="dofs" position=")" +
         position + R"("/>
  <UniformMass vertexMass="1"/>
  )" + constraint +
         "\n</Node>";
}

// Backward Euler from rest under a constant acceleration a: x_n = x_0 + h^2 n (n + 1) / 2 a.
Vec3d fallen(const Vec3d& x0, const Vec3d& a, int n, double h = 0.01) {
  return x0 + h * h * n * (n + 1) / 2.0 * a;
}

Vec3d point(const std::vector<double>& x, int i) { return {x[3 * i], x[3 * i + 1], x[3 * i + 2]}; }

TEST(PlaneProjectiveConstraint, PointSlidesWithTheProjectedGravity) {
  const Vec3d g(1, -10, 2), n = Vec3d(1, 2, 2) / 3;  // an oblique plane through the origin
  SceneHolder s;
  ASSERT_TRUE(s.load(scene(kMatrixFree, R"(<PlaneProjectiveConstraint name="c" indices="0"
      origin="0 0 0" normal="1 2 2"/>)")));
  ASSERT_TRUE(s.step(10));
  const auto x = numbers(s.text("@dofs.position"));
  const Vec3d expected = fallen(Vec3d::Zero(), g - n.dot(g) * n, 10);
  EXPECT_LT((point(x, 0) - expected).norm(), 1e-12);
  EXPECT_LT(std::abs(n.dot(point(x, 0))), 1e-14);                          // on the plane
  EXPECT_LT((point(x, 1) - fallen(Vec3d(1, 1, 1), g, 10)).norm(), 1e-12);  // the free point
  const auto v = numbers(s.text("@dofs.velocity"));
  EXPECT_LT(std::abs(n.dot(point(v, 0))), 1e-14);
}

TEST(PlaneProjectiveConstraint, PointOffThePlaneIsPutOnIt) {
  SceneHolder s;
  ASSERT_TRUE(s.load(scene(kMatrixFree, R"(<PlaneProjectiveConstraint indices="0"
      origin="0 0 1" normal="0 0 2"/>)",
                           "3 4 5  1 1 1")));
  ASSERT_TRUE(s.step(1));
  const auto x = numbers(s.text("@dofs.position"));
  // Projected on z = 1, then one step of the in-plane gravity (1, -10, 0).
  EXPECT_LT((point(x, 0) - fallen(Vec3d(3, 4, 1), Vec3d(1, -10, 0), 1)).norm(), 1e-12);
}

TEST(PlaneProjectiveConstraint, AssembledSolveAgreesForAnAxisNormal) {
  SceneHolder s;
  ASSERT_TRUE(s.load(scene(kAssembled, R"(<PlaneProjectiveConstraint name="c" indices="0"
      normal="0 3 0"/>)")));
  ASSERT_TRUE(s.step(10));
  const auto x = numbers(s.text("@dofs.position"));
  EXPECT_LT((point(x, 0) - fallen(Vec3d::Zero(), Vec3d(1, 0, 2), 10)).norm(), 1e-12);
  std::vector<std::size_t> rows;
  s.get<BaseProjectiveConstraint>("@c")->fixedRows(rows);
  EXPECT_EQ(rows, (std::vector<std::size_t>{1}));
}

TEST(PlaneProjectiveConstraint, ObliqueNormalInAnAssembledSolveWarnsAndStaysOnThePlane) {
  const Vec3d n = Vec3d(1, 2, 2) / 3;
  SceneHolder s;
  ASSERT_TRUE(s.load(scene(kAssembled, R"(<PlaneProjectiveConstraint indices="0"
      normal="1 2 2"/>)")));
  ASSERT_TRUE(s.scene().step());
  bool warned = false;
  for (const Message& m : s.scene().log().messages())
    warned |= m.level == MessageLevel::warning && m.field == "normal" &&
              m.text.find("oblique") != std::string::npos;
  EXPECT_TRUE(warned);
  EXPECT_LT(std::abs(n.dot(point(numbers(s.text("@dofs.position")), 0))), 1e-14);
}

TEST(LineProjectiveConstraint, PointSlidesWithTheProjectedGravity) {
  const Vec3d g(1, -10, 2), d = Vec3d(2, -1, 2) / 3;
  SceneHolder s;
  ASSERT_TRUE(s.load(scene(kMatrixFree, R"(<LineProjectiveConstraint indices="0"
      origin="1 1 0" direction="2 -1 2"/>)",
                           "1 1 0  1 1 1")));
  ASSERT_TRUE(s.step(10));
  const auto x = numbers(s.text("@dofs.position"));
  const Vec3d expected = fallen(Vec3d(1, 1, 0), d.dot(g) * d, 10);
  EXPECT_LT((point(x, 0) - expected).norm(), 1e-12);
  EXPECT_LT(d.cross(point(x, 0) - Vec3d(1, 1, 0)).norm(), 1e-14);  // on the line
}

TEST(LineProjectiveConstraint, AssembledSolveAgreesForAnAxisDirection) {
  SceneHolder s;
  ASSERT_TRUE(s.load(scene(kAssembled, R"(<LineProjectiveConstraint name="c" indices="1"
      origin="1 1 1" direction="0 -1 0"/>)")));
  ASSERT_TRUE(s.step(10));
  const auto x = numbers(s.text("@dofs.position"));
  EXPECT_LT((point(x, 1) - fallen(Vec3d(1, 1, 1), Vec3d(0, -10, 0), 10)).norm(), 1e-12);
  std::vector<std::size_t> rows;
  s.get<BaseProjectiveConstraint>("@c")->fixedRows(rows);
  EXPECT_EQ(rows, (std::vector<std::size_t>{3, 5}));
}

TEST(DirectionProjectiveConstraint, PointSlidesAlongTheDirectionThroughWhereItStarts) {
  const Vec3d g(1, -10, 2), d = Vec3d(2, -1, 2) / 3, x0(1, 2, 3);
  for (const char* solver : {kMatrixFree, kAssembled}) {
    SceneHolder s;
    ASSERT_TRUE(s.load(scene(solver, R"(<DirectionProjectiveConstraint indices="0"
        direction="2 -1 2"/>)",
                             "1 2 3  1 1 1"),
                       false));
    // Oblique: the assembled path warns at its first assembly (not checked here).
    for (int i = 0; i < 10; ++i) ASSERT_TRUE(s.scene().step());
    const auto x = numbers(s.text("@dofs.position"));
    EXPECT_LT(d.cross(point(x, 0) - x0).norm(), 1e-14);  // on its line
    if (solver == kMatrixFree)  // the exact constrained motion: the projected gravity
      EXPECT_LT((point(x, 0) - fallen(x0, d.dot(g) * d, 10)).norm(), 1e-12);
  }
  SceneHolder s;
  ASSERT_TRUE(s.load(scene(kAssembled, R"(<DirectionProjectiveConstraint name="c" indices="1"
      direction="0 0 -3"/>)")));
  ASSERT_TRUE(s.step(10));
  EXPECT_LT(
      (point(numbers(s.text("@dofs.position")), 1) - fallen(Vec3d(1, 1, 1), Vec3d(0, 0, 2), 10))
          .norm(),
      1e-12);
  std::vector<std::size_t> rows;
  s.get<BaseProjectiveConstraint>("@c")->fixedRows(rows);
  EXPECT_EQ(rows, (std::vector<std::size_t>{3, 4}));
}

TEST(PointProjectiveConstraint, PointGoesToItsPointAndStays) {
  SceneHolder s;
  ASSERT_TRUE(s.load(scene(kAssembled, R"(<PointProjectiveConstraint name="c" indices="1"
      point="0.5 0.25 -1"/>)")));
  ASSERT_TRUE(s.step(10));
  const auto x = numbers(s.text("@dofs.position"));
  EXPECT_EQ(point(x, 1), Vec3d(0.5, 0.25, -1));
  EXPECT_EQ(point(numbers(s.text("@dofs.velocity")), 1), Vec3d::Zero());
  EXPECT_LT((point(x, 0) - fallen(Vec3d::Zero(), Vec3d(1, -10, 2), 10)).norm(), 1e-12);
  std::vector<std::size_t> rows;
  s.get<BaseProjectiveConstraint>("@c")->fixedRows(rows);
  EXPECT_EQ(rows, (std::vector<std::size_t>{3, 4, 5}));
}

// Each projection, applied to random vectors through the component: P v lies in the allowed
// subspace, projecting again changes nothing, and the removed part is orthogonal to what stays.
TEST(PlaneProjectiveConstraint, ProjectionsOfEachComponentAreIdempotentAndOrthogonal) {
  const Vec3d n = Vec3d(1, 2, 2) / 3;
  struct Case {
    std::string xml;
    std::function<double(const Vec3d&)> distance;  // of an increment to the allowed subspace
  };
  const std::vector<Case> cases{
      {R"(<PlaneProjectiveConstraint name="c" indices="0 2" normal="1 2 2"/>)",
       [&](const Vec3d& v) { return std::abs(n.dot(v)); }},
      {R"(<LineProjectiveConstraint name="c" indices="0 2" direction="1 2 2"/>)",
       [&](const Vec3d& v) { return n.cross(v).norm(); }},
      {R"(<PointProjectiveConstraint name="c" indices="0 2"/>)",
       [&](const Vec3d& v) { return v.norm(); }},
      {R"(<FixedPlaneProjectiveConstraint name="c" indices="0 2" direction="1 2 2"/>)",
       [&](const Vec3d& v) { return std::abs(n.dot(v)); }},
      {R"(<DirectionProjectiveConstraint name="c" indices="0 2" direction="1 2 2"/>)",
       [&](const Vec3d& v) { return n.cross(v).norm(); }}};
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  for (const Case& c : cases) {
    SceneHolder s;
    ASSERT_TRUE(s.load(scene(kMatrixFree, c.xml, "0 0 0  1 1 1  2 0 1")));
    auto* constraint = s.get<ProjectiveConstraint<Vec3Types>>("@c");
    ASSERT_NE(constraint, nullptr);
    std::vector<Vec3d> v(3);
    for (Vec3d& e : v) e = Vec3d(u(rng), u(rng), u(rng));
    const std::vector<Vec3d> original = v;
    constraint->projectResponse(v);
    for (int i : {0, 2}) {
      EXPECT_LT(c.distance(v[i]), 1e-15) << c.xml;
      EXPECT_LT(std::abs((original[i] - v[i]).dot(v[i])), 1e-15) << c.xml;
    }
    EXPECT_EQ(v[1], original[1]) << c.xml;  // an unconstrained point is untouched
    std::vector<Vec3d> again = v;
    constraint->projectResponse(again);
    constraint->projectVelocity(again, 0.0);
    for (int i = 0; i < 3; ++i) EXPECT_LT((again[i] - v[i]).norm(), 1e-15) << c.xml;
    std::vector<Vec3d> x = original;
    constraint->projectPosition(x, 0.0);
    std::vector<Vec3d> y = x;
    g_allocations = 0;
    g_counting = true;  // a warm projection allocates nothing
    constraint->projectPosition(y, 0.0);
    constraint->projectResponse(again);
    constraint->projectVelocity(again, 0.0);
    g_counting = false;
    EXPECT_EQ(g_allocations, 0) << c.xml;
    for (int i = 0; i < 3; ++i) EXPECT_LT((y[i] - x[i]).norm(), 1e-15) << c.xml;
  }
}

// A constrained point pulled by a spring: the matrix-free solve (projected CG) and the assembled
// one (fixed rows, SparseLDLSolver) are two ways to the same constrained solution; projecting
// only at the end of an unconstrained solve would give another one.
TEST(PlaneProjectiveConstraint, ProjectedCGAndFixedRowsGiveTheSameCoupledMotion) {
  std::vector<std::vector<double>> results;
  for (const char* solver : {kMatrixFree, kAssembled}) {
    SceneHolder s;
    ASSERT_TRUE(s.load(scene(solver, R"(<PlaneProjectiveConstraint indices="0" normal="0 1 0"/>
  <LineProjectiveConstraint indices="2" origin="2 0 1" direction="0 0 1"/>
  <SpringForceField spring="0 1 300 0 1  1 2 300 0 1"/>)",
                             "0 0 0  1 1 1  2 0 1")));
    ASSERT_TRUE(s.step(20));
    results.push_back(numbers(s.text("@dofs.position")));
  }
  ASSERT_EQ(results[0].size(), 9u);
  for (std::size_t k = 0; k < 9; ++k) EXPECT_NEAR(results[0][k], results[1][k], 1e-10) << k;
  EXPECT_EQ(results[0][1], 0);               // point 0 stays on y = 0
  EXPECT_GT(std::abs(results[0][0]), 1e-3);  // and moves in it
  EXPECT_EQ(results[0][6], 2);               // point 2 stays on its line
  EXPECT_EQ(results[0][7], 0);
}

TEST(PlaneProjectiveConstraint, BadInputIsReported) {
  SceneHolder s;
  EXPECT_EQ(s.loadFailing(scene(kMatrixFree, R"(<PlaneProjectiveConstraint indices="0"
      normal="0 0 0"/>)"),
                          {"normal is zero"})
                .field,
            "normal");
  SceneHolder t;
  EXPECT_EQ(t.loadFailing(scene(kMatrixFree, R"(<LineProjectiveConstraint indices="0"
      direction="0 0 0"/>)"),
                          {"direction is zero"})
                .field,
            "direction");
  SceneHolder u;
  EXPECT_EQ(u.loadFailing(scene(kMatrixFree, R"(<PointProjectiveConstraint indices="0 7"/>)"),
                          {"1 index out of range of the 2 points", "7"})
                .field,
            "indices");
  SceneHolder w;
  EXPECT_EQ(w.loadFailing(scene(kMatrixFree, R"(<PlaneProjectiveConstraint indices="5"/>)"),
                          {"1 index out of range", "5"})
                .field,
            "indices");
}

}  // namespace
}  // namespace stroma::test
