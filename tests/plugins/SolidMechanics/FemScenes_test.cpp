// SPDX-License-Identifier: MIT
// The FEM scenes of scenes/beam and scenes/organ: each runs 100 steps without a warning, and
// moves as it should (clamped points stay, the free parts fall and stay finite).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "FemTestScenes.h"

namespace stroma::test {
namespace {

struct SceneRun {
  std::vector<Vec3d> rest, x, v;
  std::vector<unsigned> fixed;
};

/// Loads scenes/<name>, runs 100 steps, expects no warning or error; returns the state of
/// `statePath` and the indices fixed by the constraint at `constraintPath`.
SceneRun runScene(const std::string& name, const std::string& statePath,
                  const std::string& constraintPath, int threads = 1) {
  SceneRun run;
  Runtime runtime;
  Scene scene(runtime);
  scene.setThreadCount(threads);
  const std::filesystem::path file = std::filesystem::path(STROMA_SOURCE_DIR) / "scenes" / name;
  const bool loaded = scene.loadFile(file);
  for (int i = 0; loaded && i < 100; ++i) EXPECT_TRUE(scene.step()) << name << " step " << i;
  std::string messages;
  for (const Message& m : scene.log().messages())
    if (m.level == MessageLevel::error || m.level == MessageLevel::warning)
      messages += formatForConsole(m) + '\n';
  EXPECT_TRUE(loaded && messages.empty()) << name << ":\n" << messages;
  if (!loaded) return run;
  auto* state = objectAt<MechanicalState<Vec3Types>>(scene, statePath);
  Base* constraint = objectAt<Base>(scene, constraintPath);
  if (!state || !constraint) return run;
  run.rest = state->readCoord(VecId::restPosition());
  run.x = state->readCoord(VecId::position());
  run.v = state->readDeriv(VecId::velocity());
  std::string why;
  const std::string indices = constraint->findData("indices")->valueText();
  std::istringstream in(indices);
  for (unsigned i; in >> i;) run.fixed.push_back(i);
  return run;
}

void expectClampedAndFinite(const SceneRun& run) {
  EXPECT_FALSE(run.fixed.empty());
  for (unsigned i : run.fixed) EXPECT_EQ(run.x[i], run.rest[i]) << "fixed point " << i;
  for (std::size_t i = 0; i < run.x.size(); ++i)
    EXPECT_TRUE(run.x[i].allFinite() && run.v[i].allFinite()) << "point " << i;
}

/// Vertical displacement of the free end's centre (the points of largest rest x).
double tipDrop(const SceneRun& run) {
  const double end = std::max_element(run.rest.begin(), run.rest.end(), [](auto& a, auto& b) {
                       return a.x() < b.x();
                     })->x();
  double drop = 0;
  int count = 0;
  for (std::size_t i = 0; i < run.rest.size(); ++i)
    if (run.rest[i].x() > end - 1e-9) {
      drop += run.rest[i].y() - run.x[i].y();
      ++count;
    }
  return drop / count;
}

TEST(FemScenes, BeamsBendUnderTheirWeight) {
  // After 1 s the beams still swing about their sag. Linear beam theory gives a static tip
  // deflection of q L^4 / (8 E I) = 0.19 m; measured tip drops at 1 s: tetrahedra 0.096 m,
  // hexahedra 0.186 m (3 tetrahedra or hexahedra through the thickness: the tetrahedra lock
  // more, as in FemValidation's cantilever). Bounds: half to 1.5 times those, and the
  // hexahedral beam lower.
  const SceneRun tetra = runScene("beam/TetraBeam.scn", "@/Beam/dofs", "@/Beam/clamp");
  const SceneRun hexa = runScene("beam/HexaBeam.scn", "@/Beam/dofs", "@/Beam/clamp");
  ASSERT_FALSE(tetra.x.empty() || hexa.x.empty());
  expectClampedAndFinite(tetra);
  expectClampedAndFinite(hexa);
  EXPECT_EQ(tetra.fixed.size(), 16u);
  EXPECT_EQ(hexa.fixed.size(), 16u);
  EXPECT_GT(tipDrop(tetra), 0.048);
  EXPECT_LT(tipDrop(tetra), 0.144);
  EXPECT_GT(tipDrop(hexa), 0.093);
  EXPECT_LT(tipDrop(hexa), 0.28);
  EXPECT_GT(tipDrop(hexa), tipDrop(tetra));
}

TEST(FemScenes, OrganFallsAndHangsFromItsLeftLobe) {
  const SceneRun organ = runScene("organ/Organ.scn", "@/Organ/dofs", "@/Organ/fixed");
  ASSERT_FALSE(organ.x.empty());
  expectClampedAndFinite(organ);
  // Centre of mass: it sags below its rest height, by 0.070 m at 1 s (measured; bounds: half
  // to twice that).
  Vec3d rest = Vec3d::Zero(), now = Vec3d::Zero();
  for (std::size_t i = 0; i < organ.x.size(); ++i) {
    rest += organ.rest[i];
    now += organ.x[i];
  }
  const double sag = (rest - now).y() / static_cast<double>(organ.x.size());
  EXPECT_GT(sag, 0.035);
  EXPECT_LT(sag, 0.14);
}

}  // namespace
}  // namespace stroma::test
