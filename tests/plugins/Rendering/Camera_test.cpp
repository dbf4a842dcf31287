// SPDX-License-Identifier: MIT
// The camera's geometry: a fitted view holds the whole box, projection and unprojection are
// inverse, orbit/pan/zoom move what they say, and a scene's InteractiveCamera is read by name.
#include "stroma/rendering/Camera.h"
#include "stroma/rendering/SceneDrawer.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/Runtime.h"
#include "simulation/Scene.h"

namespace stroma::rendering {
namespace {

struct ViewCase {
  Projection projection;
  Quat orientation;
  int width, height;
};

std::vector<ViewCase> viewCases() {
  std::vector<ViewCase> cases;
  const Quat turned = Quat(Eigen::AngleAxisd(0.7, Vec3d(1, 2, 0.5).normalized()));
  for (Projection p : {Projection::perspective, Projection::orthographic})
    for (const Quat& q : {Quat::Identity(), turned})
      for (auto [w, h] : {std::pair{160, 120}, std::pair{120, 400}, std::pair{1280, 720}})
        cases.push_back({p, q, w, h});
  return cases;
}

TEST(RenderingCamera, FitPutsEveryCornerOfTheBoxInView) {
  const Aabb box{Vec3d(-0.11, -0.05, -0.03), Vec3d(0.11, 0.06, 0.07)};
  for (const ViewCase& c : viewCases()) {
    Camera camera;
    camera.projection = c.projection;
    camera.orientation = c.orientation;
    camera.fitBox(box, double(c.width) / c.height);
    double nearestToAnEdge = 1e300;
    for (int i = 0; i < 8; ++i) {
      const Vec3d corner(i & 1 ? box.max.x() : box.min.x(), i & 2 ? box.max.y() : box.min.y(),
                         i & 4 ? box.max.z() : box.min.z());
      const PixelPoint p = camera.project(corner, c.width, c.height);
      EXPECT_TRUE(p.inFront);
      EXPECT_GE(p.x, 0.0);
      EXPECT_LE(p.x, c.width);
      EXPECT_GE(p.y, 0.0);
      EXPECT_LE(p.y, c.height);
      EXPECT_GT(p.depth, 0.0) << "in front of the near plane";
      EXPECT_LT(p.depth, 1.0) << "before the far plane";
      nearestToAnEdge = std::min({nearestToAnEdge, p.x, c.width - p.x, p.y, c.height - p.y});
    }
    // Fitted, not merely inside: some corner is within 10 % of the picture of an edge.
    EXPECT_LT(nearestToAnEdge, 0.1 * std::min(c.width, c.height));
  }
}

TEST(RenderingCamera, FitBesideALegendKeepsTheBoxOutOfTheMargin) {
  const Aabb box{Vec3d(0, -0.05, -0.05), Vec3d(0.4, 0.05, 0.05)};
  const int width = 480, height = 360;
  const int margin = legendWidth(ColorMapKind::displacement, width, height);
  EXPECT_GT(margin, 40);
  EXPECT_LT(margin, width / 3);
  for (Projection projection : {Projection::perspective, Projection::orthographic}) {
    Camera camera;
    camera.projection = projection;
    camera.fitBox(box, width, height, margin);
    double left = 1e300, right = -1e300;
    for (int i = 0; i < 8; ++i) {
      const Vec3d corner(i & 1 ? box.max.x() : box.min.x(), i & 2 ? box.max.y() : box.min.y(),
                         i & 4 ? box.max.z() : box.min.z());
      const PixelPoint p = camera.project(corner, width, height);
      left = std::min(left, p.x);
      right = std::max(right, p.x);
    }
    EXPECT_GE(left, 0.0);
    EXPECT_LE(right, width - margin) << "nothing under the legend";
    // Centred in what is left, up to the perspective's asymmetry.
    EXPECT_NEAR(0.5 * (left + right), 0.5 * (width - margin), 0.05 * width);
  }
}

TEST(RenderingCamera, EmptyBoxGivesAUsableView) {
  Camera camera;
  camera.fitBox(Aabb{}, 1.5);
  EXPECT_TRUE(camera.position().allFinite());
  EXPECT_GT(camera.distance, 0.0);
  EXPECT_LT(camera.zNear, camera.zFar);
}

TEST(RenderingCamera, UnprojectIsTheInverseOfProject) {
  for (const ViewCase& c : viewCases()) {
    Camera camera;
    camera.projection = c.projection;
    camera.orientation = c.orientation;
    camera.fitBox(Aabb{Vec3d(-1, -1, -1), Vec3d(1, 2, 1)}, double(c.width) / c.height);
    for (auto [x, y] : {std::pair{0.5, 0.5}, std::pair{c.width * 0.3, c.height * 0.8},
                        std::pair{c.width - 0.5, c.height - 0.5}}) {
      const Ray ray = camera.unproject(x, y, c.width, c.height);
      EXPECT_NEAR(ray.direction.norm(), 1.0, 1e-12);
      for (double t : {camera.distance * 0.5, camera.distance, camera.distance * 1.7}) {
        const PixelPoint p = camera.project(ray.origin + t * ray.direction, c.width, c.height);
        EXPECT_NEAR(p.x, x, 1e-6);
        EXPECT_NEAR(p.y, y, 1e-6);
      }
    }
  }
}

TEST(RenderingCamera, OrbitTurnsAroundTheLookAtPoint) {
  Camera camera;
  camera.setEyeAndTarget(Vec3d(0, 0, 5), Vec3d(0, 0, 0));
  const Vec3d eye = camera.position(), right = camera.right(), up = camera.up();
  camera.orbit(0.3, 0);
  EXPECT_NEAR((camera.position() - camera.lookAt).norm(), 5.0, 1e-12);
  EXPECT_GT((camera.position() - eye).dot(right), 0.0) << "positive dx moves the eye right";
  EXPECT_NEAR(camera.lookAt.norm(), 0.0, 1e-15);
  EXPECT_NEAR(std::acos(camera.forward().dot(Vec3d(0, 0, -1))), 0.3, 1e-12);
  const Vec3d eye2 = camera.position();
  camera.orbit(0, 0.2);
  EXPECT_GT((camera.position() - eye2).dot(up), 0.0) << "positive dy moves the eye up";
  EXPECT_NEAR((camera.position() - camera.lookAt).norm(), 5.0, 1e-12);
}

TEST(RenderingCamera, PanMovesTheViewByFractionsOfItsHeight) {
  for (Projection projection : {Projection::perspective, Projection::orthographic}) {
    Camera camera;
    camera.projection = projection;
    camera.setEyeAndTarget(Vec3d(1, 2, 6), Vec3d(1, 2, 0));
    camera.fitClipPlanes(Aabb{Vec3d(-1, -1, -1), Vec3d(3, 3, 1)});
    const Vec3d target = camera.lookAt;
    camera.pan(0.25, -0.1);
    // The old target moves left by a quarter of the picture's height and up by a tenth.
    const PixelPoint p = camera.project(target, 400, 200);
    EXPECT_NEAR(p.x, 200 - 0.25 * 200, 1e-9);
    EXPECT_NEAR(p.y, 100 - 0.1 * 200, 1e-9);
    EXPECT_NEAR(camera.distance, 6.0, 1e-12);
  }
}

TEST(RenderingCamera, ZoomScalesTheDistanceAndIgnoresNonsense) {
  Camera camera;
  camera.setEyeAndTarget(Vec3d(0, 0, 4), Vec3d::Zero());
  camera.zoom(0.5);
  EXPECT_DOUBLE_EQ(camera.distance, 2.0);
  EXPECT_TRUE(camera.position().isApprox(Vec3d(0, 0, 2)));
  for (double bad : {0.0, -1.0, std::nan(""), double(INFINITY)}) camera.zoom(bad);
  EXPECT_DOUBLE_EQ(camera.distance, 2.0);
}

TEST(RenderingCamera, EyeAndTargetAlongTheUpHintStillGiveAFrame) {
  Camera camera;
  ASSERT_TRUE(camera.setEyeAndTarget(Vec3d(0, 5, 0), Vec3d::Zero()));
  EXPECT_TRUE(camera.forward().isApprox(Vec3d(0, -1, 0)));
  EXPECT_NEAR(camera.up().dot(camera.forward()), 0.0, 1e-12);
  EXPECT_FALSE(camera.setEyeAndTarget(Vec3d(1, 1, 1), Vec3d(1, 1, 1)));
}

TEST(RenderingCamera, ParsesEyeAndTarget) {
  Vec3d eye, target;
  std::string error;
  ASSERT_TRUE(parseEyeAndTarget("0 0.1 1  0 0 -2e-1", eye, target, error)) << error;
  EXPECT_TRUE(eye.isApprox(Vec3d(0, 0.1, 1)));
  EXPECT_TRUE(target.isApprox(Vec3d(0, 0, -0.2)));
  EXPECT_FALSE(parseEyeAndTarget("0 0 1 0 0", eye, target, error));
  EXPECT_NE(error.find("6 numbers"), std::string::npos) << error;
  EXPECT_FALSE(parseEyeAndTarget("0 0 1 0 0 x", eye, target, error));
  EXPECT_NE(error.find("'x'"), std::string::npos) << error;
  EXPECT_FALSE(parseEyeAndTarget("1 2 3 1 2 3", eye, target, error));
  EXPECT_NE(error.find("same point"), std::string::npos) << error;
}

bool loadScene(Scene& scene, const std::string& objects) {
  return scene.loadString("<Node name=\"root\">" + objects +
                          "<MechanicalObject position=\"0 0 0  1 1 1\"/></Node>");
}

TEST(RenderingCamera, ReadsTheScenesInteractiveCameraByName) {
  Runtime runtime;
  {
    Scene scene(runtime);
    ASSERT_TRUE(loadScene(scene, R"(<InteractiveCamera position="0 0 3" lookAt="0 1 0"
                                     fieldOfView="30" projectionType="Orthographic"/>)"));
    Camera camera;
    std::string warning;
    ASSERT_TRUE(camera.readSceneCamera(scene.root(), warning));
    EXPECT_TRUE(warning.empty()) << warning;
    EXPECT_TRUE(camera.position().isApprox(Vec3d(0, 0, 3)));
    EXPECT_TRUE(camera.lookAt.isApprox(Vec3d(0, 1, 0)));
    EXPECT_TRUE(camera.forward().isApprox(Vec3d(0, 1, -3).normalized()));
    EXPECT_DOUBLE_EQ(camera.fieldOfView, 30.0);
    EXPECT_EQ(camera.projection, Projection::orthographic);
  }
  {
    // Position and orientation (x y z w: a quarter turn about y): they win over lookAt's
    // direction; the distance to lookAt is kept.
    Scene scene(runtime);
    ASSERT_TRUE(loadScene(scene, R"(<InteractiveCamera position="2 0 0"
        orientation="0 0.7071067811865476 0 0.7071067811865476" lookAt="0 0 0"/>)"));
    Camera camera;
    std::string warning;
    ASSERT_TRUE(camera.readSceneCamera(scene.root(), warning));
    EXPECT_TRUE(camera.forward().isApprox(Vec3d(-1, 0, 0)));
    EXPECT_TRUE(camera.position().isApprox(Vec3d(2, 0, 0)));
    EXPECT_NEAR(camera.distance, 2.0, 1e-12);
  }
  {
    Scene scene(runtime);
    ASSERT_TRUE(loadScene(scene, ""));
    Camera camera;
    std::string warning;
    EXPECT_FALSE(camera.readSceneCamera(scene.root(), warning)) << "no camera in the scene";
  }
}

}  // namespace
}  // namespace stroma::rendering
