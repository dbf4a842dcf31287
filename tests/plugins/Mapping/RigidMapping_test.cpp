// SPDX-License-Identifier: MIT
// RigidMapping: points attached to frames, x = c + R p, J = [I  -[R p]x]. The local points from
// world or local output positions, `points`, `index`, `rigidIndexPerPoint`; a body made of
// mapped point masses falls without turning and answers a force at a point with the velocity
// of rigid-body dynamics; springs between points of two frames assemble as J^T K J.
#include "plugins/Mapping/MappingChecks.h"
#include "support/TestSprings.h"

namespace stroma::test {
namespace {

using PointsOnFrames = Mapping<Rigid3Types, Vec3Types>;

// Two frames, turned about oblique axes (unit quaternions "x y z w").
const char* kFrames = "0.5 -1 2  0.2 0.3 0.1 0.9273618495495703   -1 0 1  0 0.6 0 0.8";

std::string framesScene(const std::string& mappingAttributes, const std::string& output) {
  return std::string(R"(<Node name="root" gravity="0 0 0">
      <MechanicalObject template="Rigid3" name="frames" position=")") +
         kFrames + R"("/>
      <Node name="Points">
        <MechanicalObject name="points" )" +
         output + R"(/>
        <RigidMapping )" +
         mappingAttributes + R"(/>
      </Node>
    </Node>)";
}

RigidCoord3 frameOf(const PointsOnFrames& m, unsigned k) {
  return m.input()->readCoord(VecId::position())[k];
}

TEST(RigidMapping, WorldPositionsBecomeLocalPointsAndStayPut) {
  Runtime runtime;
  Scene scene(runtime);
  ASSERT_TRUE(
      scene.loadString(framesScene(R"(template="Rigid3,Vec3" rigidIndexPerPoint="0 0 1 1 1"
                                      globalToLocalCoords="1")",
                                   R"(position="1 0 0  0 2 1  -1 -1 -1  3 0.5 0  0 0 0")")))
      << problems(scene.log());
  EXPECT_EQ(problems(scene.log()), "");
  auto* mapping = findInScene<PointsOnFrames>(scene.root());
  ASSERT_NE(mapping, nullptr);
  EXPECT_EQ(mapping->templateName(), "Rigid3d,Vec3d");
  const auto& x = mapping->output()->readCoord(VecId::position());
  ASSERT_EQ(x.size(), 5u);
  // The first apply puts the points back where the scene put them.
  EXPECT_TRUE(x[1].isApprox(Vec3d(0, 2, 1), 1e-15));
  EXPECT_TRUE(x[3].isApprox(Vec3d(3, 0.5, 0), 1e-15));
  // p = R^T (x - c) in the frame of each point.
  const RigidCoord3 f1 = frameOf(*mapping, 1);
  const Vec3d local = f1.orientation.conjugate() * (Vec3d(3, 0.5, 0) - f1.center);
  std::vector<Vec3d> out;
  mapping->apply(out, mapping->input()->readCoord(VecId::position()));
  EXPECT_TRUE((f1.center + f1.orientation * local).isApprox(out[3], 1e-15));
  expectConsistentMapping(*mapping);
}

TEST(RigidMapping, LocalPointsAreTurnedAndMovedWithTheirFrame) {
  Runtime runtime;
  Scene scene(runtime);
  // Without globalToLocalCoords (false, SOFA's default) the output positions are local
  // coordinates; no template: deduced from the Vec3d state beside the mapping.
  ASSERT_TRUE(scene.loadString(
      framesScene(R"(index="1")", R"(position="1 0 0  0 0 2")")))
      << problems(scene.log());
  auto* mapping = findInScene<PointsOnFrames>(scene.root());
  ASSERT_NE(mapping, nullptr);
  const RigidCoord3 f = frameOf(*mapping, 1);  // (-1 0 1), 73.74 degrees about y
  const auto& x = mapping->output()->readCoord(VecId::position());
  EXPECT_TRUE(x[0].isApprox(f.center + f.orientation * Vec3d(1, 0, 0), 1e-15));
  // Quaternion (0, 0.6, 0, 0.8) turns x to (cos a, 0, -sin a), cos a = 0.8^2 - 0.6^2 = 0.28.
  EXPECT_TRUE(x[0].isApprox(Vec3d(-1 + 0.28, 0, 1 - 0.96), 1e-14)) << x[0].transpose();
  expectConsistentMapping(*mapping);
}

TEST(RigidMapping, PointsFieldGivesTheOutputItsPoints) {
  Runtime runtime;
  Scene scene(runtime);
  ASSERT_TRUE(scene.loadString(
      framesScene(R"(points="1 0 0  0 1 0  0 0 1" index="0" indexFromEnd="true")", "")))
      << problems(scene.log());
  auto* mapping = findInScene<PointsOnFrames>(scene.root());
  ASSERT_NE(mapping, nullptr);
  ASSERT_EQ(mapping->output()->size(), 3u);
  const RigidCoord3 f = frameOf(*mapping, 1);  // the last frame
  EXPECT_TRUE(mapping->output()->readCoord(VecId::position())[0].isApprox(
      f.center + f.orientation * Vec3d(1, 0, 0), 1e-15));
  EXPECT_TRUE(mapping->output()->readCoord(VecId::position())[2].isApprox(
      f.center + f.orientation * Vec3d(0, 0, 1), 1e-15));
  // The rest shape is the mapped one too (the output had none of its own).
  EXPECT_EQ(mapping->output()->readCoord(VecId::restPosition()),
            mapping->output()->readCoord(VecId::position()));
}

TEST(RigidMapping, ReportsFramesOutOfRange) {
  Runtime runtime;
  Scene a(runtime), b(runtime), c(runtime);
  EXPECT_FALSE(a.loadString(framesScene(R"(index="2")", R"(position="1 0 0")")));
  EXPECT_NE(problems(a.log()).find("index 2 is out of range of the 2 input frames"),
            std::string::npos)
      << problems(a.log());
  EXPECT_FALSE(b.loadString(
      framesScene(R"(rigidIndexPerPoint="0 3 7")", R"(position="1 0 0  0 1 0  0 0 1")")));
  EXPECT_NE(problems(b.log()).find("frames out of range of the 2 input frames: 3 7"),
            std::string::npos)
      << problems(b.log());
  EXPECT_FALSE(c.loadString(framesScene(R"(rigidIndexPerPoint="0 1")", R"(position="1 0 0")")));
  EXPECT_NE(problems(c.log()).find("has 2 values for 1 mapped points"), std::string::npos)
      << problems(c.log());
}

// A rigid body whose mass is carried by 4 mapped points of 0.5 kg; its frame is off the centre
// of mass and turned. `extra` goes into the points' node.
std::string bodyScene(const std::string& gravity, const std::string& extra) {
  return R"(<Node name="root" gravity=")" + gravity + R"(" dt="0.01">
      <EulerImplicitSolver rayleighMass="0" rayleighStiffness="0"/>
      <CGLinearSolver iterations="50" tolerance="1e-13" threshold="1e-40"/>
      <MechanicalObject template="Rigid3" name="frame" position="1 2 3  0.2 0.3 0.1 0.9273618495495703"/>
      <Node name="Points">
        <MechanicalObject name="points" position="1 2 3  2 2 3  1 3.5 3  1 2 5"/>
        <UniformMass vertexMass="0.5"/>
        <RigidMapping globalToLocalCoords="1"/>
        )" +
         extra + R"(
      </Node>
    </Node>)";
}

TEST(RigidMapping, ABodyOfMappedMassesFallsWithoutTurning) {
  Runtime runtime;
  Scene scene(runtime);
  ASSERT_TRUE(scene.loadString(bodyScene("0 -9.81 0", ""))) << problems(scene.log());
  const auto x0 = positionsAt(scene, "/root/Points/points");
  const int steps = 20;
  for (int i = 0; i < steps; ++i) ASSERT_TRUE(scene.step()) << problems(scene.log());
  // Uniform gravity has no moment about the centre of mass: J^T M J [g 0] = J^T M g, so each
  // backward Euler step adds h g to the linear velocity and nothing to the angular one, and
  // every point falls by g t (t + h) / 2 whatever the frame's offset and orientation.
  const double t = steps * 0.01, drop = 9.81 * t * (t + 0.01) / 2;
  const auto x = positionsAt(scene, "/root/Points/points");
  for (std::size_t k = 0; k < x.size(); ++k)
    EXPECT_NEAR(x[k], x0[k] - (k % 3 == 1 ? drop : 0.0), 1e-10) << k;
  const auto frame = positionsAt(scene, "/root/frame");
  EXPECT_NEAR(frame[1], 2 - drop, 1e-10);
  EXPECT_NEAR(frame[6], 0.9273618495495703, 1e-12);  // orientation unchanged
}

TEST(RigidMapping, AForceAtAPointGivesTheVelocityOfRigidBodyDynamics) {
  Runtime runtime;
  Scene scene(runtime);
  ASSERT_TRUE(
      scene.loadString(bodyScene("0 0 0", R"(<ConstantForceField indices="2" forces="3 -1 2"/>)")))
      << problems(scene.log());
  auto* mapping = findInScene<PointsOnFrames>(scene.root());
  ASSERT_NE(mapping, nullptr);
  // The mass matrix of the frame: sum of m [I -[r]x; [r]x -[r]x^2] over the points, r = x - c;
  // one backward Euler step from rest without stiffness solves M v = h J^T F.
  const RigidCoord3 frame = frameOf(*mapping, 0);
  const auto& points = mapping->output()->readCoord(VecId::position());
  Eigen::Matrix<double, 6, 6> M = Eigen::Matrix<double, 6, 6>::Zero();
  for (const Vec3d& p : points) {
    const Vec3d r = p - frame.center;
    Mat3d cross;
    cross << 0, -r.z(), r.y(), r.z(), 0, -r.x(), -r.y(), r.x(), 0;
    M.block<3, 3>(0, 0) += 0.5 * Mat3d::Identity();
    M.block<3, 3>(0, 3) -= 0.5 * cross;
    M.block<3, 3>(3, 0) += 0.5 * cross;
    M.block<3, 3>(3, 3) -= 0.5 * cross * cross;
  }
  const Vec3d F(3, -1, 2), r = points[2] - frame.center;
  Vec6d f;
  f << F, r.cross(F);
  const Vec6d expected = 0.01 * M.ldlt().solve(f);
  ASSERT_TRUE(scene.step()) << problems(scene.log());
  std::vector<double> v;
  mapping->input()->copyVelocities(v);
  ASSERT_EQ(v.size(), 6u);
  for (int k = 0; k < 6; ++k) EXPECT_NEAR(v[k], expected[k], 1e-12 * expected.norm()) << k;
  // The body turns: the force is off the centre of mass.
  EXPECT_GT(expected.tail<3>().norm(), 1e-3);
}

TEST(RigidMapping, SpringsBetweenTwoFramesAssembleAsJTKJ) {
  Runtime runtime;
  runtime.factory().add("TestSprings", "test").with<CorrectSprings>();
  Scene scene(runtime);
  ASSERT_TRUE(scene.loadString(R"(<Node name="root" gravity="0 0 0">
      <MechanicalObject template="Rigid3" name="frames" position=")" +
                               std::string(kFrames) + R"("/>
      <Node name="Points">
        <MechanicalObject name="points" position="1 0 0  0 2 1  -1 -1 -1  3 0.5 0  0 0 0"/>
        <RigidMapping rigidIndexPerPoint="0 0 1 1 1" globalToLocalCoords="1"/>
        <UniformMass vertexMass="0.3"/>
        <TestSprings stiffness="40" edges="0 2  0 3  1 4  1 2  0 1"/>
      </Node>
    </Node>)"))
      << problems(scene.log());
  // At rest (and without gravity) the points are not pulled, so the mapped stiffness has no
  // geometric part and the finite difference of J^T f is J^T K J exactly.
  SystemCheckReport r = measureSystem(scene, 1.5, -0.2, true);
  EXPECT_LT(r.assembled, 1e-14);
  EXPECT_LT(r.stiffness, 1e-7);
  // Off rest, the assembled J^T K J still equals the matrix-free J^T K J.
  auto* mapping = findInScene<PointsOnFrames>(scene.root());
  auto& frames = mapping->input()->writeCoord(VecId::position());
  frames[1].center += Vec3d(0.3, -0.1, 0.2);
  frames[0].orientation =
      Quat(Eigen::AngleAxisd(0.4, Vec3d(1, 1, 0).normalized())) * frames[0].orientation;
  r = measureSystem(scene, 0.0, 1.0, false);
  EXPECT_LT(r.assembled, 1e-14);
}

}  // namespace
}  // namespace stroma::test
