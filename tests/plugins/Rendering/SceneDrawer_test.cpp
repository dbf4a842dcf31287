// SPDX-License-Identifier: MIT
// The scene drawer in an offscreen context (OSMesa): what it draws by the scene's flags, a
// deformed body against its rest shape, the legend's numbers read back from the pixels, the
// background and lights, textures good and bad, collision contacts.
#include "stroma/rendering/SceneDrawer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "OffscreenContext.h"
#include "RenderingTestSupport.h"
#include "core/Runtime.h"
#include "core/StateTypes.h"
#include "plugins/TestPlugin/TestSupport.h"
#include "simulation/MechanicalState.h"
#include "simulation/Scene.h"
#include "stroma/rendering/Camera.h"
#include "stroma/rendering/SceneBounds.h"

namespace stroma::rendering {
namespace {

constexpr int kWidth = 160, kHeight = 120;

// A beam of 2 x 2 x 6 hexahedra clamped at z = 0, bending under gravity along -y.
std::string beamScene(const std::string& extra) {
  return R"(<Node name="root" dt="0.02" gravity="0 -9.81 0">)" + extra + R"(
      <EulerImplicitSolver/>
      <CGLinearSolver iterations="200" tolerance="1e-10" threshold="1e-30"/>
      <RegularGridTopology name="grid" n="3 3 7" min="0 0 0" max="0.1 0.1 0.6"/>
      <MechanicalObject name="dofs"/>
      <UniformMass totalMass="1"/>
      <HexahedronFEMForceField youngModulus="1e4" poissonRatio="0.3"/>
      <BoxConstraint name="clamp" box="-0.01 -0.01 -0.01  0.11 0.11 0.001"/>
    </Node>)";
}

/// A context, a scene and a drawer; the camera looks at the scene's box from +x.
struct Fixture {
  OffscreenContext context;
  Runtime runtime;
  Scene scene{runtime};
  std::unique_ptr<SceneDrawer> drawer;
  Camera camera;

  bool load(const std::string& xml, std::string& why) {
    if (!context.create(kWidth, kHeight, why)) return false;
    if (!scene.loadString(xml)) {
      why = test::describe(scene.log());
      return false;
    }
    drawer = std::make_unique<SceneDrawer>(scene.root());
    drawer->updateVisuals();
    const Aabb box = sceneBounds(scene.root());
    camera.setEyeAndTarget(0.5 * (box.min + box.max) + Vec3d(1, 0, 0), 0.5 * (box.min + box.max));
    camera.fitBox(box, double(kWidth) / kHeight);
    return true;
  }
  Image draw(const DrawOptions& options = {}) {
    drawer->setOptions(options);
    camera.fitClipPlanes(sceneBounds(scene.root()));
    drawer->draw(camera, kWidth, kHeight);
    Image image;
    context.readPixels(image);
    return image;
  }
};

DrawOptions showing(const char* words) {
  DrawOptions options;
  DisplayFlags flags;
  std::string unknown;
  flags.apply(words, unknown);
  options.flags = flags;
  return options;
}

std::array<int, 4> pixel(const Image& image, int x, int y) {
  const std::size_t at = (static_cast<std::size_t>(y) * image.width + x) * 4;
  return {image.rgba[at], image.rgba[at + 1], image.rgba[at + 2], image.rgba[at + 3]};
}

double meanBrightness(const Image& image) {
  double sum = 0;
  for (std::size_t i = 0; i < image.rgba.size(); i += 4)
    sum += image.rgba[i] + image.rgba[i + 1] + image.rgba[i + 2];
  return sum / (3.0 * image.rgba.size() / 4);
}

TEST(RenderingSceneDrawer, ADeformedBodyRendersDifferentlyFromItsRestShape) {
  Fixture f;
  std::string why;
  ASSERT_TRUE(f.load(beamScene(""), why)) << why;
  const DrawOptions options = showing("showForceFields");
  const Image rest = f.draw(options);
  EXPECT_GT(f.drawer->lastFrame().triangles, 0u);
  EXPECT_EQ(f.drawer->lastFrame().visualSurfaces, 0u);
  // The same state drawn twice gives the same bits.
  EXPECT_EQ(f.draw(options).rgba, rest.rgba);
  for (int i = 0; i < 25; ++i) ASSERT_TRUE(f.scene.step());
  const Image bent = f.draw(options);
  EXPECT_LT(test::matchingFraction(rest, bent), 0.95)
      << "at least 5 % of the pixels change when the beam bends";
}

TEST(RenderingSceneDrawer, LegendWritesTheRangeOfTheDisplacementItColors) {
  Fixture f;
  std::string why;
  ASSERT_TRUE(f.load(beamScene(""), why)) << why;
  for (int i = 0; i < 25; ++i) ASSERT_TRUE(f.scene.step());
  DrawOptions options;
  options.colorMap = ColorMapKind::displacement;
  const Image image = f.draw(options);
  const FrameReport& report = f.drawer->lastFrame();
  ASSERT_TRUE(report.colorMapped) << report.colorMapError;

  // The range, computed here from the state.
  const auto* dofs = f.scene.root().get<MechanicalState<Vec3Types>>();
  ASSERT_NE(dofs, nullptr);
  const auto& x = dofs->readCoord(VecId::position());
  const auto& rest = dofs->readCoord(VecId::restPosition());
  double largest = 0, smallest = 1e300;
  for (std::size_t i = 0; i < x.size(); ++i) {
    largest = std::max(largest, (x[i] - rest[i]).norm());
    smallest = std::min(smallest, (x[i] - rest[i]).norm());
  }
  EXPECT_GT(largest, 0.01) << "the beam bends by centimetres";
  EXPECT_EQ(smallest, 0.0) << "the clamped points stay";
  EXPECT_DOUBLE_EQ(report.colorMax, largest);
  EXPECT_DOUBLE_EQ(report.colorMin, smallest);

  // The numbers in the picture, read back through the font, are those of the range.
  const std::string shownMax = test::readText(image, report.legendMaxX, report.legendMaxY,
                                              report.legendScale, int(report.legendMax.size()));
  const std::string shownMin = test::readText(image, report.legendMinX, report.legendMinY,
                                              report.legendScale, int(report.legendMin.size()));
  EXPECT_EQ(shownMax, report.legendMax);
  EXPECT_EQ(shownMin, report.legendMin);
  EXPECT_NEAR(std::stod(shownMax), largest, 0.005 * largest) << "three significant digits";
  EXPECT_EQ(std::stod(shownMin), 0.0);
}

TEST(RenderingSceneDrawer, VonMisesColorsNeedAForceFieldThatGivesStress) {
  Fixture f;
  std::string why;
  ASSERT_TRUE(f.load(R"(<Node name="root" dt="0.02" gravity="0 -9.81 0">
      <EulerImplicitSolver/>
      <CGLinearSolver iterations="200" tolerance="1e-10" threshold="1e-30"/>
      <RegularGridTopology name="grid" n="3 3 5" min="0 0 0" max="0.1 0.1 0.4"/>
      <TetrahedronSetTopologyContainer name="tetras"/>
      <Hexa2TetraTopologicalMapping input="@grid" output="@tetras"/>
      <MechanicalObject name="dofs" position="@grid.position"/>
      <UniformMass totalMass="1"/>
      <TetrahedronFEMForceField youngModulus="1e4" poissonRatio="0.3" topology="@tetras"/>
      <BoxConstraint box="-0.01 -0.01 -0.01  0.11 0.11 0.001"/>
    </Node>)",
                     why))
      << why;
  for (int i = 0; i < 10; ++i) ASSERT_TRUE(f.scene.step());
  DrawOptions options;
  options.colorMap = ColorMapKind::vonMises;
  f.draw(options);
  const FrameReport& report = f.drawer->lastFrame();
  if (!report.colorMapped) {
    EXPECT_NE(report.colorMapError.find("provides stress"), std::string::npos)
        << report.colorMapError;
    GTEST_SKIP() << "this build's TetrahedronFEMForceField gives no stress: "
                 << report.colorMapError;
  }
  EXPECT_GE(report.colorMin, 0.0);
  EXPECT_GT(report.colorMax, report.colorMin) << "a bent beam is stressed unevenly";
}

TEST(RenderingSceneDrawer, ASceneWithNothingToShowDrawsNothingButTheBackground) {
  Fixture f;
  std::string why;
  ASSERT_TRUE(f.load(R"(<Node name="root"><BackgroundSetting color="0 0.5 1"/>
      <MechanicalObject position="0 0 0  1 1 1"/></Node>)",
                     why))
      << why;
  const Image image = f.draw();
  EXPECT_EQ(f.drawer->lastFrame().drawn(), 0u);
  for (int y = 0; y < kHeight; y += 7)
    for (int x = 0; x < kWidth; x += 7) {
      const auto p = pixel(image, x, y);
      ASSERT_EQ(p[0], 0);
      ASSERT_NEAR(p[1], 128, 1);
      ASSERT_EQ(p[2], 255);
    }
  // The same scene with its states shown: points, and nothing else.
  f.draw(showing("showBehaviorModels"));
  EXPECT_EQ(f.drawer->lastFrame().points, 2u);
  EXPECT_EQ(f.drawer->lastFrame().triangles, 0u);
}

TEST(RenderingSceneDrawer, BehaviourModelsShowEveryPointAndTheFixedOnes) {
  Fixture f;
  std::string why;
  ASSERT_TRUE(f.load(beamScene(R"(<VisualStyle displayFlags="showBehaviorModels"/>)"), why)) << why;
  f.draw();
  // 3 x 3 x 7 points, and the 9 of the clamped end again, bigger.
  EXPECT_EQ(f.drawer->lastFrame().points, 63u + 9u);
  EXPECT_EQ(f.drawer->lastFrame().triangles, 0u) << "force fields not asked for";
  f.draw(showing("showForceFields showWireframe"));
  EXPECT_EQ(f.drawer->lastFrame().triangles, 0u);
  EXPECT_GT(f.drawer->lastFrame().lines, 0u) << "wireframe: edges instead of faces";
}

TEST(RenderingSceneDrawer, AVisualStyleAppliesToItsSubtree) {
  Fixture f;
  std::string why;
  ASSERT_TRUE(f.load(R"(<Node name="root">
      <Node name="A"><VisualStyle displayFlags="showBehaviorModels"/>
        <MechanicalObject position="0 0 0  1 0 0  0 1 0"/>
        <Node name="Child"><MechanicalObject position="0 0 1"/></Node></Node>
      <Node name="B"><MechanicalObject position="1 1 1  0 0 1"/></Node>
    </Node>)",
                     why))
      << why;
  f.draw();
  EXPECT_EQ(f.drawer->lastFrame().points, 4u) << "A's 3 points and its child's, not B's";
  // A viewer's override applies everywhere.
  f.draw(showing("showBehaviorModels"));
  EXPECT_EQ(f.drawer->lastFrame().points, 6u);
}

TEST(RenderingSceneDrawer, GridsAxesAndLabelsOfTheScene) {
  Fixture f;
  std::string why;
  ASSERT_TRUE(f.load(R"(<Node name="root">
      <VisualGrid size="2" nbSubdiv="4" plane="y"/>
      <LineAxis size="1" axis="xz"/>
      <OglLabel label="STEP 12" prefix="" x="5" y="6" fontsize="14"/>
      <MechanicalObject position="-1 0 -1  1 0 1"/>
    </Node>)", why)) << why;
  f.camera.setEyeAndTarget(Vec3d(0, 3, 2), Vec3d::Zero());
  const Image image = f.draw();
  // 5 lines each way, and two axes.
  EXPECT_EQ(f.drawer->lastFrame().lines, 12u);
  // The label, in our font at twice its size (14 pixels / 7), white on the dark background.
  EXPECT_EQ(test::readText(image, 5, 6, 2, 7), "STEP 12");
  // Not with the visual models hidden.
  f.draw(showing("hideVisual"));
  EXPECT_EQ(f.drawer->lastFrame().lines, 0u);
}

TEST(RenderingSceneDrawer, SceneLightsReplaceTheHeadlight) {
  // The beam's face towards the camera (+x) lit by a light going along -x (from the camera's
  // side) is bright; lit from behind it is dark.
  auto brightness = [](const char* direction) {
    Fixture f;
    std::string why;
    EXPECT_TRUE(f.load(beamScene(std::string(R"(<LightManager ambient="0 0 0 1"/>
        <DirectionalLight color="1 1 1" direction=")") +
                                 direction + R"("/>)"),
                       why))
        << why;
    return meanBrightness(f.draw(showing("showForceFields")));
  };
  const double front = brightness("-1 0 0"), back = brightness("1 0 0");
  EXPECT_GT(front, back + 10) << front << " " << back;
}

std::string texturedQuad(const std::string& texture) {
  return R"(<Node name="root"><BackgroundSetting color="0 0 0"/>
      <Node name="Visual"><OglModel name="quad" position="0 0 0  1 0 0  1 1 0  0 1 0"
          triangles="0 1 2  0 2 3" texcoords="0 0  1 0  1 1  0 1" texturename=")" +
         texture +
         R"(" material="Default Diffuse 1 1 1 1 1 Ambient 1 0.5 0.5 0.5 1 Specular 0 1 1 1 1 Emissive 0 0 0 0 0 Shininess 0 45"/></Node>
    </Node>)";
}

/// Quadrants, as the picture file shows them: red top left, blue top right, green bottom
/// left, yellow bottom right.
Image quadrantTexture() {
  Image image;
  image.width = 8;
  image.height = 8;
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) {
      const bool top = y < 4, left = x < 4;
      const std::uint8_t r = (top && left) || (!top && !left) ? 255 : 0;
      const std::uint8_t g = !top ? 255 : 0;
      const std::uint8_t b = top && !left ? 255 : 0;
      image.rgba.insert(image.rgba.end(), {r, g, b, 255});
    }
  return image;
}

TEST(RenderingSceneDrawer, TexturesAreDrawnAndBadOnesWarnedOnceThenLeftOut) {
  test::TempDir dir;
  std::string error;
  ASSERT_TRUE(writePng(dir.path() / "quadrants.png", quadrantTexture(), error)) << error;
  {
    Fixture f;
    std::string why;
    ASSERT_TRUE(f.load(texturedQuad((dir.path() / "quadrants.png").string()), why)) << why;
    f.camera.setEyeAndTarget(Vec3d(0.5, 0.5, 2), Vec3d(0.5, 0.5, 0));
    const Image image = f.draw();
    ASSERT_EQ(f.drawer->lastFrame().visualSurfaces, 1u);
    // Texture coordinates as OBJ files give them (t = 0 at the bottom of the picture): the
    // quad shows the picture the right way up.
    const auto topLeft = pixel(image, kWidth / 2 - 10, kHeight / 2 - 10);
    const auto topRight = pixel(image, kWidth / 2 + 10, kHeight / 2 - 10);
    const auto bottomLeft = pixel(image, kWidth / 2 - 10, kHeight / 2 + 10);
    const auto bottomRight = pixel(image, kWidth / 2 + 10, kHeight / 2 + 10);
    auto near = [](const std::array<int, 4>& p, int r, int g, int b) {
      return std::abs(p[0] - r) < 60 && std::abs(p[1] - g) < 60 && std::abs(p[2] - b) < 60;
    };
    EXPECT_TRUE(near(topLeft, 255, 0, 0)) << topLeft[0] << " " << topLeft[1] << " " << topLeft[2];
    EXPECT_TRUE(near(topRight, 0, 0, 255));
    EXPECT_TRUE(near(bottomLeft, 0, 255, 0));
    EXPECT_TRUE(near(bottomRight, 255, 255, 0));
    EXPECT_EQ(f.scene.log().count(MessageLevel::warning), 0u) << test::describe(f.scene.log());
  }
  const auto corrupt = dir.write("corrupt.png", "\x89PNG\r\n\x1a\n but nothing after");
  for (const std::filesystem::path& bad : {corrupt, dir.path() / "missing.png"}) {
    Fixture f;
    std::string why;
    ASSERT_TRUE(f.load(texturedQuad(bad.string()), why)) << why;
    f.camera.setEyeAndTarget(Vec3d(0.5, 0.5, 2), Vec3d(0.5, 0.5, 0));
    const std::size_t before = f.scene.log().count(MessageLevel::warning);
    f.draw();
    const Image image = f.draw();  // a second frame warns no more
    EXPECT_EQ(f.scene.log().count(MessageLevel::warning), before + 1)
        << test::describe(f.scene.log());
    const std::string log = test::describe(f.scene.log());
    EXPECT_NE(log.find("/root/Visual/quad"), std::string::npos) << log;
    EXPECT_NE(log.find(bad.filename().string()), std::string::npos) << log;
    // Drawn without texture: one grey-white color over the quad.
    EXPECT_EQ(f.drawer->lastFrame().triangles, 2u);
    const auto left = pixel(image, kWidth / 2 - 10, kHeight / 2);
    const auto right = pixel(image, kWidth / 2 + 10, kHeight / 2);
    EXPECT_GT(left[0], 100);
    EXPECT_NEAR(left[0], left[2], 3);
    EXPECT_NEAR(left[0], right[0], 3);
  }
}

TEST(RenderingSceneDrawer, CollisionModelsAndContactsOfAScene) {
  Fixture f;
  std::string why;
  const std::string file = std::string(STROMA_SOURCE_DIR) + "/scenes/collision/TwoCubes.scn";
  Runtime probe;
  if (!probe.plugins().providerOf("CollisionPipeline") ||
      !probe.plugins().providerOf("CollisionPipeline")->unavailable.empty())
    GTEST_SKIP() << "this build has no Collision plugin (Bullet)";
  ASSERT_TRUE(f.context.create(kWidth, kHeight, why)) << why;
  ASSERT_TRUE(f.scene.loadFile(file)) << test::describe(f.scene.log());
  f.drawer = std::make_unique<SceneDrawer>(f.scene.root());
  f.camera.fitBox(sceneBounds(f.scene.root()), double(kWidth) / kHeight);
  f.draw(showing("showCollisionModels"));
  EXPECT_GT(f.drawer->lastFrame().triangles, 0u);
  EXPECT_EQ(f.drawer->lastFrame().contacts, 0u) << "apart at the start";
  for (int i = 0; i < 30; ++i) ASSERT_TRUE(f.scene.step());
  f.draw(showing("showCollisionModels"));
  EXPECT_GT(f.drawer->lastFrame().contacts, 0u) << "the thrown cube touches the other";
}

}  // namespace
}  // namespace stroma::rendering
