// SPDX-License-Identifier: MIT
// Hertz's contact (issue 16): the coarse case of bench/studies/Hertz.xml, a quarter of a linear
// elastic hemisphere (share/mesh/hemisphere-6.msh, points 0.032 R apart at the pole) pressed on a
// rigid plane to d / R = 0.5, 1, 1.5, 2 %, with the constraint response and the penalty response.
// The tolerances are this mesh's (the study's table in docs/accuracy.md has the finer ones). Also:
// the reference's axis field (plugins/Validation/kernels/HertzContact.h) against a numerical
// integral of Johnson's stresses, and HertzContactComparison's bad input.
#include "Validation/kernels/HertzContact.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include "core/Runtime.h"
#include "plugins/TestPlugin/TestSupport.h"
#include "simulation/Scene.h"

namespace stroma::test {
namespace {

// The study's scene template with one row's placeholders filled (as `stroma bench` does).
std::string hertzScene(const std::string& loop, const std::string& response,
                       const std::string& correction, const std::string& stiffness) {
  std::ifstream in(std::string(STROMA_SOURCE_DIR) + "/bench/studies/Hertz.scn.in");
  std::stringstream text;
  text << in.rdbuf();
  std::string scene = text.str();
  for (const auto& [key, value] : {std::pair<std::string, std::string>{"${loop}", loop},
                                   {"${response}", response},
                                   {"${correction}", correction},
                                   {"${stiffness}", stiffness},
                                   {"${n}", "6"}})
    for (auto at = scene.find(key); at != std::string::npos; at = scene.find(key))
      scene.replace(at, key.size(), value);
  return scene;
}

double output(Scene& scene, const char* name) {
  const Node* sphere = scene.root().findChild("Sphere");
  for (const auto& object : sphere ? sphere->objects() : scene.root().objects())
    if (object->className() == "HertzContactComparison")
      return std::stod(object->findData(name)->valueText());
  ADD_FAILURE() << "no HertzContactComparison";
  return NAN;
}

struct Pressed {
  double force, maxHertzError, maxHalfSpaceError, hertzError;
  int comparisons;
};

Pressed press(const std::string& scene) {
  Runtime runtime;
  Scene s(runtime);
  EXPECT_TRUE(s.loadString(scene, std::string(STROMA_SOURCE_DIR) + "/bench/studies/Hertz.scn"))
      << describe(s.log());
  for (int n = 0; n < 4; ++n) EXPECT_TRUE(s.step()) << describe(s.log());
  EXPECT_EQ(s.log().count(MessageLevel::warning), 0u) << describe(s.log());
  return {output(s, "force"), output(s, "maxHertzError"), output(s, "maxHalfSpaceError"),
          output(s, "hertzError"), static_cast<int>(output(s, "comparisons"))};
}

const std::string kConstraintLoop =
    R"(<FreeMotionAnimationLoop/><GenericConstraintSolver tolerance="1e-12" maxIterations="10000"/>)";
const std::string kConstraintResponse =
    R"(<CollisionResponse response="FrictionContactConstraint" responseParams="mu=0"/>)";

TEST(HertzContact, ConstraintResponseFollowsHertzOnTheCoarseMesh) {
  // Measured on this mesh: 7.8 % from the half-space solution at the centre's depth (the
  // largest of the 4 indentations, at d / R = 2 %; the mesh is too soft), 11.7 % from
  // F_H(delta). The law itself is 8 to 18 % under the half-space solution there (the sphere is
  // driven at its centre, depth R, not at infinity): the force must be above it at 2 %.
  const Pressed p = press(
      hertzScene(kConstraintLoop, kConstraintResponse, "<LinearSolverConstraintCorrection/>", "1"));
  EXPECT_EQ(p.comparisons, 4);
  EXPECT_LT(p.maxHalfSpaceError, 0.085);
  EXPECT_LT(p.maxHertzError, 0.125);
  EXPECT_GT(p.hertzError, 0.0);
}

TEST(HertzContact, PenaltyResponseIsSofterThanTheConstraint) {
  // The same indentations with penalty forces (k per contact point): each contact sinks f / k
  // into the plane, so the body is compressed less and pushes less. Measured at 2 %: k = 1000
  // N/m 0.5 % under the constraint's force, SOFA's default stiffnesses (10 x 10) 4.9 % under.
  const Pressed exact = press(
      hertzScene(kConstraintLoop, kConstraintResponse, "<LinearSolverConstraintCorrection/>", "1"));
  const Pressed stiff = press(hertzScene("", "<CollisionResponse/>", "", "1000"));
  const Pressed soft = press(hertzScene("", "<CollisionResponse/>", "", "100"));
  EXPECT_EQ(stiff.comparisons, 4);
  EXPECT_LT(stiff.force, exact.force);
  EXPECT_GT(stiff.force, 0.99 * exact.force);
  EXPECT_LT(soft.force, 0.96 * exact.force);
  EXPECT_GT(soft.force, 0.94 * exact.force);
  EXPECT_GT(soft.maxHalfSpaceError, exact.maxHalfSpaceError);
}

TEST(HertzContact, AxisFieldIsTheIntegralOfJohnsonsStresses) {
  // u(z) = integral from z to infinity of -eps_z on the axis, eps_z = (sigma_z - 2 nu sigma_r) /
  // E, Johnson's (3.45) stresses, by the midpoint rule on s = z' / a = zeta + t / (1 - t).
  const reference::HertzContact hertz{1e4, 0.3, 0.05};
  const double d = 0.001, a = std::sqrt(hertz.radius * d);
  const double p0 = 3 * hertz.force(d) / (2 * M_PI * a * a), nu = hertz.poissonRatio;
  for (double depth : {0.0, 0.2 * a, a, 3 * a, hertz.radius}) {
    double sum = 0;
    const int n = 200000;
    for (int i = 0; i < n; ++i) {
      const double t = (i + 0.5) / n, s = depth / a + t / (1 - t);
      const double sz = -p0 / (1 + s * s);
      const double sr = p0 * (-(1 + nu) * (1 - s * std::atan(1 / s)) + 0.5 / (1 + s * s));
      sum -= (sz - 2 * nu * sr) / hertz.youngModulus * a / ((1 - t) * (1 - t)) / n;
    }
    EXPECT_NEAR(hertz.axisLag(d, depth), sum, 1e-6 * d) << "depth " << depth;
  }
  EXPECT_NEAR(hertz.axisLag(d, 0), d, 1e-15);  // the pole reaches the plane
  // The far series takes over from the closed form without a jump.
  const double far = 100 * a;
  const double below = hertz.axisLag(d, far * (1 - 1e-12)),
               above = hertz.axisLag(d, far * (1 + 1e-12));
  EXPECT_NEAR(below, above, 1e-10 * below);
  // The inverse: the approach of the centre at d / R = 2 % is 10 % short of d.
  const double lag = hertz.axisLag(d, hertz.radius);
  EXPECT_NEAR(lag / d, 0.1021, 1e-3);
  EXPECT_NEAR(hertz.indentationForApproachAt(d - lag, hertz.radius), d, 1e-12 * d);
}

TEST(HertzContact, ComparisonRejectsBadInput) {
  Runtime runtime;
  Scene scene(runtime);
  EXPECT_FALSE(scene.loadString(R"(<Node name="root">
    <MechanicalObject position="0 0 0  1 0 0"/>
    <HertzContactComparison name="hertz" indices="5" radius="0" poissonRatio="0.5" normal="0 0 0"/>
  </Node>)"));
  const std::string text = describe(scene.log());
  for (const char* field : {"indices", "radius", "poissonRatio", "normal"})
    EXPECT_NE(text.find(std::string("field '") + field + "'"), std::string::npos)
        << field << ": " << text;
}

}  // namespace
}  // namespace stroma::test
