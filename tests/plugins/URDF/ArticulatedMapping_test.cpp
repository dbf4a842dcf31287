// SPDX-License-Identifier: MIT
// ArticulatedMapping: the link frames of the 2-link arm equal the closed form at random joint
// values; on a branching 3D robot (origins with rpy, a prismatic joint, a fixed one) J equals
// central differences of apply, jacobian() equals applyJ, and <J x, y> = <x, J^T y>; the same
// with a mimic joint, whose frames are those of its source's value times its multiplier plus
// its offset; a mimic of a missing joint is an error.
#include <random>

#include "plugins/URDF/URDFTestRobots.h"

namespace stroma::test {
namespace {

using JointsToFrames = Mapping<Vec1Types, Rigid3Types>;

Quat aboutY(double angle) { return Quat(Eigen::AngleAxisd(angle, Vec3d::UnitY())); }

TEST(ArticulatedMapping, TwoLinkArmFramesAreTheClosedForm) {
  RobotFolder folder;
  Runtime runtime;
  Scene scene(runtime);
  ASSERT_TRUE(loadArm(scene, folder, armScene(folder, twoLinkArm(), "", "", "0 0 0")))
      << problems(scene.log());
  auto* mapping = findInScene<JointsToFrames>(scene.root());
  ASSERT_NE(mapping, nullptr);
  EXPECT_EQ(mapping->className(), "ArticulatedMapping");
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> angle(-M_PI, M_PI);
  const double L = 0.5;
  for (int sample = 0; sample < 20; ++sample) {
    const double q1 = angle(rng), q2 = angle(rng);
    std::vector<RigidCoord3> frames;
    mapping->apply(frames, {Vec1d(q1), Vec1d(q2)});
    ASSERT_EQ(frames.size(), 3u);  // base_link, link1, link2
    EXPECT_LT(frames[0].center.norm(), 1e-15);
    EXPECT_LT(frames[1].center.norm(), 1e-15);
    const Vec3d elbow = L * Vec3d(std::cos(q1), 0, -std::sin(q1));
    EXPECT_LT((frames[2].center - elbow).norm(), 1e-15);
    EXPECT_LT(frames[1].orientation.angularDistance(aboutY(q1)), 1e-14);
    EXPECT_LT(frames[2].orientation.angularDistance(aboutY(q1 + q2)), 1e-14);
    // The tip of link 2, through its frame: the classical planar arm.
    const Vec3d tip = frames[2].center + frames[2].orientation * Vec3d(L, 0, 0);
    const Vec3d closed(L * (std::cos(q1) + std::cos(q1 + q2)), 0,
                       -L * (std::sin(q1) + std::sin(q1 + q2)));
    EXPECT_LT((tip - closed).norm(), 1e-15);
  }
}

// A branching robot: base -> a (revolute, rpy origin) -> b (prismatic) -> c (fixed) and
// a -> d (continuous, oblique axis).
const char* kBranchingRobot = R"(<?xml version="1.0"?>
<robot name="tree">
  <link name="base"/> <link name="a"/> <link name="b"/> <link name="c"/> <link name="d"/>
  <joint name="ja" type="revolute"><parent link="base"/><child link="a"/>
    <origin xyz="0.1 -0.2 0.3" rpy="0.3 -0.5 1.1"/><axis xyz="0 0 1"/>
    <limit lower="-10" upper="10" effort="1" velocity="1"/></joint>
  <joint name="jb" type="prismatic"><parent link="a"/><child link="b"/>
    <origin xyz="0.4 0 0" rpy="-0.7 0.2 0"/><axis xyz="1 1 0"/>
    <limit lower="-10" upper="10" effort="1" velocity="1"/></joint>
  <joint name="jc" type="fixed"><parent link="b"/><child link="c"/>
    <origin xyz="0 0.25 0" rpy="0.1 0.2 0.3"/></joint>
  <joint name="jd" type="continuous"><parent link="a"/><child link="d"/>
    <origin xyz="0 0 0.5" rpy="1.0 0 -0.4"/><axis xyz="0.3 -0.4 0.866"/></joint>
</robot>
)";

RigidDeriv3 difference(const RigidCoord3& a, const RigidCoord3& b) {
  RigidDeriv3 d;
  d.linear = a.center - b.center;
  const Eigen::AngleAxisd turn(a.orientation * b.orientation.conjugate());
  d.angular = turn.angle() * turn.axis();
  return d;
}

// J against central differences of apply, jacobian() against applyJ, <J x, y> = <x, J^T y>, at
// random joint values of `urdf` (`dofs` joint values, 5 links).
void expectJacobianConsistent(const std::string& urdf, std::size_t dofs) {
  RobotFolder folder;
  Runtime runtime;
  Scene scene(runtime);
  ASSERT_TRUE(loadArm(scene, folder, armScene(folder, urdf, "", "", "0 0 0")))
      << problems(scene.log());
  auto* mapping = findInScene<JointsToFrames>(scene.root());
  ASSERT_NE(mapping, nullptr);
  auto& q = mapping->input()->writeCoord(VecId::position());
  ASSERT_EQ(q.size(), dofs);
  const int n = static_cast<int>(dofs);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> uniform(-1, 1);
  for (int sample = 0; sample < 5; ++sample) {
    for (auto& v : q) v[0] = 2 * uniform(rng);
    const std::vector<Vec1d> q0 = q;
    std::vector<Vec1d> dq(q.size());
    for (auto& v : dq) v[0] = uniform(rng);
    // J dq against (apply(q + h dq) - apply(q - h dq)) / 2h.
    std::vector<RigidDeriv3> Jdq;
    mapping->applyJ(Jdq, dq);
    const double h = 1e-6;
    std::vector<Vec1d> plus = q0, minus = q0;
    for (std::size_t j = 0; j < q0.size(); ++j) {
      plus[j][0] += h * dq[j][0];
      minus[j][0] -= h * dq[j][0];
    }
    std::vector<RigidCoord3> xp, xm;
    mapping->apply(xp, plus);
    mapping->apply(xm, minus);
    ASSERT_EQ(Jdq.size(), 5u);
    for (std::size_t k = 0; k < Jdq.size(); ++k) {
      const RigidDeriv3 fd = difference(xp[k], xm[k]);
      EXPECT_LT((fd.linear / (2 * h) - Jdq[k].linear).norm(), 1e-8) << "frame " << k;
      EXPECT_LT((fd.angular / (2 * h) - Jdq[k].angular).norm(), 1e-8) << "frame " << k;
    }
    // jacobian() columns are applyJ of unit vectors.
    const Eigen::SparseMatrix<double> J = mapping->jacobian();
    ASSERT_EQ(J.rows(), 30);
    ASSERT_EQ(J.cols(), n);
    Eigen::VectorXd flatDq(n), flatJdq(30);
    for (int j = 0; j < n; ++j) flatDq[j] = dq[j][0];
    for (int k = 0; k < 5; ++k) {
      flatJdq.segment<3>(6 * k) = Jdq[k].linear;
      flatJdq.segment<3>(6 * k + 3) = Jdq[k].angular;
    }
    EXPECT_LT((J * flatDq - flatJdq).norm(), 1e-14 * (1 + flatJdq.norm()));
    // <J x, y> = <x, J^T y> for a random y.
    std::vector<RigidDeriv3> y(5);
    Eigen::VectorXd flatY(30);
    for (int k = 0; k < 5; ++k) {
      y[k].linear = Vec3d(uniform(rng), uniform(rng), uniform(rng));
      y[k].angular = Vec3d(uniform(rng), uniform(rng), uniform(rng));
      flatY.segment<3>(6 * k) = y[k].linear;
      flatY.segment<3>(6 * k + 3) = y[k].angular;
    }
    std::vector<Vec1d> JTy(dofs, Vec1d::Zero());
    mapping->applyJT(JTy, y);
    double right = 0;
    for (int j = 0; j < n; ++j) right += flatDq[j] * JTy[j][0];
    const double left = flatJdq.dot(flatY);
    EXPECT_LT(std::abs(left - right), 1e-13 * (flatJdq.norm() * flatY.norm()));
  }
}

TEST(ArticulatedMapping, JacobianIsTheDerivativeAndJTransposeItsAdjoint) {
  expectJacobianConsistent(kBranchingRobot, 3);  // ja, jb, jd
}

// The branching robot with jd following ja (URDF's <mimic>): two joint values, jd's column
// added to ja's, times the multiplier.
std::string mimicRobot() {
  std::string urdf = kBranchingRobot;
  const std::string axis = R"(<axis xyz="0.3 -0.4 0.866"/>)";
  urdf.insert(urdf.find(axis) + axis.size(),
              R"(<mimic joint="ja" multiplier="-0.7" offset="0.2"/>)");
  return urdf;
}

TEST(ArticulatedMapping, MimicJointFollowsItsSourceInFramesAndJacobian) {
  expectJacobianConsistent(mimicRobot(), 2);  // ja, jb; jd = -0.7 ja + 0.2
  // Link d's frame at (ja, jb) is the branching robot's at (ja, jb, -0.7 ja + 0.2).
  RobotFolder folder, plainFolder;
  Runtime runtime;
  Scene mimic(runtime), plain(runtime);
  ASSERT_TRUE(loadArm(mimic, folder, armScene(folder, mimicRobot(), "", "", "0 0 0")));
  ASSERT_TRUE(loadArm(plain, plainFolder, armScene(plainFolder, kBranchingRobot, "", "", "0 0 0")));
  std::string why;
  const auto* names = dynamic_cast<const Data<std::vector<std::string>>*>(
      resolveObjectPath(mimic.root(), "@/root/loader", why)->findData("jointNames"));
  EXPECT_EQ(names->value(), (std::vector<std::string>{"ja", "jb"}));
  auto* m = findInScene<JointsToFrames>(mimic.root());
  auto* p = findInScene<JointsToFrames>(plain.root());
  for (double ja : {-1.3, 0.4, 2.0}) {
    std::vector<RigidCoord3> a, b;
    m->apply(a, {Vec1d(ja), Vec1d(0.1)});
    p->apply(b, {Vec1d(ja), Vec1d(0.1), Vec1d(-0.7 * ja + 0.2)});
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t k = 0; k < a.size(); ++k) {
      EXPECT_LT((a[k].center - b[k].center).norm(), 1e-15) << "link " << k;
      EXPECT_LT(a[k].orientation.angularDistance(b[k].orientation), 1e-14) << "link " << k;
    }
  }
}

TEST(ArticulatedMapping, MimicOfAMissingJointIsAnError) {
  std::string urdf = mimicRobot();
  urdf.replace(urdf.find("<mimic joint=\"ja\""), 18, "<mimic joint=\"zz\"");
  RobotFolder folder;
  Runtime runtime;
  Scene scene(runtime);
  EXPECT_FALSE(loadArm(scene, folder, armScene(folder, urdf, "", "", "0 0 0")));
  EXPECT_NE(problems(scene.log()).find("mimics 'zz'"), std::string::npos) << problems(scene.log());
}

}  // namespace
}  // namespace stroma::test
