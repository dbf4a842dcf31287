// SPDX-License-Identifier: MIT
// The scenes of scenes/precomputed load and run without a warning, and give what the model
// promises: the bar equals the static solve of the same small-strain tetrahedra, the pulled
// organ moves its pulled point along the force and not its attachment, the imposed points of
// the organ reach their displacements and the imposed work d . r is positive (the compliance
// of the imposed points is positive definite).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "plugins/SolidMechanics/FemTestScenes.h"
#include "plugins/TestPlugin/TestSupport.h"

namespace stroma::test {
namespace {

std::string sceneText(const std::string& name) {
  std::ifstream in(std::filesystem::path(STROMA_SOURCE_DIR) / "scenes/precomputed" / name);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

const std::vector<Vec3d>& positionsOf(Scene& scene, const std::string& path) {
  static const std::vector<Vec3d> none;
  const auto* dofs = objectAt<MechanicalState<Vec3Types>>(scene, path);
  return dofs ? dofs->readCoord(VecId::position()) : none;
}

bool runQuietly(Scene& scene, const std::filesystem::path& file, int steps) {
  if (!scene.loadFile(file)) {
    ADD_FAILURE() << describe(scene.log());
    return false;
  }
  for (int i = 0; i < steps; ++i)
    if (!scene.step()) {
      ADD_FAILURE() << describe(scene.log());
      return false;
    }
  EXPECT_EQ(scene.log().count(MessageLevel::error) + scene.log().count(MessageLevel::warning), 0u)
      << describe(scene.log());
  return true;
}

TEST(PrecomputedScenes, BarEqualsTheStaticFemSolve) {
  const auto dir = std::filesystem::path(STROMA_SOURCE_DIR) / "scenes/precomputed";
  Runtime rt;
  Scene scene(rt);
  ASSERT_TRUE(runQuietly(scene, dir / "Bar.scn", 3));
  // The same scene with the model replaced by the FEM force field and a static solve.
  std::string fem = sceneText("Bar.scn");
  const auto at = fem.find("<PrecomputedLinearModel");
  ASSERT_NE(at, std::string::npos);
  fem.replace(at, fem.find("/>", at) + 2 - at,
              "<StaticSolver newton_iterations=\"1\"/><SparseLDLSolver/>"
              "<TetrahedronFEMForceField method=\"small\" youngModulus=\"5000\" "
              "poissonRatio=\"0.45\"/>");
  Runtime rtFem;
  Scene reference(rtFem);
  ASSERT_TRUE(reference.loadString(fem, dir / "BarFem.scn")) << describe(reference.log());
  ASSERT_TRUE(reference.step());
  const auto& x = positionsOf(scene, "/Bar/dofs");
  const auto& xRef = positionsOf(reference, "/Bar/dofs");
  ASSERT_EQ(x.size(), 192u);
  ASSERT_EQ(xRef.size(), 192u);
  const auto& rest =
      objectAt<MechanicalState<Vec3Types>>(scene, "/Bar/dofs")->readCoord(VecId::restPosition());
  double error = 0, norm = 0;
  for (size_t i = 0; i < x.size(); ++i) {
    error += (x[i] - xRef[i]).squaredNorm();
    norm += (xRef[i] - rest[i]).squaredNorm();
  }
  EXPECT_LT(std::sqrt(error / norm), 1e-8);
  const double tip = x[191].y() - rest[191].y();
  // Linear tetrahedra three cells across, nu = 0.45, lock: the bar is about twice as stiff as
  // the Euler-Bernoulli cantilever (F L^3 / 3 E I = 0.0167 m); see SparseGridValidation's
  // tetrahedra ratios on coarse beams.
  std::printf("[ bar ] tip deflection %.4f m (cantilever F L^3 / 3 E I: 0.0167 m)\n", tip);
  EXPECT_LT(tip, -0.3 * 0.0167);
  EXPECT_GT(tip, -0.0167);
}

TEST(PrecomputedScenes, OrganPulledAndImposed) {
  const auto dir = std::filesystem::path(STROMA_SOURCE_DIR) / "scenes/precomputed";
  {
    Runtime rt;
    Scene scene(rt);
    ASSERT_TRUE(runQuietly(scene, dir / "OrganPulled.scn", 3));
    const auto* dofs = objectAt<MechanicalState<Vec3Types>>(scene, "/Organ/dofs");
    const auto& x = dofs->readCoord(VecId::position());
    const auto& rest = dofs->readCoord(VecId::restPosition());
    // Pulled down with 0.2 N: positive work, the pulled point goes down.
    EXPECT_LT(x[302].y() - rest[302].y(), -1e-3);
    for (unsigned i : {348u, 364u, 642u}) EXPECT_EQ(x[i], rest[i]) << "attached point " << i;
  }
  Runtime rt;
  Scene scene(rt);
  ASSERT_TRUE(runQuietly(scene, dir / "OrganImposed.scn", 10));  // t = 0.5 s: half way
  const auto* dofs = objectAt<MechanicalState<Vec3Types>>(scene, "/Organ/dofs");
  const auto& x = dofs->readCoord(VecId::position());
  const auto& rest = dofs->readCoord(VecId::restPosition());
  const std::vector<unsigned> imposed{10,  11,  12,  13,  14,  58,  60,  102, 103, 202,
                                      210, 228, 229, 234, 235, 236, 248, 270, 278, 280};
  const Vec3d d(-0.005, -0.0025, 0);
  for (unsigned i : imposed) EXPECT_LT((x[i] - rest[i] - d).norm(), 1e-12) << "point " << i;
  auto* model = objectAt<Base>(scene, "/Organ/model");
  ASSERT_NE(model, nullptr);
  const auto* reactions =
      dynamic_cast<const Data<std::vector<Vec3d>>*>(model->findData("reactionForces"));
  ASSERT_NE(reactions, nullptr);
  ASSERT_EQ(reactions->value().size(), imposed.size());
  double work = 0;
  Vec3d total = Vec3d::Zero();
  for (const Vec3d& r : reactions->value()) {
    work += d.dot(r);
    total += r;
  }
  std::printf("[ organ ] 20 points pushed by %.4f m: total force %.4f %.4f %.4f N\n", d.norm(),
              total.x(), total.y(), total.z());
  EXPECT_GT(work, 0);
}

}  // namespace
}  // namespace stroma::test
