// SPDX-License-Identifier: MIT
// The viewer in a real window: ctest runs this under xvfb-run (tests/plugins/Viewer/
// CMakeLists.txt); without a display every test skips, saying why.
#include "SceneViewer.h"

#include <GLFW/glfw3.h>
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>

#include "ViewerWindow.h"
#include "plugins/TestPlugin/TestSupport.h"
#include "stroma/rendering/PngImage.h"
#include "core/Node.h"
#include "core/Runtime.h"
#include "simulation/Scene.h"

namespace stroma::viewer {
namespace {

constexpr int kWidth = 320, kHeight = 240;

class SceneViewerTest : public ::testing::Test {
 protected:
  void SetUp() override {
    window = std::make_unique<ViewerWindow>(kWidth, kHeight, "SceneViewer_test");
    if (!window->isOpen())
      GTEST_SKIP() << "no window (" << window->error()
                   << "); ctest runs this test under xvfb-run (Debian package xvfb)";
    ASSERT_TRUE(scene.loadFile(STROMA_SOURCE_DIR "/scenes/beam/HexaBeam.scn"))
        << scene.log().errorCount() << " errors";
  }
  void TearDown() override {
    viewer.reset();
    if (window) window->attach(nullptr);
  }

  /// The viewer over the scene, sized as the window's framebuffer.
  SceneViewer& makeViewer(ViewerSettings settings = {}) {
    viewer = std::make_unique<SceneViewer>(scene, settings);
    window->attach(viewer.get());
    return *viewer;
  }

  /// The frame just drawn (back buffer), RGB rows bottom first.
  std::vector<unsigned char> readFrame() const {
    int w = 0, h = 0;
    window->framebufferSize(w, h);
    std::vector<unsigned char> pixels(static_cast<std::size_t>(3 * w * h));
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadBuffer(GL_BACK);
    glReadPixels(0, 0, w, h, GL_RGB, GL_UNSIGNED_BYTE, pixels.data());
    return pixels;
  }

  void steps(int n) {
    for (int i = 0; i < n; ++i) {
      viewer->key(GLFW_KEY_N, GLFW_PRESS, 0);
      ASSERT_TRUE(viewer->advance());
    }
  }

  Vec3State& beam() {
    auto* dofs = dynamic_cast<Vec3State*>(scene.root().findChild("Beam")->findObject("dofs"));
    EXPECT_NE(dofs, nullptr);
    return *dofs;
  }

  std::unique_ptr<ViewerWindow> window;
  Runtime runtime;
  Scene scene{runtime};
  std::unique_ptr<SceneViewer> viewer;
};

std::size_t countDifferent(const std::vector<unsigned char>& a, const std::vector<unsigned char>& b,
                           int tolerance) {
  std::size_t n = 0;
  for (std::size_t p = 0; p + 2 < a.size(); p += 3)
    for (int c = 0; c < 3; ++c)
      if (std::abs(int(a[p + c]) - int(b[p + c])) > tolerance) {
        ++n;
        break;
      }
  return n;
}

TEST_F(SceneViewerTest, TheBeamIsDrawnAndItsDeformedFrameDiffersFromItsRestFrame) {
  SceneViewer& v = makeViewer({.showText = false});  // the text changes with time: off
  v.drawFrame();
  const auto rest = readFrame();
  // Not empty: against a picture of the background alone (its bottom-left pixel's color).
  const std::size_t pixels = rest.size() / 3;
  const std::vector<unsigned char> background = [&] {
    std::vector<unsigned char> b(rest.size());
    for (std::size_t p = 0; p < b.size(); ++p) b[p] = rest[p % 3];
    return b;
  }();
  const std::size_t drawn = countDifferent(rest, background, 8);
  EXPECT_GT(drawn, pixels / 20) << "the beam covers " << drawn << " of " << pixels << " pixels";

  steps(40);  // 0.4 s: the free end falls several centimetres under gravity
  v.drawFrame();
  const auto deformed = readFrame();
  // Per-pixel tolerance 8 of 255 per channel, against rasterization and shading noise.
  const std::size_t changed = countDifferent(rest, deformed, 8);
  std::printf("pixels: %zu drawn of %zu at rest, %zu changed after 40 steps\n", drawn, pixels,
              changed);
  EXPECT_GT(changed, pixels / 100) << changed << " of " << pixels << " pixels changed";
  EXPECT_GT(countDifferent(deformed, background, 8), pixels / 20);
}

/// Compares the frame just drawn with tests/plugins/Viewer/reference/<name>.png: at least
/// 99.5 % of the pixels within 8/255 on every channel (the allowance for another Mesa version's
/// rasterization and shading; the render tests use the same). With
/// STROMA_UPDATE_VIEWER_REFERENCES=1 the frame becomes the reference instead
/// (tests/plugins/Viewer/update-references.sh).
void expectMatchesReference(const std::vector<unsigned char>& rgb, int width, int height,
                            const std::string& name) {
  rendering::Image frame;
  frame.width = width;
  frame.height = height;
  for (std::size_t i = 0; i + 2 < rgb.size(); i += 3)
    frame.rgba.insert(frame.rgba.end(), {rgb[i], rgb[i + 1], rgb[i + 2], 255});
  rendering::flipRows(frame);
  const std::filesystem::path file =
      std::filesystem::path(STROMA_SOURCE_DIR) / "tests/plugins/Viewer/reference" / (name + ".png");
  std::string error;
  if (const char* update = std::getenv("STROMA_UPDATE_VIEWER_REFERENCES");
      update && std::string(update) == "1") {
    ASSERT_TRUE(rendering::writePng(file, frame, error)) << error;
    GTEST_SKIP() << "wrote the reference " << file;
  }
  rendering::Image reference;
  ASSERT_TRUE(rendering::readPng(file, reference, error)) << error;
  ASSERT_EQ(reference.width, width);
  ASSERT_EQ(reference.height, height);
  std::size_t off = 0;
  for (std::size_t p = 0; p < frame.rgba.size(); p += 4)
    for (int c = 0; c < 3; ++c)
      if (std::abs(int(frame.rgba[p + c]) - int(reference.rgba[p + c])) > 8) {
        ++off;
        break;
      }
  const std::size_t pixels = frame.rgba.size() / 4;
  EXPECT_LE(off, pixels / 200) << name << ": " << off << " of " << pixels
                               << " pixels differ from the reference by more than 8";
}

// The frames of HexaBeam at rest and after 40 steps (one thread, so the same numbers on any
// machine), text hidden, against their reference pictures.
TEST_F(SceneViewerTest, RestAndDeformedFramesMatchTheirReferencePictures) {
  scene.setThreadCount(1);
  SceneViewer& v = makeViewer({.showText = false});
  ASSERT_EQ(v.width(), kWidth);
  ASSERT_EQ(v.height(), kHeight);
  v.drawFrame();
  expectMatchesReference(readFrame(), kWidth, kHeight, "hexabeam-rest");
  steps(40);
  v.drawFrame();
  expectMatchesReference(readFrame(), kWidth, kHeight, "hexabeam-step40");
}

TEST_F(SceneViewerTest, ShiftDragPullsTheGrabbedVertexTowardTheMouseAndReleaseRemovesTheSpring) {
  SceneViewer& v = makeViewer();
  // A vertex of the beam's front face (z = 0.05, facing the default camera) near the free end.
  const Vec3d vertexAtRest(0.4 - 0.4 / 12, 0.05 / 3, 0.05);
  const auto& x = beam().readCoord(VecId::position());
  std::size_t expected = 0;
  for (std::size_t i = 0; i < x.size(); ++i)
    if ((x[i] - vertexAtRest).norm() < (x[expected] - vertexAtRest).norm()) expected = i;
  ASSERT_LT((x[expected] - vertexAtRest).norm(), 1e-9);
  const rendering::PixelPoint p = v.camera().project(vertexAtRest, v.width(), v.height());
  ASSERT_TRUE(p.inFront);

  // Press with shift one pixel off the vertex: its triangle is met, the vertex is the nearest.
  v.cursorMoved(p.x + 1, p.y + 1);
  v.mouseButton(GLFW_MOUSE_BUTTON_LEFT, GLFW_PRESS, GLFW_MOD_SHIFT);
  ASSERT_TRUE(v.mouseSpring().active());
  EXPECT_EQ(v.mouseSpring().picked().state, &beam());
  EXPECT_EQ(v.mouseSpring().picked().index, expected);
  Node& beamNode = *scene.root().findChild("Beam");
  const auto* spring = dynamic_cast<const MouseSpringForceField*>(beamNode.findObject("mouseSpring"));
  ASSERT_NE(spring, nullptr);
  // The beam's mass is 1000 kg/m^3 x 0.4 x 0.1 x 0.1 m^3 = 4 kg: 4000 N/m by default.
  EXPECT_NEAR(spring->d_stiffness.value(), 4000.0, 1e-6);

  // Drag 40 pixels up and 20 right: the target moves up and right, at the vertex's depth.
  v.cursorMoved(p.x + 21, p.y - 39);
  const Vec3d target = spring->d_target.value();
  EXPECT_GT(target.y(), vertexAtRest.y() + 0.03);
  EXPECT_NEAR(target.z(), vertexAtRest.z(), 1e-9);
  const double before = (x[expected] - target).norm();
  steps(30);
  const double after = (beam().readCoord(VecId::position())[expected] - target).norm();
  // The spring (4000 N/m) is 50 times stiffer than the cantilever at its tip (3 E I / L^3 =
  // 78 N/m): within 0.3 s the vertex closes at least half the gap (three quarters measured),
  // against gravity.
  std::printf("gap to the mouse target: %.4f m -> %.4f m after 30 steps\n", before, after);
  EXPECT_LT(after, 0.5 * before) << "gap " << before << " m -> " << after << " m";
  EXPECT_GT(beam().readCoord(VecId::position())[expected].y(), vertexAtRest.y());

  v.mouseButton(GLFW_MOUSE_BUTTON_LEFT, GLFW_RELEASE, 0);
  EXPECT_FALSE(v.mouseSpring().active());
  EXPECT_EQ(beamNode.findObject("mouseSpring"), nullptr);
  steps(1);  // and the scene steps on without it
}

TEST_F(SceneViewerTest, AShiftPressOnTheBackgroundGrabsNothing) {
  SceneViewer& v = makeViewer();
  v.cursorMoved(2, 2);
  v.mouseButton(GLFW_MOUSE_BUTTON_LEFT, GLFW_PRESS, GLFW_MOD_SHIFT);
  EXPECT_FALSE(v.mouseSpring().active());
  EXPECT_EQ(scene.root().findChild("Beam")->findObject("mouseSpring"), nullptr);
}

TEST_F(SceneViewerTest, MouseMovesTheCameraAndKeysDriveTheSimulation) {
  SceneViewer& v = makeViewer();
  const rendering::Camera start = v.camera();
  v.cursorMoved(100, 100);
  v.mouseButton(GLFW_MOUSE_BUTTON_LEFT, GLFW_PRESS, 0);
  v.cursorMoved(140, 100);
  v.mouseButton(GLFW_MOUSE_BUTTON_LEFT, GLFW_RELEASE, 0);
  EXPECT_GT(start.forward().dot(v.camera().forward()), 0.0);
  EXPECT_LT(start.forward().dot(v.camera().forward()), 1.0 - 1e-3) << "orbit";
  const Vec3d lookAt = v.camera().lookAt;
  v.mouseButton(GLFW_MOUSE_BUTTON_RIGHT, GLFW_PRESS, 0);
  v.cursorMoved(140, 130);
  v.mouseButton(GLFW_MOUSE_BUTTON_RIGHT, GLFW_RELEASE, 0);
  EXPECT_GT((v.camera().lookAt - lookAt).norm(), 1e-4) << "pan";
  const double distance = v.camera().distance;
  v.scrolled(1);
  EXPECT_NEAR(v.camera().distance, 0.9 * distance, 1e-12) << "zoom";

  EXPECT_FALSE(v.running());  // HexaBeam does not say animate="1"
  v.key(GLFW_KEY_SPACE, GLFW_PRESS, 0);
  EXPECT_TRUE(v.running());
  ASSERT_TRUE(v.advance());
  v.key(GLFW_KEY_SPACE, GLFW_PRESS, 0);
  EXPECT_FALSE(v.running());
  v.key(GLFW_KEY_RIGHT, GLFW_PRESS, 0);
  ASSERT_TRUE(v.advance());
  EXPECT_NEAR(scene.root().time(), 0.02, 1e-12);
  ASSERT_TRUE(v.advance());  // paused: no step
  EXPECT_NEAR(scene.root().time(), 0.02, 1e-12);
  EXPECT_NE(v.statusLines().front().find("paused"), std::string::npos);

  const Vec3d moved = beam().readCoord(VecId::position()).back();
  v.key(GLFW_KEY_R, GLFW_PRESS, 0);  // reset: the scene is read again
  EXPECT_EQ(scene.root().time(), 0.0);
  const Vec3d reset = beam().readCoord(VecId::position()).back();
  EXPECT_GT((moved - reset).norm(), 1e-6);
  EXPECT_EQ(reset, beam().readCoord(VecId::restPosition()).back());
  v.drawFrame();  // the drawer follows the new graph

  EXPECT_FALSE(v.quitRequested());
  v.key(GLFW_KEY_Q, GLFW_PRESS, 0);
  EXPECT_TRUE(v.quitRequested());
}

TEST_F(SceneViewerTest, TheSKeyWritesTheNextScreenshotOfTheWorkingFolder) {
  SceneViewer& v = makeViewer();
  test::TempDir dir;
  const std::filesystem::path before = std::filesystem::current_path();
  std::filesystem::current_path(dir.path());
  dir.write("stroma-view-0000.png", "taken");  // an existing one is kept, not overwritten
  v.key(GLFW_KEY_S, GLFW_PRESS, 0);
  v.drawFrame();
  std::filesystem::current_path(before);
  rendering::Image image;
  std::string error;
  ASSERT_TRUE(rendering::readPng(dir.path() / "stroma-view-0001.png", image, error)) << error;
  EXPECT_EQ(image.width, v.width());
  EXPECT_EQ(image.height, v.height());
  // The beam is in it: the centre pixel is not the top-left corner's background.
  const auto pixel = [&](int x, int y) {
    const std::size_t i = 4 * (static_cast<std::size_t>(y) * image.width + x);
    return Vec3d(image.rgba[i], image.rgba[i + 1], image.rgba[i + 2]);
  };
  EXPECT_GT((pixel(image.width / 2, image.height / 2) - pixel(0, 0)).norm(), 30.0);
  EXPECT_NE(v.statusLines().back().find("saved"), std::string::npos);
}

}  // namespace
}  // namespace stroma::viewer
