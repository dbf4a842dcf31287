// SPDX-License-Identifier: MIT
// The scenes of scenes/tensormass run 100 steps without a warning, and show what the models
// are for: under the same load, the linear tensor-mass cylinder swells where it rotates, the
// St Venant-Kirchhoff one much less, and less again with the incompressibility penalty (seed
// 004, table 2, whose figures for our mesh and load are printed).
#include <gtest/gtest.h>

#include <filesystem>

#include "TensorMassTestScenes.h"
#include "topology/Topology.h"

namespace stroma::test {
namespace {

struct CylinderResult {
  double topDisplacement;  // mean x displacement of the top face (m)
  double volumeChange;     // (V - V0) / V0 of the whole cylinder
};

CylinderResult measure(Scene& scene, const std::string& node) {
  const auto* dofs = objectAt<MechanicalState<Vec3Types>>(scene, "/root/" + node + "/dofs");
  const auto* topology = objectAt<Topology>(scene, "/root/" + node + "/topology");
  const auto& x = dofs->readCoord(VecId::position());
  const auto& rest = dofs->readCoord(VecId::restPosition());
  const auto volume = [&](const std::vector<Vec3d>& p) {
    double v = 0;
    for (const Tetrahedron& t : topology->tetrahedra())
      v += (p[t[1]] - p[t[0]]).dot((p[t[2]] - p[t[0]]).cross(p[t[3]] - p[t[0]])) / 6;
    return v;
  };
  double top = 0;
  int count = 0;
  for (std::size_t i = 0; i < x.size(); ++i)
    if (rest[i].y() > 0.099) {
      top += x[i].x() - rest[i].x();
      ++count;
    }
  return {top / count, volume(x) / volume(rest) - 1};
}

TEST(TensorMassScenes, CylinderBendsAndTheLinearModelSwells) {
  const std::filesystem::path file =
      std::filesystem::path(STROMA_SOURCE_DIR) / "scenes/tensormass/Cylinder.scn";
  Runtime runtime;
  Scene scene(runtime);
  ASSERT_TRUE(scene.loadFile(file)) << describe(scene.log());
  for (int i = 0; i < 100; ++i) ASSERT_TRUE(scene.step()) << describe(scene.log());
  EXPECT_EQ(scene.log().count(MessageLevel::error) + scene.log().count(MessageLevel::warning), 0u)
      << describe(scene.log());

  const CylinderResult linear = measure(scene, "Linear");
  const CylinderResult stvk = measure(scene, "StVK");
  const CylinderResult incompressible = measure(scene, "StVKIncompressible");
  std::printf(
      "[ cylinder ] top displacement (m) / volume change: linear %.4f / %+.2f %%, StVK "
      "%.4f / %+.2f %%, StVK + penalty %.4f / %+.2f %% (seed 004 table 2, largest load: "
      "63 %%, 2 %%, 1 %%)\n",
      linear.topDisplacement, 100 * linear.volumeChange, stvk.topDisplacement,
      100 * stvk.volumeChange, incompressible.topDisplacement, 100 * incompressible.volumeChange);
  // All three bend to the right by a good part of their height (0.1 m).
  for (const CylinderResult& r : {linear, stvk, incompressible}) EXPECT_GT(r.topDisplacement, 0.02);
  // The linear model swells by far the most; the penalty reduces the StVK volume change.
  EXPECT_GT(linear.volumeChange, 3 * std::abs(stvk.volumeChange));
  EXPECT_LT(std::abs(incompressible.volumeChange), std::abs(stvk.volumeChange));
}

}  // namespace
}  // namespace stroma::test
