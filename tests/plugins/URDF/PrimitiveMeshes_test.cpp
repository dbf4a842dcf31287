// SPDX-License-Identifier: MIT
// The meshes of URDF's primitives (box, cylinder, sphere): closed and consistently oriented
// (every edge shared by two triangles, once in each direction; Euler characteristic 2), their
// enclosed volume the polyhedron's closed form (positive: normals outward), their points on the
// primitive's surface; a frame moves them rigidly. Then a URDF link drawn and collided as a
// box, cylinder and sphere: its visual nodes hold those meshes.
#include <cmath>
#include <map>
#include <utility>

#include "PrimitiveMeshes.h"
#include "plugins/URDF/URDFTestRobots.h"

namespace stroma::test {
namespace {

double enclosedVolume(const PrimitiveMesh& m) {
  double v = 0;
  for (const Vec3i& t : m.triangles)
    v += m.points[static_cast<std::size_t>(t.x())].dot(
             m.points[static_cast<std::size_t>(t.y())].cross(m.points[static_cast<std::size_t>(t.z())])) /
         6.0;
  return v;
}

void expectClosedAndOriented(const PrimitiveMesh& m) {
  std::map<std::pair<int, int>, int> directed;
  for (const Vec3i& t : m.triangles)
    for (int k = 0; k < 3; ++k) ++directed[{t[k], t[(k + 1) % 3]}];
  for (const auto& [edge, count] : directed) {
    EXPECT_EQ(count, 1) << "edge " << edge.first << "-" << edge.second << " twice one way";
    EXPECT_EQ(directed.count({edge.second, edge.first}), 1u)
        << "edge " << edge.first << "-" << edge.second << " has no opposite";
  }
  const long edges = static_cast<long>(directed.size()) / 2;
  EXPECT_EQ(static_cast<long>(m.points.size()) - edges + static_cast<long>(m.triangles.size()), 2);
}

TEST(PrimitiveMeshes, BoxIsClosedOutwardWithItsVolume) {
  const PrimitiveMesh box = boxMesh(Vec3d(0.1, 0.2, 0.3));
  EXPECT_EQ(box.points.size(), 8u);
  EXPECT_EQ(box.triangles.size(), 12u);
  expectClosedAndOriented(box);
  EXPECT_NEAR(enclosedVolume(box), 0.1 * 0.2 * 0.3, 1e-15);
  for (const Vec3d& p : box.points)
    EXPECT_TRUE(p.cwiseAbs().isApprox(Vec3d(0.05, 0.1, 0.15)));
}

TEST(PrimitiveMeshes, CylinderIsClosedOutwardWithThePrismsVolume) {
  const int n = 32;
  const double r = 0.04, L = 0.3;
  const PrimitiveMesh c = cylinderMesh(r, L, n);
  expectClosedAndOriented(c);
  // The prism on a regular n-gon inscribed in the circle.
  EXPECT_NEAR(enclosedVolume(c), 0.5 * n * r * r * std::sin(2 * M_PI / n) * L, 1e-15);
  for (const Vec3d& p : c.points) {
    EXPECT_NEAR(std::abs(p.z()), L / 2, 1e-15);
    const double radial = std::hypot(p.x(), p.y());
    EXPECT_TRUE(radial < 1e-15 || std::abs(radial - r) < 1e-15) << radial;
  }
}

TEST(PrimitiveMeshes, SphereIsClosedOutwardOnTheSphereAndConverges) {
  const double r = 0.05;
  double previous = 0;
  for (int rings : {6, 12, 24}) {
    const PrimitiveMesh s = sphereMesh(r, rings, 2 * rings);
    expectClosedAndOriented(s);
    for (const Vec3d& p : s.points) EXPECT_NEAR(p.norm(), r, 1e-15);
    // An inscribed polyhedron: below the ball's volume, approaching it at second order.
    const double error = 4.0 / 3.0 * M_PI * r * r * r - enclosedVolume(s);
    EXPECT_GT(error, 0);
    if (previous > 0) {
      EXPECT_NEAR(previous / error, 4.0, 0.3) << rings << " rings";
    }
    previous = error;
  }
}

TEST(PrimitiveMeshes, AFrameMovesTheMeshRigidly) {
  PrimitiveMesh box = boxMesh(Vec3d(0.1, 0.2, 0.3));
  const PrimitiveMesh before = box;
  RigidCoord3 frame;
  frame.center = Vec3d(1, 2, 3);
  frame.orientation = Quat(Eigen::AngleAxisd(0.7, Vec3d(1, 1, 0).normalized()));
  transformMesh(box, frame);
  for (std::size_t i = 0; i < box.points.size(); ++i)
    EXPECT_TRUE(box.points[i].isApprox(frame.center + frame.orientation * before.points[i], 1e-14));
  EXPECT_NEAR(enclosedVolume(box), 0.1 * 0.2 * 0.3, 1e-14);  // still outward
}

TEST(PrimitiveMeshes, UrdfPrimitivesAreDrawnAsTheirMeshes) {
  // link1 drawn as a box, a cylinder and a sphere; a box placed by its origin.
  ArmOptions arm;
  arm.secondLink = false;
  std::string urdf = twoLinkArm(arm);
  const std::string visuals =
      R"(<visual><origin xyz="0.25 0 0" rpy="0 1.5707963267948966 0"/><geometry><cylinder radius="0.02" length="0.5"/></geometry></visual>
      <visual><origin xyz="0.5 0 0"/><geometry><sphere radius="0.03"/></geometry></visual>
      <visual><origin xyz="0.1 0 0"/><geometry><box size="0.04 0.06 0.08"/></geometry></visual>)";
  urdf.insert(urdf.find("</link>", urdf.find("link name=\"link1\"")), visuals);
  RobotFolder folder;
  Runtime runtime;
  Scene scene(runtime);
  ASSERT_TRUE(loadArm(scene, folder,
                      armScene(folder, urdf, "<EulerImplicitSolver/><SparseLDLSolver/>", "",
                               "0 0 0")))
      << problems(scene.log());
  EXPECT_EQ(problems(scene.log()), "");
  std::string why;
  for (const auto& [node, points] : std::map<std::string, std::size_t>{
           {"visual_link1", 2 * 32 + 2}, {"visual_link1_1", 2 + 11 * 24}, {"visual_link1_2", 8}}) {
    const Base* model = resolveObjectPath(scene.root(), "@/root/arm/links/" + node + "/visual", why);
    ASSERT_NE(model, nullptr) << why;
    const auto* position = dynamic_cast<const Data<std::vector<Vec3d>>*>(model->findData("position"));
    ASSERT_NE(position, nullptr);
    EXPECT_EQ(position->value().size(), points) << node;
  }
  // The box's corners at (0.1 +- 0.02, +-0.03, +-0.04) in the link, which is the world at q = 0.
  ASSERT_TRUE(scene.step());
  const Base* box = resolveObjectPath(scene.root(), "@/root/arm/links/visual_link1_2/visual", why);
  const auto& corners = dynamic_cast<const Data<std::vector<Vec3d>>*>(box->findData("position"))->value();
  for (const Vec3d& p : corners)
    EXPECT_TRUE((p - Vec3d(0.1, 0, 0)).cwiseAbs().isApprox(Vec3d(0.02, 0.03, 0.04), 1e-9)) << p.transpose();
}

}  // namespace
}  // namespace stroma::test
