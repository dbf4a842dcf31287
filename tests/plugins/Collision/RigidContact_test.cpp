// SPDX-License-Identifier: MIT
// Rigid and deformable bodies in contact through the penalty response: two rigid bodies
// (Rigid3d frames with spheres and a full inertia) keep their momentum, a rigid body comes to
// rest on a deformable block carried by the contact, and one deformable body made of two parts
// does not pass through itself with selfCollision.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <sstream>

#include "CollisionTestScenes.h"
#include "collision/CollisionPipeline.h"
#include "core/Runtime.h"
#include "core/StateTypes.h"
#include "plugins/TestPlugin/TestSupport.h"
#include "simulation/ForceField.h"
#include "simulation/MechanicalState.h"
#include "simulation/Scene.h"

namespace stroma::test {
namespace {

const std::string kProximity = collisionPipeline(
    R"(<MinProximityIntersection alarmDistance="0.01" contactDistance="0.005"/>)");

MechanicalState<Rigid3Types>& frameAt(Scene& scene, const std::string& node) {
  std::function<Node*(Node&)> find = [&](Node& n) -> Node* {
    if (n.name() == node) return &n;
    for (const auto& c : n.children())
      if (Node* f = find(*c)) return f;
    return nullptr;
  };
  return *find(scene.root())->get<MechanicalState<Rigid3Types>>();
}

// A rigid ball of mass m and radius r: 'mass volume inertia' with I/m = 2/5 r^2.
std::string rigidBall(const std::string& name, const std::string& frame, const std::string& v,
                      double m, double r) {
  const double j = 0.4 * r * r;
  return "<Node name=\"" + name + "\"><MechanicalObject template=\"Rigid3d\" position=\"" + frame +
         "\" velocity=\"" + v + "\"/><UniformMass vertexMass=\"" + std::to_string(m) + " 1 " +
         std::to_string(j) + " 0 0 0 " + std::to_string(j) + " 0 0 0 " + std::to_string(j) +
         "\"/><SphereCollisionModel radius=\"" + std::to_string(r) +
         "\" contactStiffness=\"30\"/></Node>";
}

TEST(RigidContact, TwoRigidBodiesCollidingKeepTheirMomentum) {
  // Rigid3d frames of 1 and 2 kg, spinning, meet off centre without gravity under one explicit
  // solver: the penalty forces are equal and opposite along the line of centres, so the linear
  // momentum stays to round-off; the spins are untouched (no torque through a sphere's centre).
  Runtime runtime;
  Scene scene(runtime);
  const std::string xml = "<Node name=\"root\" dt=\"1e-4\" gravity=\"0 0 0\">" + kProximity +
                          "<Node name=\"Bodies\"><EulerExplicitSolver/>" +
                          rigidBall("A", "-0.2 0 0  0 0 0 1", "2 0 0  0 0 5", 1.0, 0.05) +
                          rigidBall("B", "0.2 0.03 0  0 0 0 1", "-1 0 0  3 0 0", 2.0, 0.05) +
                          "</Node></Node>";
  ASSERT_TRUE(scene.loadString(xml)) << describe(scene.log());
  auto& a = frameAt(scene, "A");
  auto& b = frameAt(scene, "B");
  auto momentum = [&] {
    return Vec3d(1.0 * a.readDeriv(VecId::velocity())[0].linear +
                 2.0 * b.readDeriv(VecId::velocity())[0].linear);
  };
  const Vec3d p0 = momentum();
  for (int n = 0; n < 3000; ++n) ASSERT_TRUE(scene.step()) << describe(scene.log());
  EXPECT_LT((momentum() - p0).norm(), 1e-12);
  EXPECT_NEAR(a.readDeriv(VecId::velocity())[0].angular.z(), 5, 1e-12);
  EXPECT_NEAR(b.readDeriv(VecId::velocity())[0].angular.x(), 3, 1e-12);
  // They met and parted: B now moves away from A along x, and off-centre the impact turned
  // their paths (some y velocity).
  EXPECT_GT(
      b.readDeriv(VecId::velocity())[0].linear.x() - a.readDeriv(VecId::velocity())[0].linear.x(),
      0);
  EXPECT_GT(std::abs(b.readDeriv(VecId::velocity())[0].linear.y()), 0.01);
}

TEST(RigidContact, ARigidBodyRestsOnADeformableBlock) {
  // A rigid ball (0.2 kg, radius 2 cm) dropped on a soft block (hexahedra, E = 50 kPa, bottom
  // fixed), both under one implicit solver (bodies in contact share a solver: between solvers
  // a contact is coupled explicitly, each solve holding the other body fixed): at rest the ball
  // is carried by the contact (the force on it equals its weight) and sinks the block's top.
  Runtime runtime;
  Scene scene(runtime);
  const std::string xml = "<Node name=\"root\" dt=\"0.005\" gravity=\"0 -9.81 0\">" + kProximity +
                          R"(
    <Node name="Bodies"><EulerImplicitSolver rayleighMass="2"/><SparseLDLSolver/>
    <Node name="Block">
      <RegularGridTopology name="grid" min="-0.05 -0.05 -0.05" max="0.05 0 0.05" n="6 4 6"/>
      <MechanicalObject name="dofs"/><UniformMass totalMass="0.5"/>
      <HexahedronFEMForceField method="large" youngModulus="50000" poissonRatio="0.3"/>
      <BoxROI name="bottom" box="-1 -0.06 -1  1 -0.049 1" position="@dofs.rest_position"/>
      <FixedConstraint indices="@bottom.indices"/>
      <PointCollisionModel contactStiffness="30"/><TriangleCollisionModel contactStiffness="30"/>
    </Node>)" + rigidBall("Ball", "0.003 0.04 0.002  0 0 0 1", "0 0 0  0 0 0", 0.2, 0.02) +
                          "</Node></Node>";
  ASSERT_TRUE(scene.loadString(xml)) << describe(scene.log());
  for (int n = 0; n < 600; ++n) ASSERT_TRUE(scene.step()) << describe(scene.log());
  auto& ball = frameAt(scene, "Ball");
  EXPECT_LT(ball.readDeriv(VecId::velocity())[0].linear.norm(), 1e-4);
  const double y = ball.readCoord(VecId::position())[0].center.y();
  EXPECT_LT(y, 0.02 + 0.005);  // the top (y = 0) sank under it
  EXPECT_GT(y, 0.0);
  // The force of every response (in the bodies' node, their nearest common ancestor) on the
  // ball's frame.
  Vec3d force = Vec3d::Zero();
  for (const auto& o : scene.root().children().front()->objects())
    if (auto* ff = dynamic_cast<BaseForceField*>(o.get());
        ff && ff->name().rfind("penality", 0) == 0) {
      auto& f = ball.writeDeriv(VecId::externalForce());
      f.assign(f.size(), RigidDeriv3{});
      ff->accumulateForce(MechanicalParams{}, VecId::externalForce());
      force += ball.readDeriv(VecId::externalForce())[0].linear;
    }
  EXPECT_NEAR(force.y(), 0.2 * 9.81, 0.002 * 0.2 * 9.81) << force.transpose();
}

TEST(RigidContact, OneDeformableBodyDoesNotPassThroughItselfWithSelfCollision) {
  // One state, one surface, two parts: a soft cube (2 cm, 20 g) 1 cm above a soft slab (6 x 2 x
  // 6 cm, its bottom fixed), under gravity. With selfCollision the cube comes to rest on the
  // slab at the kept gap (5 mm here, at most a stated 5 % of it lost over the contacts); without
  // it the cube falls through (its top below the slab's bottom).
  auto run = [](bool self, double& gap) {
    std::ostringstream points, hexahedra;
    auto block = [&](Vec3d origin, Vec3d size, int first) {
      // 2 x 2 x 2 cells, 27 points, from `origin`.
      for (int k = 0; k < 3; ++k)
        for (int j = 0; j < 3; ++j)
          for (int i = 0; i < 3; ++i)
            points << origin.x() + 0.5 * size.x() * i << ' ' << origin.y() + 0.5 * size.y() * j
                   << ' ' << origin.z() + 0.5 * size.z() * k << "  ";
      auto at = [&](int a, int b, int c) { return first + a + 3 * b + 9 * c; };
      for (int k = 0; k < 2; ++k)
        for (int j = 0; j < 2; ++j)
          for (int i = 0; i < 2; ++i)
            hexahedra << at(i, j, k) << ' ' << at(i + 1, j, k) << ' ' << at(i + 1, j + 1, k) << ' '
                      << at(i, j + 1, k) << ' ' << at(i, j, k + 1) << ' ' << at(i + 1, j, k + 1)
                      << ' ' << at(i + 1, j + 1, k + 1) << ' ' << at(i, j + 1, k + 1) << "  ";
    };
    block(Vec3d(-0.03, -0.02, -0.03), Vec3d(0.06, 0.02, 0.06), 0);    // the slab, top at y = 0
    block(Vec3d(-0.007, 0.01, -0.013), Vec3d(0.02, 0.02, 0.02), 27);  // the cube, bottom at 0.01
    const std::string selfAttribute = self ? " selfCollision=\"1\"" : "";
    const std::string xml =
        "<Node name=\"root\" dt=\"0.005\" gravity=\"0 -9.81 0\">" + kProximity +
        "<Node name=\"Body\"><EulerImplicitSolver rayleighMass=\"2\"/><SparseLDLSolver/>"
        "<MeshTopology name=\"mesh\" position=\"" +
        points.str() + "\" hexahedra=\"" + hexahedra.str() +
        "\"/><MechanicalObject name=\"dofs\" position=\"@mesh.position\"/>"
        "<UniformMass vertexMass=\"0.002\"/>"
        "<HexahedronFEMForceField method=\"large\" youngModulus=\"20000\" poissonRatio=\"0.3\"/>"
        "<BoxROI name=\"bottom\" box=\"-1 -0.021 -1  1 -0.019 1\" "
        "position=\"@dofs.rest_position\"/>"
        "<FixedConstraint indices=\"@bottom.indices\"/>"
        "<PointCollisionModel" +
        selfAttribute +
        " contactStiffness=\"10\"/>"
        "<TriangleCollisionModel" +
        selfAttribute + " contactStiffness=\"10\"/></Node></Node>";
    Runtime runtime;
    Scene scene(runtime);
    ASSERT_TRUE(scene.loadString(xml)) << describe(scene.log());
    for (int n = 0; n < 300; ++n) ASSERT_TRUE(scene.step()) << describe(scene.log());
    if (self) {
      // The smallest gap between the two parts' surfaces, over this step's contacts.
      gap = 1;
      for (const ModelPairContacts& pair : scene.root().get<CollisionPhase>()->lastContacts())
        for (const Contact& c : pair.contacts) gap = std::min(gap, c.distance);
    } else {
      // The cube's highest point below the slab's top.
      const auto& x = scene.root().children().front()->get<MechanicalState<Vec3Types>>()->readCoord(
          VecId::position());
      gap = -1;
      for (int i = 27; i < 54; ++i) gap = std::max(gap, x[i].y());
    }
  };
  double withSelf = 0, without = 0;
  run(true, withSelf);
  run(false, without);
  EXPECT_GT(withSelf, 0.005 * 0.95) << "gap " << withSelf;
  EXPECT_LT(withSelf, 0.005 + 1e-4) << "gap " << withSelf;
  EXPECT_LT(without, -0.02) << "without self-collision the cube should fall through the slab";
}

}  // namespace
}  // namespace stroma::test
