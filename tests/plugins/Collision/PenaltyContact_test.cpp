// SPDX-License-Identifier: MIT
// Penalty contact (plugins/Collision, PenalityContactForceField): the generic force-field test,
// a sphere resting on a plane (equilibrium gap and force = weight), an undamped bounce (energy
// kept) and a head-on collision of two free spheres (momentum kept).
#include <gtest/gtest.h>

#include <cmath>

#include "CollisionTestScenes.h"
#include "collision/CollisionPipeline.h"
#include "core/Runtime.h"
#include "core/StateTypes.h"
#include "plugins/TestPlugin/TestSupport.h"
#include "simulation/ForceField.h"
#include "simulation/MechanicalState.h"
#include "simulation/Scene.h"
#include "support/ForceFieldTest.h"

namespace stroma::test {
namespace {

constexpr double kGravity = 9.81;

// A floor: a 2 x 2 m square of two triangles at y = 0, normal +y, that does not move.
const std::string kFloor = R"(<Node name="Floor">
    <MechanicalObject name="dofs" position="-1 0 -1  1 0 -1  1 0 1  -1 0 1"/>
    <MeshTopology name="mesh" triangles="0 3 1  1 3 2"/>
    <TriangleCollisionModel simulated="0" moving="0" contactStiffness="10"/>
  </Node>)";

// A ball: one point of mass m with a sphere of radius 0.05 m, at height y0.
std::string ball(const std::string& solver, double mass, double y0, double vy = 0) {
  return R"(<Node name="Ball">)" + solver + R"(
    <MechanicalObject name="dofs" position="0.1 )" +
         std::to_string(y0) + R"( 0.2" velocity="0 )" + std::to_string(vy) + R"( 0"/>
    <UniformMass vertexMass=")" +
         std::to_string(mass) + R"("/>
    <SphereCollisionModel radius="0.05" contactStiffness="10"/>
  </Node>)";
}

MechanicalState<Vec3Types>& stateAt(Scene& scene, const std::string& node) {
  for (const auto& c : scene.root().children())
    if (c->name() == node) return *c->get<MechanicalState<Vec3Types>>();
  throw std::runtime_error("no node " + node);
}

// The contact force of the scene's penalty response on the ball's state at its positions now.
Vec3d contactForceOn(Scene& scene, MechanicalState<Vec3Types>& state) {
  for (const auto& o : scene.root().objects())
    if (auto* ff = dynamic_cast<BaseForceField*>(o.get())) {
      const VecId f = VecId::externalForce();
      for (BaseMechanicalState* s : ff->states())
        if (auto* t = dynamic_cast<MechanicalState<Vec3Types>*>(s))
          for (Vec3d& v : t->writeDeriv(f)) v.setZero();
      ff->accumulateForce(MechanicalParams{}, f);
      return state.readDeriv(f)[0];
    }
  return Vec3d::Constant(std::nan(""));
}

TEST(PenaltyContact, ASphereRestsOnAPlaneAtTheContactDistanceWithItsWeight) {
  // Implicit Euler with damping settles the ball. The response keeps the gap d0 = 0.01 (the
  // intersection's contactDistance) between the sphere and the floor: k = 10 x 10 / (d0 + r) =
  // 1666.7 N/m, so the sphere sinks m g / k = 5.886e-4 m below it.
  const double m = 0.1, r = 0.05, d0 = 0.01, k = 10.0 * 10.0 / (d0 + r);
  Runtime runtime;
  Scene scene(runtime);
  const std::string xml =
      "<Node name=\"root\" dt=\"0.01\" gravity=\"0 -9.81 0\">" +
      collisionPipeline(
          R"(<MinProximityIntersection alarmDistance="0.03" contactDistance="0.01"/>)") +
      kFloor + ball(R"(<EulerImplicitSolver rayleighMass="2"/><SparseLDLSolver/>)", m, 0.08) +
      "</Node>";
  ASSERT_TRUE(scene.loadString(xml)) << describe(scene.log());
  for (int n = 0; n < 500; ++n) ASSERT_TRUE(scene.step()) << describe(scene.log());
  auto& state = stateAt(scene, "Ball");
  const Vec3d& x = state.readCoord(VecId::position())[0];
  const double gap = x.y() - r;  // sphere surface to floor
  EXPECT_NEAR(gap, d0 - m * kGravity / k, 1e-9) << "gap " << gap;
  EXPECT_NEAR(state.readDeriv(VecId::velocity())[0].norm(), 0, 1e-9);
  const Vec3d force = contactForceOn(scene, state);
  EXPECT_NEAR(force.y(), m * kGravity, 1e-9 * m * kGravity);
  EXPECT_NEAR(force.x(), 0, 1e-12);
  EXPECT_NEAR(force.z(), 0, 1e-12);
}

TEST(PenaltyContact, AnUndampedBounceKeepsItsEnergy) {
  // Symplectic Euler, no damping, dt = 1e-4 s: a ball dropped from 0.2 m hits the floor at 1.7
  // m/s (omega dt = 0.013 in contact) and comes back up. The penalty force is conservative (its
  // energy is k p^2 / 2 for a fixed normal), so the ball climbs back to its height: measured
  // within 0.02 % (stated: 0.2 %).
  const double m = 0.1, y0 = 0.25;
  Runtime runtime;
  Scene scene(runtime);
  const std::string xml =
      "<Node name=\"root\" dt=\"2e-5\" gravity=\"0 -9.81 0\">" +
      collisionPipeline(
          R"(<MinProximityIntersection alarmDistance="0.03" contactDistance="0.01"/>)") +
      kFloor + ball("<EulerExplicitSolver/>", m, y0) + "</Node>";
  ASSERT_TRUE(scene.loadString(xml)) << describe(scene.log());
  auto& state = stateAt(scene, "Ball");
  double highestAfter = 0, lowest = y0;
  bool bounced = false;
  for (int n = 0; n < 40000 && !(bounced && state.readDeriv(VecId::velocity())[0].y() < 0); ++n) {
    ASSERT_TRUE(scene.step()) << describe(scene.log());
    const double y = state.readCoord(VecId::position())[0].y();
    const double vy = state.readDeriv(VecId::velocity())[0].y();
    lowest = std::min(lowest, y);
    if (vy > 0) bounced = true;
    if (bounced) highestAfter = std::max(highestAfter, y);
  }
  ASSERT_TRUE(bounced) << "lowest " << lowest;
  EXPECT_LT(lowest, 0.05 + 0.01);  // it did reach the contact
  EXPECT_NEAR(highestAfter, y0, 2e-3 * y0) << "rebound height " << highestAfter;
}

TEST(PenaltyContact, TwoFreeSpheresCollidingKeepTheirMomentum) {
  // Two spheres, 1 and 3 kg, meet almost head on without gravity under one explicit solver:
  // the penalty forces are equal and opposite, so the total momentum stays (1 x 2 + 3 x -1 =
  // -1 kg m/s along x) to round-off, and after the collision they separate.
  Runtime runtime;
  Scene scene(runtime);
  const std::string xml =
      "<Node name=\"root\" dt=\"1e-4\" gravity=\"0 0 0\">" +
      collisionPipeline(
          R"(<MinProximityIntersection alarmDistance="0.03" contactDistance="0.01"/>)") +
      R"(<Node name="Spheres"><EulerExplicitSolver/>
           <Node name="A"><MechanicalObject name="dofs" position="-0.2 0 0" velocity="2 0 0"/>
             <UniformMass vertexMass="1"/><SphereCollisionModel radius="0.05" contactStiffness="30"/>
           </Node>
           <Node name="B"><MechanicalObject name="dofs" position="0.2 0.01 0" velocity="-1 0 0"/>
             <UniformMass vertexMass="3"/><SphereCollisionModel radius="0.05" contactStiffness="30"/>
           </Node>
         </Node></Node>)";
  ASSERT_TRUE(scene.loadString(xml)) << describe(scene.log());
  Node& spheres = *scene.root().children().front();
  auto& a = *spheres.children()[0]->get<MechanicalState<Vec3Types>>();
  auto& b = *spheres.children()[1]->get<MechanicalState<Vec3Types>>();
  auto momentum = [&] {
    return Vec3d(1.0 * a.readDeriv(VecId::velocity())[0] + 3.0 * b.readDeriv(VecId::velocity())[0]);
  };
  const Vec3d p0 = momentum();
  for (int n = 0; n < 3000; ++n) {
    ASSERT_TRUE(scene.step()) << describe(scene.log());
    EXPECT_LT((momentum() - p0).norm(), 1e-12) << "step " << n;
  }
  EXPECT_LT(a.readDeriv(VecId::velocity())[0].x(), b.readDeriv(VecId::velocity())[0].x())
      << "they still approach each other";
}

TEST(PenaltyContact, PassesTheForceFieldTest) {
  // The points of a bumpy sheet pressed 5 cm into the triangles of another (every contact
  // pushing, much deeper than the test's perturbations), so that the scene has one response:
  // its forces, energy, tangent and assembled matrix.
  ForceFieldTestOptions options;
  options.zeroAtRest = false;
  options.rotationInvariant = false;  // the normals are fixed at detection
  options.perturbation = 1e-3;
  const auto report = measureForceField(
      [](Scene& scene) {
        const std::string xml =
            "<Node name=\"root\" dt=\"0.01\" gravity=\"0 0 0\">" +
            collisionPipeline(
                R"(<MinProximityIntersection alarmDistance="0.2" contactDistance="0.15"/>)") +
            "<Node name=\"Lower\"><MeshTopology name=\"mesh\" " +
            sheetAttributes(5, 0.0, 0.01, 1, false) +
            "/><MechanicalObject position=\"@mesh.position\"/><TriangleCollisionModel/></Node>"
            "<Node name=\"Upper\"><MeshTopology name=\"mesh\" " +
            sheetAttributes(6, 0.1, 0.01, 2, true) +
            "/><MechanicalObject position=\"@mesh.position\"/><PointCollisionModel/></Node>"
            "</Node>";
        if (!scene.loadString(xml)) return false;
        return scene.step();  // detection: the response and its contacts
      },
      options);
  ASSERT_TRUE(report.failure.empty()) << report.failure << report.describe();
  EXPECT_GT(report.forceNorm, 0) << report.describe();
  EXPECT_LT(report.energyError, 1e-6) << report.describe();
  EXPECT_LT(report.dForceError, 1e-6) << report.describe();
  EXPECT_LT(report.fieldMatrixError, 1e-9) << report.describe();
  EXPECT_LT(report.systemMatrixError, 1e-9) << report.describe();
  EXPECT_LT(report.asymmetry, 1e-12) << report.describe();
}

}  // namespace
}  // namespace stroma::test
