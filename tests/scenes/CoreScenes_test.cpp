// SPDX-License-Identifier: MIT
// The SOFA scenes of ../shared/sofa/core-scenes.txt (they use only the kernel and the
// mechanics core) load and run 100 steps unmodified, without an error and with finite states;
// a few of them also show the physics they are about: the MatrixAssembly beams give the same
// motion whichever way the system is built and solved, the beams of the FEM examples hang from
// their fixed ends, bend the same way under every corotational method, and lose energy under
// Rayleigh damping.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "core/Node.h"
#include "core/PathResolver.h"
#include "core/Runtime.h"
#include "core/StateTypes.h"
#include "plugins/TestPlugin/TestSupport.h"
#include "scenes/SceneLists.h"
#include "simulation/MechanicalOperations.h"
#include "simulation/MechanicalState.h"
#include "simulation/Scene.h"

namespace stroma::test {
namespace {

namespace fs = std::filesystem;

const fs::path kSofaDir = fs::path(STROMA_SHARED_DIR) / "sofa";

std::vector<std::string> coreScenes() { return readSceneList(kSofaDir / "core-scenes.txt"); }

class CoreScenes : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!fs::is_regular_file(kSofaDir / "core-scenes.txt"))
      GTEST_SKIP() << "SOFA's core scenes are not at " << kSofaDir
                   << " (the shared test data lives beside the clone)";
    runtime.addDataDirectory(kSofaDir / "share");
    runtime.addDataDirectory(kSofaDir / "examples");
  }

  /// Loads `scene` (relative to ../shared/sofa), runs `steps` steps; the scene stays loaded.
  std::unique_ptr<Scene> runScene(const std::string& scene, int steps) {
    auto s = std::make_unique<Scene>(runtime);
    if (!s->loadFile(kSofaDir / scene)) {
      ADD_FAILURE() << scene << " does not load:\n" << describe(s->log());
      return nullptr;
    }
    for (int i = 0; i < steps; ++i)
      if (!s->step()) {
        ADD_FAILURE() << scene << " failed at step " << i << ":\n" << describe(s->log());
        return nullptr;
      }
    return s;
  }

  Runtime runtime;
};

/// Positions of the Vec3d state at `path`, and the indices fixed by `constraint`.
std::vector<Vec3d> positions(Scene& scene, const std::string& path, VecId id = VecId::position()) {
  std::string why;
  auto* state =
      dynamic_cast<MechanicalState<Vec3Types>*>(resolveObjectPath(scene.root(), path, why));
  EXPECT_NE(state, nullptr) << path << ": " << why;
  return state ? state->readCoord(id) : std::vector<Vec3d>{};
}

std::vector<unsigned> indicesOf(Scene& scene, const std::string& path) {
  std::string why;
  Base* object = resolveObjectPath(scene.root(), path, why);
  EXPECT_NE(object, nullptr) << path << ": " << why;
  std::vector<unsigned> indices;
  if (!object) return indices;
  std::istringstream in(object->findData("indices")->valueText());
  for (unsigned i; in >> i;) indices.push_back(i);
  return indices;
}

double largestDistance(const std::vector<Vec3d>& a, const std::vector<Vec3d>& b) {
  EXPECT_EQ(a.size(), b.size());
  double d = 0;
  for (std::size_t i = 0; i < a.size() && i < b.size(); ++i) d = std::max(d, (a[i] - b[i]).norm());
  return d;
}

TEST_F(CoreScenes, EachRuns100StepsWithoutError) {
  const std::vector<std::string> scenes = coreScenes();
  ASSERT_FALSE(scenes.empty());
  int passed = 0;
  for (const std::string& name : scenes) {
    SCOPED_TRACE(name);
    Scene scene(runtime);
    const bool loaded = scene.loadFile(kSofaDir / name);
    if (!loaded) {
      ADD_FAILURE() << "does not load:\n" << describe(scene.log());
      continue;
    }
    bool stepped = true;
    for (int i = 0; i < 100 && stepped; ++i) stepped = scene.step();
    EXPECT_TRUE(stepped) << describe(scene.log());
    EXPECT_EQ(scene.log().errorCount(), 0u) << describe(scene.log());
    // Every state is finite (the solvers check it too; this holds them to it).
    bool finite = true;
    MechanicalOperations mop(scene.root(), scene.timing());
    for (const BaseMechanicalState* state : mop.independentStates()) {
      std::size_t where = 0;
      finite &= std::isfinite(state->vMaxAbs(VecId::position(), where)) &&
                std::isfinite(state->vMaxAbs(VecId::velocity(), where));
    }
    EXPECT_TRUE(finite);
    const std::size_t warnings = scene.log().count(MessageLevel::warning);
    std::printf("[ core     ] %-80s %s, %zu warnings\n", name.c_str(),
                stepped && finite && scene.log().errorCount() == 0 ? "ran 100 steps" : "FAILED",
                warnings);
    passed += stepped && finite && scene.log().errorCount() == 0;
  }
  std::printf("[ core     ] %d of %zu scenes ran 100 steps without an error\n", passed,
              scenes.size());
}

TEST_F(CoreScenes, MatrixAssemblyVariantsTakeTheSameSteps) {
  // The same cantilever (truthcylinder1.msh, corotational tetrahedra, backward Euler) with the
  // system matrix-free, assembled in scalars or 3x3 blocks, solved by CG (33 iterations) or by
  // LDL^T. Assembled or not, CG does the same arithmetic on the same matrix: equal to
  // round-off. The direct solves are exact; the CG ones stop at a relative residual of about
  // 2e-3 each step, so the two families agree to a small fraction of the motion.
  const std::string folder = "examples/Benchmark/Performance/MatrixAssembly/";
  std::map<std::string, std::vector<Vec3d>> final;
  std::vector<Vec3d> rest;
  std::vector<unsigned> fixed;
  for (const char* variant :
       {"matrixfreeCG", "assembledCG", "assembledCG_blocs", "direct", "direct_blocs"}) {
    const auto scene = runScene(folder + "MatrixAssembly_" + variant + ".scn", 100);
    ASSERT_NE(scene, nullptr);
    final[variant] = positions(*scene, "@/DeformableObject/dofs");
    rest = positions(*scene, "@/DeformableObject/dofs", VecId::restPosition());
  }
  const double motion = largestDistance(final["direct"], rest);
  EXPECT_GT(motion, 1e-3);  // the beam fell under gravity (-1.8, 0, 100)
  std::printf("[ core     ] MatrixAssembly: largest displacement %.4g; CG vs LDL %.3g\n", motion,
              largestDistance(final["matrixfreeCG"], final["direct"]));
  EXPECT_LT(largestDistance(final["assembledCG"], final["matrixfreeCG"]), 1e-9 * motion);
  EXPECT_LT(largestDistance(final["assembledCG_blocs"], final["matrixfreeCG"]), 1e-9 * motion);
  EXPECT_LT(largestDistance(final["direct_blocs"], final["direct"]), 1e-12 * motion);
  EXPECT_LT(largestDistance(final["matrixfreeCG"], final["direct"]), 0.01 * motion);
  // The 54 fixed indices of the scene have not moved; the rest moved along gravity.
  const std::vector<unsigned> fixedIndices = {
      0,  1,  2,  3,  4,  5,  6,  7,  8,  9,  10, 11, 12,  13,  14,  15,  16,  17,
      18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30,  31,  32,  33,  34,  35,
      36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 268, 269, 270, 271, 343, 345};
  for (unsigned i : fixedIndices) EXPECT_EQ(final["direct"][i], rest[i]) << "fixed point " << i;
  Vec3d meanDisplacement = Vec3d::Zero();
  for (std::size_t i = 0; i < rest.size(); ++i) meanDisplacement += final["direct"][i] - rest[i];
  EXPECT_GT(meanDisplacement.z(), 0);  // gravity is mostly +z
}

/// Kinetic plus potential (elastic and gravity) energy of the bodies under `node`.
double mechanicalEnergy(Scene& scene, const std::string& node) {
  std::string why;
  auto* n = dynamic_cast<Node*>(resolveObjectPath(scene.root(), node, why));
  EXPECT_NE(n, nullptr) << node << ": " << why;
  if (!n) return 0;
  MechanicalOperations mop(*n, scene.timing());
  return mop.kineticEnergy() + mop.potentialEnergy(MechanicalParams{});
}

/// Mean displacement of the points of largest rest z (the free end of a beam along z).
Vec3d tipDisplacement(const std::vector<Vec3d>& x, const std::vector<Vec3d>& rest) {
  double end = -1e300;
  for (const Vec3d& p : rest) end = std::max(end, p.z());
  Vec3d sum = Vec3d::Zero();
  int count = 0;
  for (std::size_t i = 0; i < rest.size(); ++i)
    if (rest[i].z() > end - 1e-9) {
      sum += x[i] - rest[i];
      ++count;
    }
  return sum / count;
}

/// The beams BeamFEM_<beam> of `scene` (run 100 steps), which is run 100 steps further.
void checkHangingBeams(const std::unique_ptr<Scene>& scene, const std::string& name,
                       const std::vector<std::string>& beams) {
  ASSERT_NE(scene, nullptr);
  std::map<std::string, Vec3d> tip;
  std::map<std::string, double> energy;
  for (const std::string& beam : beams) {
    SCOPED_TRACE(beam);
    const std::string node = "@/BeamFEM_" + beam;
    const std::vector<Vec3d> x = positions(*scene, node + "/mechanicalObject");
    const std::vector<Vec3d> rest =
        positions(*scene, node + "/mechanicalObject", VecId::restPosition());
    const std::vector<unsigned> fixed = indicesOf(*scene, node + "/fixedProjectiveConstraint");
    ASSERT_FALSE(x.empty());
    EXPECT_EQ(fixed.size(), 25u);  // the 5 x 5 points of the z = 0 face
    for (unsigned i : fixed) EXPECT_EQ(x[i], rest[i]) << "fixed point " << i;
    tip[beam] = tipDisplacement(x, rest);
    energy[beam] = mechanicalEnergy(*scene, node);
    EXPECT_LT(tip[beam].y(), -1.0) << "the free end hangs down (gravity -9 y)";
  }
  // Energy from step 100 to 200. Backward Euler with Rayleigh damping only dissipates when
  // the force is the gradient of an energy, as for small, polar and svd (for polar and svd the
  // derivative of the rotation does no work). Method large takes the rotation from the
  // element's edges, which is not exactly such a gradient: its energy may rise a little in a
  // step while the beam turns through large rotations, by less than 5 % of what the
  // step-100-to-200 swing dissipates (2.2 % measured on the TetrahedralCorotational beam,
  // which bends through 90 degrees).
  std::map<std::string, double> start = energy, largestRise;
  for (int step = 0; step < 100; ++step) {
    ASSERT_TRUE(scene->step()) << describe(scene->log());
    for (const std::string& beam : beams) {
      const double e = mechanicalEnergy(*scene, "@/BeamFEM_" + beam);
      largestRise[beam] = std::max(largestRise[beam], e - energy[beam]);
      energy[beam] = e;
    }
  }
  for (const std::string& beam : beams) {
    const double dissipated = start[beam] - energy[beam];
    std::printf(
        "[ core     ] %s %s: tip displacement at 1 s (%.4g %.4g %.4g); energy %.6g -> "
        "%.6g from 1 s to 2 s, largest rise in a step %.3g\n",
        name.c_str(), beam.c_str(), tip[beam].x(), tip[beam].y(), tip[beam].z(), start[beam],
        energy[beam], largestRise[beam]);
    EXPECT_GT(dissipated, 0) << beam;
    const double allowed = beam == "LARGE" ? 0.05 * dissipated : 1e-9 * std::abs(start[beam]);
    EXPECT_LE(largestRise[beam], allowed) << beam << ": the energy grew in a step";
  }
  // The corotational methods agree with each other (the rotations differ only by the strain
  // in the element, small here) and differ from the linear one, which stretches in rotation.
  for (const std::string& beam : beams)
    if (beam != "SMALL" && beam != "LARGE" && tip.count("LARGE")) {
      EXPECT_LT((tip[beam] - tip["LARGE"]).norm(), 0.05 * tip["LARGE"].norm()) << beam;
    }
}

TEST_F(CoreScenes, FemBeamsHangFromTheirFixedEndsAndLoseEnergy) {
  // Beams of 5x5x20 points split into tetrahedra, fixed at z = 0, under gravity -9 y with
  // Rayleigh damping and backward Euler: their ends hang down, the fixed face stays, the
  // corotational methods agree, and the energy only decreases once they swing.
  for (const auto& [name, beams] : std::map<std::string, std::vector<std::string>>{
           {"examples/Component/SolidMechanics/FEM/TetrahedronFEMForceField.scn",
            {"SMALL", "LARGE", "POLAR", "SVD"}},
           {"examples/Component/SolidMechanics/FEM/TetrahedralCorotationalFEMForceField.scn",
            {"SMALL", "LARGE", "POLAR"}}}) {
    SCOPED_TRACE(name);
    checkHangingBeams(runScene(name, 100), name, beams);
  }
}

}  // namespace
}  // namespace stroma::test
