// SPDX-License-Identifier: MIT
// ArticulatedBodyMass: the joint-space mass of the 2-link arm equals the textbook double
// pendulum's; released 0.5 rad off hanging at both joints, the undamped arm keeps its energy
// (Newmark's average acceleration to 3e-3 of m g reach over 10 s at dt = 1 ms; implicit Euler
// loses energy by its numerical damping, measured and bounded); released horizontal (chaotic),
// the energy error shrinks with the step.
#include <cstdio>

#include "plugins/URDF/URDFTestRobots.h"
#include "simulation/Mass.h"

namespace stroma::test {
namespace {

TEST(ArticulatedBodyMass, MassMatrixIsTheDoublePendulums) {
  RobotFolder folder;
  Runtime runtime;
  Scene scene(runtime);
  ArmOptions arm;
  arm.inertia = 0.02;
  ASSERT_TRUE(loadArm(scene, folder, armScene(folder, twoLinkArm(arm), "")))
      << problems(scene.log());
  auto* mass = findInScene<Mass<Vec1Types>>(scene.root());
  ASSERT_NE(mass, nullptr);
  const double m = 1, L = 0.5, c = L / 2, I = 0.02;
  for (double q2 : {0.0, 0.7, -2.1}) {
    auto& q = mass->mstate()->writeCoord(VecId::position());
    q = {Vec1d(0.3), Vec1d(q2)};
    // M11 = I1 + m c^2 + I2 + m (L^2 + c^2 + 2 L c cos q2), M12 = I2 + m (c^2 + L c cos q2),
    // M22 = I2 + m c^2 (about y; the links' x and z inertias do not enter a planar motion).
    const double M11 = 2 * I + m * c * c + m * (L * L + c * c + 2 * L * c * std::cos(q2));
    const double M12 = I + m * (c * c + L * c * std::cos(q2));
    const double M22 = I + m * c * c;
    // M v by addMDx, for v = e1 and e2.
    for (int column = 0; column < 2; ++column) {
      std::vector<Vec1d> v(2, Vec1d::Zero()), f(2, Vec1d::Zero());
      v[column][0] = 1;
      mass->addMDx(f, v, 1.0);
      EXPECT_NEAR(f[0][0], column == 0 ? M11 : M12, 1e-12);
      EXPECT_NEAR(f[1][0], column == 0 ? M12 : M22, 1e-12);
    }
  }
}

// The loader's armature (rotor inertia) adds to each diagonal entry of M.
TEST(ArticulatedBodyMass, ArmatureAddsToTheDiagonal) {
  std::vector<Vec1d> without, with;
  for (const std::string& armature : {"0", "0.1"}) {
    RobotFolder folder;
    Runtime runtime;
    Scene scene(runtime);
    ASSERT_TRUE(loadArm(scene, folder,
                        armScene(folder, twoLinkArm(), "", "", "0 0 -9.81",
                                 "armature=\"" + armature + "\"")))
        << problems(scene.log());
    auto* mass = findInScene<Mass<Vec1Types>>(scene.root());
    ASSERT_NE(mass, nullptr);
    std::vector<Vec1d> f(2, Vec1d::Zero());
    mass->addMDx(f, {Vec1d(1.0), Vec1d(0.0)}, 1.0);
    (armature == "0" ? without : with) = f;
  }
  EXPECT_NEAR(with[0][0] - without[0][0], 0.1, 1e-12);  // M11 + armature
  EXPECT_NEAR(with[1][0] - without[1][0], 0.0, 1e-12);  // M21 unchanged
}

struct EnergyRun {
  double maxDrift = 0;    // max |E(t) - E(0)| / (total mass x g x reach)
  double finalDrift = 0;  // (E(10 s) - E(0)) / the same
};

// The arm (rods of 1 kg, 0.5 m, 0.01 kg m^2 about their center) released from rest at joint
// values `start` ("q1 q2"; hanging straight down is q1 = pi/2, q2 = 0), 10 s.
EnergyRun runPendulum(const std::string& solver, const std::string& start, double dt = 1e-3) {
  RobotFolder folder;
  Runtime runtime;
  Scene scene(runtime);
  ArmOptions arm;
  arm.inertia = 0.01;
  EnergyRun run;
  std::string xml = armScene(folder, twoLinkArm(arm), solver + "<SparseLDLSolver/>", "",
                             "0 0 -9.81", "initialJoints=\"" + start + "\"");
  xml.replace(xml.find("dt=\"0.001\""), 10, "dt=\"" + std::to_string(dt) + "\"");
  if (!loadArm(scene, folder, xml)) {
    ADD_FAILURE() << problems(scene.log());
    return run;
  }
  auto* mass = findInScene<Mass<Vec1Types>>(scene.root());
  if (!mass) {
    ADD_FAILURE() << "no mass";
    return run;
  }
  MechanicalParams mp;
  auto energy = [&] {
    return mass->kineticEnergy(mass->mstate()->readDeriv(VecId::velocity())) +
           mass->potentialEnergy(mp, mass->mstate()->readCoord(VecId::position()));
  };
  const double scale = 2 * 1.0 * 9.81 * 1.0;
  const double e0 = energy();
  double maxKinetic = 0;
  for (int step = 0; step < static_cast<int>(std::lround(10 / dt)); ++step) {
    if (!scene.step()) {
      ADD_FAILURE() << problems(scene.log());
      return run;
    }
    run.maxDrift = std::max(run.maxDrift, std::abs(energy() - e0) / scale);
    maxKinetic = std::max(maxKinetic, mass->kineticEnergy(mass->mstate()->readDeriv(VecId::velocity())));
  }
  run.finalDrift = (energy() - e0) / scale;
  EXPECT_GT(maxKinetic, 0.1 * scale * 0.1) << "the arm swung";
  return run;
}

// From 0.5 rad off the hanging position at each joint (a swing with both links moving).
TEST(ArticulatedBodyMass, UndampedDoublePendulumKeepsItsEnergy) {
  const std::string start = std::to_string(M_PI / 2 - 0.5) + " 0.5";
  const EnergyRun newmark = runPendulum("<NewmarkImplicitSolver/>", start);
  const EnergyRun euler =
      runPendulum("<EulerImplicitSolver rayleighStiffness=\"0\" rayleighMass=\"0\"/>", start);
  std::printf("energy drift over 10 s at dt = 1 ms (fraction of m g reach): Newmark max %.3g "
              "(final %.3g); implicit Euler max %.3g (final %.3g)\n",
              newmark.maxDrift, newmark.finalDrift, euler.maxDrift, euler.finalDrift);
  EXPECT_LT(newmark.maxDrift, 3e-3);  // measured 1.44e-3
  // Implicit Euler damps (numerical damping of order h omega per period): the energy goes down.
  EXPECT_LT(euler.finalDrift, 0.0);
  EXPECT_LT(euler.maxDrift, 0.05);  // measured 1.37e-2
}

// Released horizontal (chaotic, fast swings through the hanging position): the Coriolis force
// and M(q) are taken at the start of each step, a first-order error that shrinks with dt.
TEST(ArticulatedBodyMass, ChaoticDoublePendulumEnergyErrorShrinksWithTheStep) {
  const EnergyRun coarse = runPendulum("<NewmarkImplicitSolver/>", "0 0", 1e-3);
  const EnergyRun fine = runPendulum("<NewmarkImplicitSolver/>", "0 0", 2.5e-4);
  std::printf("released horizontal: energy drift %.3g at dt = 1 ms, %.3g at 0.25 ms\n",
              coarse.maxDrift, fine.maxDrift);
  EXPECT_LT(fine.maxDrift, coarse.maxDrift / 4);
  EXPECT_LT(fine.maxDrift, 0.05);
}

}  // namespace
}  // namespace stroma::test
