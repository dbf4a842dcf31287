// SPDX-License-Identifier: MIT
// GenerateRigidMass in scenes: the outputs for a box of triangles or quads (closed forms),
// scale and mirror, a Rigid3d UniformMass reading vertexMass="@engine.rigidMass", SOFA's liver
// surface through a loader, and the errors for a surface that is not a closed, outward one.
#include <gtest/gtest.h>

#include "SurfaceMeshes.h"
#include "linalg/AssembledMatrix.h"
#include "plugins/Spring/MechanicsTestSupport.h"

namespace stroma::test {
namespace {

std::string engineScene(const Surface& s, const std::string& attributes) {
  std::string faces;
  if (!s.triangles.empty()) faces += " triangles=\"" + elementsText(s.triangles) + "\"";
  if (!s.quads.empty()) faces += " quads=\"" + elementsText(s.quads) + "\"";
  return "<Node name=\"root\">\n  <GenerateRigidMass name=\"engine\" position=\"" +
         pointsText(s.points) + "\"" + faces + " " + attributes + "/>\n</Node>\n";
}

/// A box a x b x c with its corner at `corner`.
Surface movedBox(double a, double b, double c, const Vec3d& corner, bool asQuads = false) {
  Surface s = boxSurface(a, b, c, asQuads);
  for (Vec3d& p : s.points) p += corner;
  return s;
}

TEST(GenerateRigidMass, BoxMassCenterAndInertia) {
  // Box 0.5 x 1 x 2 at (1, 2, 3), density 7: V = 1, m = 7, center (1.25, 2.5, 4), inertia per
  // unit mass (b^2 + c^2, a^2 + c^2, a^2 + b^2) / 12.
  SceneHolder s;
  ASSERT_TRUE(s.load(engineScene(movedBox(0.5, 1, 2, Vec3d(1, 2, 3)), "density=\"7\"")));
  EXPECT_NEAR(std::stod(s.text("@engine.volume")), 1, 1e-15);
  EXPECT_NEAR(std::stod(s.text("@engine.mass")), 7, 1e-14);
  const auto center = numbers(s.text("@engine.massCenter"));
  const auto toOrigin = numbers(s.text("@engine.centerToOrigin"));
  const Vec3d expectedCenter(1.25, 2.5, 4);
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(center[i], expectedCenter[i], 1e-14);
    EXPECT_EQ(toOrigin[i], -center[i]);
  }
  const Vec3d diagonal = Vec3d(1 + 4, 0.25 + 4, 0.25 + 1) / 12;
  const auto inertia = numbers(s.text("@engine.inertiaMatrix"));
  ASSERT_EQ(inertia.size(), 9u);
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(inertia[3 * r + c], r == c ? diagonal[r] : 0.0, 1e-14) << r << " " << c;
  // rigidMass: "mass volume inertia(9)", the same numbers.
  const auto rigid = numbers(s.text("@engine.rigidMass"));
  ASSERT_EQ(rigid.size(), 11u);
  EXPECT_EQ(rigid[0], std::stod(s.text("@engine.mass")));
  EXPECT_EQ(rigid[1], std::stod(s.text("@engine.volume")));
  for (int k = 0; k < 9; ++k) EXPECT_EQ(rigid[2 + k], inertia[k]);
}

TEST(GenerateRigidMass, QuadsScaleAndMirror) {
  // The unit cube of quads, default density 1000; scale 2 along x doubles the volume; a mirror
  // (x -> -x) reverses the faces' orientation, which the engine undoes: volume +1.
  SceneHolder s;
  ASSERT_TRUE(s.load(engineScene(boxSurface(1, 1, 1, true), "")));
  EXPECT_NEAR(std::stod(s.text("@engine.mass")), 1000, 1e-12);
  s.set("@engine.scale", "2 1 1");
  EXPECT_NEAR(std::stod(s.text("@engine.volume")), 2, 1e-15);
  EXPECT_NEAR(numbers(s.text("@engine.massCenter"))[0], 1, 1e-15);
  EXPECT_NEAR(numbers(s.text("@engine.inertiaMatrix"))[4], (4 + 1) / 12.0, 1e-15);
  s.set("@engine.scale", "-1 1 1");
  EXPECT_NEAR(std::stod(s.text("@engine.volume")), 1, 1e-15);
  EXPECT_NEAR(numbers(s.text("@engine.massCenter"))[0], -0.5, 1e-15);
  EXPECT_NEAR(numbers(s.text("@engine.inertiaMatrix"))[0], 1 / 6.0, 1e-15);
}

TEST(GenerateRigidMass, UniformMassReadsTheRigidMass) {
  // A rigid box (0.5 x 1 x 2 at (1, 2, 3), density 7), its frame put at the center of mass as
  // SOFA's GenerateRigidMass.scn does: the Rigid3d UniformMass takes the engine's rigidMass; its
  // mass matrix is diag(m I3, m J) with J the inertia per unit mass.
  const Surface box = movedBox(0.5, 1, 2, Vec3d(1, 2, 3));
  const std::string faces = elementsText(box.triangles);
  SceneHolder s;
  ASSERT_TRUE(s.load(R"(<Node name="root" gravity="0 0 -10" dt="0.01">
  <EulerImplicitSolver rayleighMass="0" rayleighStiffness="0"/>
  <CGLinearSolver iterations="50" tolerance="1e-14" threshold="0"/>
  <GenerateRigidMass name="engine" template="Rigid3" density="7" position=")" +
                     pointsText(box.points) + R"(" triangles=")" + faces + R"("/>
  <MechanicalObject template="Rigid3" name="frame" position="0 0 0  0 0 0 1"
                    translation="@engine.massCenter"/>
  <UniformMass name="mass" vertexMass="@engine.rigidMass"/>
</Node>)"));
  EXPECT_EQ(s.text("@mass.vertexMass"), s.text("@engine.rigidMass"));
  const auto frame = numbers(s.text("@frame.position"));
  EXPECT_NEAR(frame[0], 1.25, 1e-14);
  EXPECT_NEAR(frame[1], 2.5, 1e-14);
  EXPECT_NEAR(frame[2], 4, 1e-14);
  MechanicalOperations mop(s.root(), s.scene().timing());
  MechanicalParams mp;
  mp.mFactor = 1;
  mp.kFactor = 0;
  AssembledMatrix A;
  mop.assemble(mp, A);
  const Eigen::MatrixXd M(A.matrix());
  Eigen::VectorXd expected(6);
  expected << 7, 7, 7, 7 * (1 + 4) / 12.0, 7 * (0.25 + 4) / 12.0, 7 * (0.25 + 1) / 12.0;
  EXPECT_LT((M - Eigen::MatrixXd(expected.asDiagonal())).cwiseAbs().maxCoeff(), 1e-13) << M;
  // It falls freely: z = -g h^2 n (n + 1) / 2 after n implicit Euler steps.
  ASSERT_TRUE(s.step(10));
  EXPECT_NEAR(numbers(s.text("@frame.position"))[2], 4 - 10 * 0.01 * 0.01 * 10 * 11 / 2, 1e-12);
}

TEST(GenerateRigidMass, SofaLiverSurfaceThroughALoader) {
  // SOFA's GenerateRigidMass.scn: liver-smooth.obj (4384 triangles, closed). The volume,
  // 39.267352037054 by a separate signed-tetrahedra sum over the file (Python, double), is the
  // same with handleSeams (points duplicated along seams, matched by position).
  const auto share = std::filesystem::path(STROMA_SHARED_DIR) / "sofa/share";
  if (!std::filesystem::exists(share / "mesh/liver-smooth.obj"))
    GTEST_SKIP() << "no SOFA meshes (../shared absent)";
  for (const char* seams : {"0", "1"}) {
    SCOPED_TRACE(std::string("handleSeams ") + seams);
    SceneHolder s;
    s.scene().runtime().addDataDirectory(share);
    ASSERT_TRUE(s.load(std::string(R"(<Node name="root">
  <MeshOBJLoader name="loader" filename="mesh/liver-smooth.obj" handleSeams=")") +
                       seams + R"("/>
  <GenerateRigidMass template="Rigid3" name="engine" density="1000" position="@loader.position"
                     triangles="@loader.triangles" quads="@loader.quads"/>
</Node>)"));
    const double volume = std::stod(s.text("@engine.volume"));
    EXPECT_NEAR(volume, 39.267352037054124, 1e-12 * volume);
    EXPECT_NEAR(std::stod(s.text("@engine.mass")), 1000 * volume, 1e-9 * volume);
    const auto v = numbers(s.text("@engine.inertiaMatrix"));
    Mat3d J;
    for (int k = 0; k < 9; ++k) J(k / 3, k % 3) = v[k];
    EXPECT_LT((J - J.transpose()).norm(), 1e-15 * J.norm());
    EXPECT_GT(Eigen::SelfAdjointEigenSolver<Mat3d>(J).eigenvalues().minCoeff(), 0);
  }
}

TEST(GenerateRigidMass, ReversedSurfaceIsAnError) {
  Surface box = boxSurface(1, 2, 3);
  for (Triangle& f : box.triangles) std::swap(f[1], f[2]);
  SceneHolder s;
  const Message m =
      s.loadFailing(engineScene(box, ""),
                    {"the surface is inverted: its volume is negative (-6 m^3)", "flipNormals"});
  EXPECT_EQ(m.field, "triangles");
  EXPECT_EQ(m.componentClass, "GenerateRigidMass");
  // Quads only: the message names the quads.
  Surface quads = boxSurface(1, 1, 1, true);
  for (Quad& q : quads.quads) std::swap(q[1], q[3]);
  SceneHolder t;
  EXPECT_EQ(t.loadFailing(engineScene(quads, ""), {"the surface is inverted"}).field, "quads");
}

TEST(GenerateRigidMass, OpenSurfaceIsAnError) {
  Surface box = boxSurface(1, 1, 1);
  box.triangles.erase(box.triangles.begin());  // (0 2 3) removed: a hole in the bottom
  SceneHolder s;
  const Message m = s.loadFailing(
      engineScene(box, ""),
      {"the surface is not closed: no face runs the edge from point", "the other way"});
  EXPECT_EQ(m.field, "triangles");
  // A face oriented against its neighbours.
  Surface flipped = boxSurface(1, 1, 1);
  std::swap(flipped.triangles[5][1], flipped.triangles[5][2]);
  SceneHolder t;
  EXPECT_EQ(t.loadFailing(engineScene(flipped, ""), {"the surface is not closed"}).field,
            "triangles");
}

TEST(GenerateRigidMass, EmptyOrOutOfRangeInputIsAnError) {
  SceneHolder s;
  EXPECT_EQ(s.loadFailing(R"(<Node><GenerateRigidMass position="0 0 0 1 0 0 0 1 0"/></Node>)",
                          {"no triangles nor quads"})
                .field,
            "triangles");
  SceneHolder t;
  EXPECT_EQ(
      t.loadFailing(R"(<Node><GenerateRigidMass triangles="0 1 2"/></Node>)", {"no points"}).field,
      "position");
  SceneHolder u;
  EXPECT_EQ(u.loadFailing(R"(<Node><GenerateRigidMass position="0 0 0 1 0 0 0 1 0"
triangles="0 1 2  0 2 7"/></Node>)",
                          {"triangle 1 (0 2 7) uses point 7, out of range of the 3 points"})
                .field,
            "triangles");
  SceneHolder w;  // two opposite triangles: closed, but flat
  EXPECT_EQ(w.loadFailing(R"(<Node><GenerateRigidMass position="0 0 0 1 0 0 0 1 0"
triangles="0 1 2  0 2 1"/></Node>)",
                          {"the surface encloses no volume"})
                .field,
            "triangles");
}

}  // namespace
}  // namespace stroma::test
