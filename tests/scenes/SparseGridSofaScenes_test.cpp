// SPDX-License-Identifier: MIT
// SOFA's sparse-grid example scenes (../shared/sofa/examples), run 100 steps as copies without
// their collision components (collision comes with a later issue), everything else unchanged:
// - Component/Topology/Container/Grid/SparseGridTopology.scn: the dragon in sparse grids at
//   three resolutions, MeshSpringForceField, each grid held by a BoxConstraint;
// - Tutorials/ForceFields/TutorialForceFieldLiverHexaFEM.scn: HexahedronFEMForceField (polar)
//   on the sparse grid of the liver, points 80, 81 and 166 fixed by index.
// Checked: every position finite at every step, the fixed points exactly where they started,
// the bodies sag under gravity, and the energy is bounded: kinetic energy <= the work of
// gravity since the start (springs and elements store energy >= 0, damping dissipates).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "core/PathResolver.h"
#include "core/Runtime.h"
#include "core/StateTypes.h"
#include "plugins/TestPlugin/TestSupport.h"
#include "simulation/MechanicalState.h"
#include "simulation/Scene.h"

namespace stroma::test {
namespace {

namespace fs = std::filesystem;

const fs::path kSofaDir = fs::path(STROMA_SHARED_DIR) / "sofa";

std::string readText(const fs::path& file) {
  std::ifstream in(file);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

/// Removes every element `<tag ... />` of the text; returns how many.
int eraseElements(std::string& text, const std::string& tag) {
  int count = 0;
  for (auto at = text.find("<" + tag); at != std::string::npos; at = text.find("<" + tag, at)) {
    text.erase(at, text.find("/>", at) + 2 - at);
    ++count;
  }
  return count;
}

/// Removes every `<Node name="name"> ... </Node>` (without nested nodes) of the text.
int eraseNodes(std::string& text, const std::string& name) {
  int count = 0;
  const std::string open = "<Node name=\"" + name + "\"";
  for (auto at = text.find(open); at != std::string::npos; at = text.find(open, at)) {
    text.erase(at, text.find("</Node>", at) + 7 - at);
    ++count;
  }
  return count;
}

/// The scene at `relative` in SOFA's examples without its collision pipeline and its collision
/// nodes; empty when the shared data is absent.
std::string collisionFreeCopy(const std::string& relative, const std::string& collisionNode,
                              int collisionNodes) {
  const fs::path file = kSofaDir / "examples" / relative;
  if (!fs::exists(file)) return {};
  std::string text = readText(file);
  for (const char* tag : {"CollisionPipeline", "BruteForceBroadPhase", "BVHNarrowPhase",
                          "CollisionResponse", "DiscreteIntersection"})
    EXPECT_EQ(eraseElements(text, tag), 1) << tag;
  EXPECT_EQ(eraseNodes(text, collisionNode), collisionNodes);
  for (const char* left : {"<SphereCollisionModel", "<SphereLoader", "<CollisionPipeline"})
    EXPECT_EQ(text.find(left), std::string::npos) << left << " is left";
  return text;
}

MechanicalState<Vec3Types>* stateAt(Scene& scene, const std::string& path) {
  std::string why;
  auto* state =
      dynamic_cast<MechanicalState<Vec3Types>*>(resolveObjectPath(scene.root(), path, why));
  EXPECT_NE(state, nullptr) << path << ": " << why;
  return state;
}

/// One deformable body of a scene: its state, the mass of each of its points, its fixed points.
struct Body {
  Body(std::string path_, double pointMass_, std::vector<unsigned> fixed_)
      : path(std::move(path_)), pointMass(pointMass_), fixed(std::move(fixed_)) {}
  std::string path;
  double pointMass;
  std::vector<unsigned> fixed;
  MechanicalState<Vec3Types>* state = nullptr;
  std::vector<Vec3d> rest;
};

/// Runs `steps` steps and checks the bodies at each: finite, fixed points still, kinetic energy
/// at most the work of gravity g since the start. Returns the largest sag of each body.
std::vector<double> runAndCheck(Scene& scene, std::vector<Body>& bodies, const Vec3d& g,
                                int steps) {
  for (Body& b : bodies) {
    b.state = stateAt(scene, b.path);
    if (!b.state) return {};
    b.rest = b.state->readCoord(VecId::position());
  }
  for (int step = 0; step < steps; ++step) {
    EXPECT_TRUE(scene.step()) << describe(scene.log());
    for (const Body& b : bodies) {
      const auto& x = b.state->readCoord(VecId::position());
      const auto& v = b.state->readDeriv(VecId::velocity());
      double kinetic = 0, work = 0;
      for (std::size_t i = 0; i < x.size(); ++i) {
        if (!x[i].allFinite() || !v[i].allFinite()) {
          ADD_FAILURE() << b.path << " point " << i << " not finite at step " << step;
          return {};
        }
        kinetic += 0.5 * b.pointMass * v[i].squaredNorm();
        work += b.pointMass * g.dot(x[i] - b.rest[i]);
      }
      EXPECT_LE(kinetic, work + 1e-12) << b.path << " step " << step;
      for (unsigned i : b.fixed) EXPECT_EQ(x[i], b.rest[i]) << b.path << " point " << i;
    }
  }
  std::vector<double> sags;
  for (const Body& b : bodies) {
    double sag = 0;
    const auto& x = b.state->readCoord(VecId::position());
    for (std::size_t i = 0; i < x.size(); ++i)
      sag = std::max(sag, g.normalized().dot(x[i] - b.rest[i]));
    sags.push_back(sag);
  }
  return sags;
}

/// Errors, and warnings other than the CG's "did not converge" that the scenes ask for (their
/// iteration counts and thresholds stop CG early, as in SOFA).
std::string unexpectedMessages(const MessageLog& log) {
  std::string out;
  for (const Message& m : log.messages())
    if (m.level == MessageLevel::error ||
        (m.level == MessageLevel::warning && m.componentClass != "CGLinearSolver"))
      out += formatForConsole(m) + '\n';
  return out;
}

std::vector<unsigned> indicesOf(Scene& scene, const std::string& path) {
  std::string why;
  BaseData* d = resolveDataPath(scene.root(), path, why);
  EXPECT_NE(d, nullptr) << path << ": " << why;
  std::vector<unsigned> out;
  if (!d) return out;
  std::istringstream in(d->valueText());
  for (unsigned i; in >> i;) out.push_back(i);
  return out;
}

TEST(SparseGridSofaScenes, SparseGridTopologyDragonsHangFromTheirBoxConstraints) {
  std::string text =
      collisionFreeCopy("Component/Topology/Container/Grid/SparseGridTopology.scn", "Surf", 3);
  if (text.empty()) GTEST_SKIP() << kSofaDir << " is absent";
  ASSERT_NE(text.find("<BoxConstraint"), std::string::npos);
  Runtime runtime;
  runtime.addDataDirectory(kSofaDir / "share");
  Scene scene(runtime);
  ASSERT_TRUE(scene.loadString(text)) << describe(scene.log());
  EXPECT_EQ(unexpectedMessages(scene.log()), "");
  // The three dragons, UniformMass vertexMass="0.5"; their BoxConstraints hold the points of
  // the grid's end at x in [10, 12].
  std::vector<Body> bodies;
  for (const char* node : {"DragonCoarse", "DragonMiddle", "DragonFine"}) {
    Body b(std::string("@/") + node + "/mechanicalObject", 0.5, {});
    // The unnamed components take their class name.
    std::string why;
    Base* constraint =
        resolveObjectPath(scene.root(), std::string("@/") + node + "/boxConstraint", why);
    ASSERT_NE(constraint, nullptr) << why;
    b.fixed = indicesOf(scene, std::string("@/") + node + "/boxConstraint.indices");
    EXPECT_GE(b.fixed.size(), 4u) << node;
    bodies.push_back(b);
  }
  const std::vector<double> sags = runAndCheck(scene, bodies, Vec3d(0, -9, 0), 100);
  ASSERT_EQ(sags.size(), 3u);
  for (std::size_t k = 0; k < 3; ++k) {
    std::printf("[ dragon   ] %s: %zu points, %zu fixed by BoxConstraint, largest sag %.3f\n",
                bodies[k].path.c_str(), bodies[k].rest.size(), bodies[k].fixed.size(), sags[k]);
    EXPECT_GT(sags[k], 0.1) << bodies[k].path;  // hangs from one end, 20 units long
    // The fixed points are at the grid's end x in [10, 12], as the box says.
    for (unsigned i : bodies[k].fixed) {
      EXPECT_GE(bodies[k].rest[i].x(), 10);
      EXPECT_LE(bodies[k].rest[i].x(), 12);
    }
  }
  EXPECT_EQ(unexpectedMessages(scene.log()), "");
}

TEST(SparseGridSofaScenes, LiverHexaFemTutorialSagsFromItsThreePoints) {
  std::string text =
      collisionFreeCopy("Tutorials/ForceFields/TutorialForceFieldLiverHexaFEM.scn", "Surf", 1);
  if (text.empty()) GTEST_SKIP() << kSofaDir << " is absent";
  Runtime runtime;
  runtime.addDataDirectory(kSofaDir / "share");
  Scene scene(runtime);
  ASSERT_TRUE(scene.loadString(text)) << describe(scene.log());
  EXPECT_EQ(unexpectedMessages(scene.log()), "");
  auto* dofs = stateAt(scene, "@/LiverHexaFEM/dofs");
  ASSERT_NE(dofs, nullptr);
  const std::size_t n = dofs->size();
  // UniformMass totalMass="1".
  std::vector<Body> bodies{
      Body("@/LiverHexaFEM/dofs", 1.0 / static_cast<double>(n), {80, 81, 166})};
  const std::vector<double> sags = runAndCheck(scene, bodies, Vec3d(0, -9.81, 0), 100);
  ASSERT_EQ(sags.size(), 1u);
  std::printf("[ liver    ] %zu points, 3 fixed, largest sag %.3f\n", n, sags[0]);
  EXPECT_GT(sags[0], 0.1);
  EXPECT_EQ(unexpectedMessages(scene.log()), "");
}

}  // namespace
}  // namespace stroma::test
