// SPDX-License-Identifier: MIT
// JointActuatorForceField: one joint of known inertia driven by a PD spring toward a step
// target follows the damped oscillator's closed form (to 1% of the target); its torque output is the drive's
// -k (q - target) - d qdot; targets interpolate between key times and come from a CSV file.
#include "plugins/URDF/URDFTestRobots.h"
#include "simulation/ForceField.h"

namespace stroma::test {
namespace {

// One link (1 kg at 0.25 m, 0.01 kg m^2 about its center): J = 0.01 + 1 x 0.25^2 about the
// joint. No gravity. Target 0.5 rad from t = 0; k = 10 N m/rad, d = 0.3 N m s/rad.
TEST(JointActuatorForceField, PDJointFollowsTheDampedOscillator) {
  RobotFolder folder;
  Runtime runtime;
  Scene scene(runtime);
  ArmOptions arm;
  arm.inertia = 0.01;
  arm.secondLink = false;
  const double J = 0.01 + 0.25 * 0.25, k = 10, d = 0.3, target = 0.5;
  ASSERT_TRUE(loadArm(
      scene, folder,
      armScene(folder, twoLinkArm(arm), "<NewmarkImplicitSolver/><SparseLDLSolver/>",
               "<JointActuatorForceField name=\"pd\" mstate=\"@arm/joints\" stiffness=\"10\" "
               "damping=\"0.3\" keyTimes=\"0\" keyTargets=\"0.5\"/>",
               "0 0 0")))
      << problems(scene.log());
  EXPECT_EQ(problems(scene.log()), "");
  auto* pd = findInScene<ForceField<Vec1Types>>(scene.root());
  ASSERT_NE(pd, nullptr);
  const double wn = std::sqrt(k / J), zeta = d / (2 * std::sqrt(k * J));
  const double wd = wn * std::sqrt(1 - zeta * zeta);
  double worst = 0;
  for (int step = 1; step <= 2000; ++step) {
    ASSERT_TRUE(scene.step()) << problems(scene.log());
    const double t = step * 1e-3;
    const double closed =
        target * (1 - std::exp(-zeta * wn * t) *
                          (std::cos(wd * t) + zeta / std::sqrt(1 - zeta * zeta) * std::sin(wd * t)));
    worst = std::max(worst, std::abs(pd->mstate()->readCoord(VecId::position())[0][0] - closed));
  }
  std::printf("PD step response: max |q - closed form| = %.3g rad over 2 s (target %.2g rad)\n",
              worst, target);
  // Measured 2.1e-3 rad: Newmark takes the drive's damping force at the start of each step.
  EXPECT_LT(worst, 1e-2 * target);
  // The torque output: the drive's torque at the last evaluation (the start of the last step).
  const double q = pd->mstate()->readCoord(VecId::position())[0][0];
  const double qdot = pd->mstate()->readDeriv(VecId::velocity())[0][0];
  const auto* torques = dynamic_cast<const Data<std::vector<double>>*>(pd->findData("torques"));
  ASSERT_NE(torques, nullptr);
  ASSERT_EQ(torques->value().size(), 1u);
  EXPECT_NEAR(torques->value()[0], -k * (q - target) - d * qdot, 0.05 * k * std::abs(q - target) + 1e-3);
}

TEST(JointActuatorForceField, TargetsInterpolateKeysAndReadACsvFile) {
  RobotFolder folder;
  folder.write("targets.csv", "t, joint1, joint2\n0, 0, 1\n1, 2, 1\n3, 2, -1\n");
  Runtime runtime;
  Scene scene(runtime);
  ASSERT_TRUE(loadArm(scene, folder,
                      armScene(folder, twoLinkArm(), "",
                               "<JointActuatorForceField mstate=\"@arm/joints\" stiffness=\"1\" "
                               "targetFile=\"targets.csv\"/>",
                               "0 0 0")))
      << problems(scene.log());
  auto* pd = findInScene<ForceField<Vec1Types>>(scene.root());
  ASSERT_NE(pd, nullptr);
  // Through the class: the target at a few times.
  struct Sample {
    double t, q0, q1;
  };
  for (const Sample s : {Sample{-1, 0, 1}, Sample{0.5, 1, 1}, Sample{2, 2, 0}, Sample{5, 2, -1}}) {
    // E = 1/2 sum (q - target)^2 at q = (1, 0); the drive takes the node's time.
    scene.root().setTime(s.t);
    MechanicalParams mp;
    const std::vector<Vec1d> q{Vec1d(1.0), Vec1d(0.0)};
    EXPECT_NEAR(pd->potentialEnergy(mp, q), 0.5 * ((1 - s.q0) * (1 - s.q0) + s.q1 * s.q1), 1e-12)
        << "t = " << s.t;
  }
}

}  // namespace
}  // namespace stroma::test
