// SPDX-License-Identifier: MIT
// OglModel: nothing is read or mapped until a renderer asks (updateVisual); then the surface
// follows its mapping exactly as a mechanical output of the same mapping would, with SOFA's
// transform and material, and bad meshes or texts are reported by field.
#include <filesystem>
#include <fstream>

#include "plugins/Mapping/MappingChecks.h"
#include "simulation/VisualModel.h"

namespace stroma::test {
namespace {

// A beam of 2 x 2 x 4 hexahedra fixed at z = 0, bending under gravity; `children` go in it.
std::string beamScene(const std::string& children) {
  return R"(<Node name="root" dt="0.01" gravity="0 -9.81 0">
      <EulerImplicitSolver/>
      <CGLinearSolver iterations="200" tolerance="1e-10" threshold="1e-30"/>
      <RegularGridTopology name="grid" n="3 3 5" min="0 0 0" max="0.1 0.1 0.4"/>
      <MechanicalObject name="dofs"/>
      <UniformMass totalMass="1"/>
      <HexahedronFEMForceField youngModulus="2e4" poissonRatio="0.3"/>
      <BoxConstraint box="-0.01 -0.01 -0.01  0.11 0.11 0.001"/>
      )" + children + R"(
    </Node>)";
}

constexpr const char* kPoints = "0.02 0.03 0.05  0.08 0.05 0.2  0.05 0.09 0.39  0.01 0.01 0.3";

std::filesystem::path writeObj(const std::string& name, const std::string& text) {
  const auto path = std::filesystem::temp_directory_path() / name;
  std::ofstream(path) << text;
  return path;
}

VisualModel* visualNamed(const Scene& scene, const std::string& path) {
  std::string why;
  auto* model = dynamic_cast<VisualModel*>(resolveObjectPath(scene.root(), "@" + path, why));
  EXPECT_NE(model, nullptr) << path << ": " << why;
  return model;
}

TEST(OglModel, FollowsItsMappingOnlyWhenDrawn) {
  const auto obj = writeObj("stroma_oglmodel_points.obj",
                            "v 0.02 0.03 0.05\nv 0.08 0.05 0.2\nv 0.05 0.09 0.39\n"
                            "v 0.01 0.01 0.3\nf 1 2 3\nf 1 3 4\n");
  Runtime runtime;
  Scene scene(runtime);
  ASSERT_TRUE(scene.loadString(beamScene(R"(
      <Node name="Visual">
        <OglModel name="surface" filename=")" + obj.string() + R"(" color="red"/>
        <BarycentricMapping input="@.." output="@surface"/>
      </Node>
      <Node name="Points">
        <MechanicalObject name="points" position=")" + kPoints + R"("/>
        <BarycentricMapping input="@.." output="@points"/>
      </Node>)")))
      << problems(scene.log());
  VisualModel* surface = visualNamed(scene, "/root/Visual/surface");
  ASSERT_NE(surface, nullptr);
  for (int i = 0; i < 20; ++i) ASSERT_TRUE(scene.step());
  // A batch run never read the mesh nor mapped it.
  EXPECT_EQ(surface->surface(), nullptr);

  surface->updateVisual();
  const VisualSurface* s = surface->surface();
  ASSERT_NE(s, nullptr) << problems(scene.log());
  const std::vector<double> points = positionsAt(scene, "/root/Points/points");
  ASSERT_EQ(s->positions.size() * 3, points.size());
  for (std::size_t k = 0; k < s->positions.size(); ++k) {
    const Vec3d expected(points[3 * k], points[3 * k + 1], points[3 * k + 2]);
    EXPECT_LT((s->positions[k] - expected).norm(), 1e-12) << k;
  }
  EXPECT_GT(std::abs(points[7] - 0.09), 1e-4);  // the tip point sagged: the mapping moved it
  ASSERT_EQ(s->triangles.size(), 2u);
  ASSERT_EQ(s->normals.size(), s->positions.size());
  for (const Vec3d& n : s->normals) EXPECT_NEAR(n.norm(), 1.0, 1e-12);
  EXPECT_EQ(s->material.diffuse, Vec4d(1, 0, 0, 1));

  // Later draws follow later steps.
  for (int i = 0; i < 5; ++i) ASSERT_TRUE(scene.step());
  surface->updateVisual();
  const std::vector<double> later = positionsAt(scene, "/root/Points/points");
  EXPECT_LT((s->positions[2] - Vec3d(later[6], later[7], later[8])).norm(), 1e-12);
  EXPECT_EQ(problems(scene.log()), "");
  std::filesystem::remove(obj);
}

TEST(OglModel, RigidMappingMovesLocalPointsWithTheFrame) {
  Runtime runtime;
  Scene scene(runtime);
  ASSERT_TRUE(scene.loadString(R"(<Node name="root">
      <MechanicalObject template="Rigid3d" name="frame" position="1 2 3  0 0 0 1"/>
      <Node name="Visual">
        <OglModel name="body" position="1 0 0  0 1 0  0 0 1" triangles="0 1 2"/>
        <RigidMapping input="@../frame" output="@body"/>
      </Node>
    </Node>)"))
      << problems(scene.log());
  auto* frame = findInScene<MechanicalState<Rigid3Types>>(scene.root());
  ASSERT_NE(frame, nullptr);
  // The frame turns by 90 degrees about z before anything is drawn.
  auto& x = frame->writeCoord(VecId::position());
  x[0].orientation = Quat(Eigen::AngleAxisd(M_PI / 2, Vec3d::UnitZ()));
  VisualModel* body = visualNamed(scene, "/root/Visual/body");
  ASSERT_NE(body, nullptr);
  body->updateVisual();
  ASSERT_NE(body->surface(), nullptr) << problems(scene.log());
  const auto& p = body->surface()->positions;
  ASSERT_EQ(p.size(), 3u);
  EXPECT_LT((p[0] - Vec3d(1, 3, 3)).norm(), 1e-12);
  EXPECT_LT((p[1] - Vec3d(0, 2, 3)).norm(), 1e-12);
  EXPECT_LT((p[2] - Vec3d(1, 2, 4)).norm(), 1e-12);
}

TEST(OglModel, AppliesSofasTransformAndMaterial) {
  Runtime runtime;
  Scene scene(runtime);
  ASSERT_TRUE(scene.loadString(R"(<Node name="root">
      <OglModel name="a" position="1 0 0  0 1 0  0 0 0" triangles="0 1 2"
                scale="2" rotation="0 0 90" translation="1 2 3"
                material="Default Diffuse 1 0.1 0.2 0.3 1 Ambient 0 1 1 1 1 Specular 1 0.5 0.5 0.5 1 Emissive 0 1 1 1 1 Shininess 1 20"/>
      <OglModel name="b" position="0 0 0  1 0 0  1 1 0  0 1 0" quads="0 1 2 3" color="0 0 1 0.5"/>
    </Node>)"))
      << problems(scene.log());
  VisualModel* a = visualNamed(scene, "/root/a");
  a->updateVisual();
  ASSERT_NE(a->surface(), nullptr);
  // Scaled by 2, turned 90 degrees about z, then moved: (1, 0, 0) -> (2, 0, 0) -> (0, 2, 0).
  EXPECT_LT((a->surface()->positions[0] - Vec3d(1, 4, 3)).norm(), 1e-12);
  EXPECT_LT((a->surface()->positions[1] - Vec3d(-1, 2, 3)).norm(), 1e-12);
  const VisualMaterial& m = a->surface()->material;
  EXPECT_EQ(m.diffuse, Vec4d(0.1, 0.2, 0.3, 1));
  EXPECT_EQ(m.ambient, VisualMaterial{}.ambient);  // switched off: the default stays
  EXPECT_EQ(m.specular, Vec4d(0.5, 0.5, 0.5, 1));
  EXPECT_EQ(m.shininess, 20);
  EXPECT_NEAR(a->surface()->normals[0].z(), 1.0, 1e-12);  // counter-clockwise seen from +z

  VisualModel* b = visualNamed(scene, "/root/b");
  b->updateVisual();
  ASSERT_NE(b->surface(), nullptr);
  EXPECT_EQ(b->surface()->triangles.size(), 2u);  // the quad, split
  EXPECT_EQ(b->surface()->material.diffuse, Vec4d(0, 0, 1, 0.5));
  EXPECT_TRUE(b->surface()->alphaBlend);
}

TEST(OglModel, ReportsBadInputByField) {
  Runtime runtime;
  Scene scene(runtime);
  ASSERT_TRUE(scene.loadString(R"(<Node name="root">
      <OglModel name="missing" filename="no/such/mesh.obj"/>
      <OglModel name="badColor" position="0 0 0  1 0 0  0 1 0" triangles="0 1 2" color="redd"/>
      <OglModel name="badTriangle" position="0 0 0  1 0 0  0 1 0" triangles="0 1 7"/>
    </Node>)"))
      << problems(scene.log());
  // Cheap checks at load: the color text.
  EXPECT_NE(problems(scene.log()).find("badColor"), std::string::npos);
  EXPECT_NE(problems(scene.log()).find("unknown color name 'redd'"), std::string::npos);
  // The mesh is read when drawn.
  VisualModel* missing = visualNamed(scene, "/root/missing");
  missing->updateVisual();
  EXPECT_EQ(missing->surface(), nullptr);
  EXPECT_NE(problems(scene.log()).find("no/such/mesh.obj"), std::string::npos);
  VisualModel* badTriangle = visualNamed(scene, "/root/badTriangle");
  badTriangle->updateVisual();
  EXPECT_EQ(badTriangle->surface(), nullptr);
  EXPECT_NE(problems(scene.log()).find("uses point 7, out of range of the 3 points"),
            std::string::npos);
  VisualModel* badColor = visualNamed(scene, "/root/badColor");
  badColor->updateVisual();
  ASSERT_NE(badColor->surface(), nullptr);
  EXPECT_EQ(badColor->surface()->material.diffuse, VisualMaterial{}.diffuse);
}

}  // namespace
}  // namespace stroma::test
