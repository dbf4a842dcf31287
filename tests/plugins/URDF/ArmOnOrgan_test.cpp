// SPDX-License-Identifier: MIT
// scenes/robot/ArmOnOrgan.scn: the 6-axis arm presses its instrument into the organ, contact
// and joint limits solved as Lagrange multipliers. Once the press is held, the organ pushes the
// tip up (its constraintForce, the force a haptic device would render), and in joint space that
// force, carried through the link mappings (J^T f, the joints' constraintForce), balances the
// drive's torques: the arm is at rest, with neither gravity (compensated) nor a stop acting.
#include <cmath>
#include <filesystem>
#include <sstream>

#include "plugins/URDF/URDFTestRobots.h"

namespace stroma::test {
namespace {

std::vector<double> vectorAt(const Scene& scene, const std::string& path, const std::string& field) {
  std::string why;
  const Base* object = resolveObjectPath(scene.root(), "@" + path, why);
  EXPECT_NE(object, nullptr) << why;
  const BaseData* data = object ? object->findData(field) : nullptr;
  EXPECT_NE(data, nullptr) << path << "." << field;
  std::vector<double> values;
  if (!data) return values;
  std::istringstream in(data->valueText());
  for (double v; in >> v;) values.push_back(v);
  return values;
}

TEST(ArmOnOrgan, ContactForceOnTheTipBalancesTheDriveInJointSpace) {
  const auto file = std::filesystem::path(STROMA_SOURCE_DIR) / "scenes/robot/ArmOnOrgan.scn";
  Runtime runtime;
  Scene scene(runtime);
  ASSERT_TRUE(scene.loadFile(file)) << problems(scene.log());
  double largest = 0;
  for (int i = 0; i < 120; ++i) {
    ASSERT_TRUE(scene.step()) << problems(scene.log());
    largest = std::max(largest, vectorAt(scene, "/root/Robot/Tip/tip", "constraintForce")[1]);
  }
  EXPECT_EQ(problems(scene.log()), "");
  // The organ pushes the tip up (+y), a few newtons (the drive's springs, 400 N m/rad, pull the
  // tip 2.5 cm into the organ of E = 30 kPa), with little sideways friction.
  const std::vector<double> f = vectorAt(scene, "/root/Robot/Tip/tip", "constraintForce");
  ASSERT_EQ(f.size(), 3u);
  EXPECT_GT(f[1], 1.0);
  EXPECT_LT(f[1], 10.0);
  EXPECT_LT(std::hypot(f[0], f[2]), 0.05 * f[1]);
  EXPECT_LT(largest, 1.5 * f[1]);  // a Lagrangian contact lands without a penalty's spike
  // At rest: tau_drive + J^T f = 0, joint by joint, to 1e-3 of the largest torque.
  const std::vector<double> contact = vectorAt(scene, "/root/Robot/arm6/joints", "constraintForce");
  const std::vector<double> drive = vectorAt(scene, "/root/Robot/drive", "torques");
  ASSERT_EQ(contact.size(), 6u);
  ASSERT_EQ(drive.size(), 6u);
  double scale = 0;
  for (double t : drive) scale = std::max(scale, std::abs(t));
  ASSERT_GT(scale, 0.1);
  for (std::size_t j = 0; j < 6; ++j)
    EXPECT_NEAR(contact[j] + drive[j], 0.0, 1e-3 * scale) << "joint " << j;
  // No joint is on its stop.
  for (double t : vectorAt(scene, "/root/Robot/arm6/limits", "forces")) EXPECT_EQ(t, 0.0);
  std::printf("tip force %.6f %.6f %.6f N (largest up %.6f); shoulder: contact %.6f, drive %.6f N m\n",
              f[0], f[1], f[2], largest, contact[1], drive[1]);
}

}  // namespace
}  // namespace stroma::test
