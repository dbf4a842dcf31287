// SPDX-License-Identifier: MIT
// The parts of the drawing library that need no OpenGL: display flags, color maps, the font,
// PNG files.
#include <gtest/gtest.h>

#include <fstream>
#include <set>

#include "core/Runtime.h"
#include "plugins/TestPlugin/TestSupport.h"
#include "simulation/Scene.h"
#include "stroma/rendering/BitmapFont.h"
#include "stroma/rendering/ColorMap.h"
#include "stroma/rendering/DisplayFlags.h"
#include "stroma/rendering/PngImage.h"

namespace stroma::rendering {
namespace {

TEST(RenderingDisplayFlags, ReadsSofasWordsInOrder) {
  DisplayFlags flags;
  EXPECT_TRUE(flags.visualModels);
  EXPECT_FALSE(flags.behaviorModels || flags.forceFields || flags.collisionModels ||
               flags.wireframe);
  std::string unknown;
  flags.apply("hideVisual showBehavior showWireFrame showMappings", unknown);
  EXPECT_FALSE(flags.visualModels);
  EXPECT_TRUE(flags.behaviorModels);
  EXPECT_TRUE(flags.forceFields);
  EXPECT_TRUE(flags.wireframe);
  EXPECT_TRUE(unknown.empty()) << unknown;
  flags.apply("hideForceFields showCollisionModels showWireframe hideWireframe", unknown);
  EXPECT_FALSE(flags.forceFields);
  EXPECT_TRUE(flags.collisionModels);
  EXPECT_FALSE(flags.wireframe);
  flags.apply("showAll", unknown);
  EXPECT_TRUE(flags.visualModels && flags.behaviorModels && flags.forceFields &&
              flags.collisionModels);
  flags.apply("showNothingKnown frobnicate", unknown);
  EXPECT_EQ(unknown, "showNothingKnown frobnicate");
}

TEST(RenderingDisplayFlags, StylesNestFromTheRootDown) {
  Runtime runtime;
  Scene scene(runtime);
  ASSERT_TRUE(scene.loadString(R"(<Node name="root">
      <VisualStyle displayFlags="showBehaviorModels hideVisual"/>
      <Node name="A"><Node name="B"><VisualStyle displayFlags="showForceFields"/></Node></Node>
    </Node>)"));
  std::string unknown;
  const Node& a = *scene.root().findChild("A");
  const DisplayFlags atA = sceneDisplayFlags(a, unknown);
  EXPECT_TRUE(atA.behaviorModels);
  EXPECT_FALSE(atA.visualModels);
  const DisplayFlags atB = sceneDisplayFlags(*a.findChild("B"), unknown);
  EXPECT_TRUE(atB.forceFields) << "B's style adds force fields";
  EXPECT_TRUE(atB.behaviorModels) << "and keeps what the root's says";
  EXPECT_FALSE(atB.visualModels);
  EXPECT_FALSE(sceneDisplayFlags(scene.root(), unknown).forceFields);
  EXPECT_TRUE(unknown.empty()) << unknown;
}

TEST(RenderingColorMap, NamesAreCheckedWithTheKnownOnesListed) {
  ColorMapKind kind = ColorMapKind::none;
  std::string error;
  EXPECT_TRUE(parseColorMapKind("Displacement", kind, error));
  EXPECT_EQ(kind, ColorMapKind::displacement);
  EXPECT_TRUE(parseColorMapKind("von-mises", kind, error));
  EXPECT_EQ(kind, ColorMapKind::vonMises);
  EXPECT_FALSE(parseColorMapKind("temperature", kind, error));
  EXPECT_NE(error.find("'temperature'"), std::string::npos) << error;
  EXPECT_NE(error.find("displacement, vonmises"), std::string::npos) << error;
}

TEST(RenderingColorMap, RampGoesFromDarkBlueToRedAndClamps) {
  EXPECT_TRUE(rampColor(0).isApprox(rampColor(-3)));
  EXPECT_TRUE(rampColor(1).isApprox(rampColor(7)));
  EXPECT_TRUE(rampColor(std::nan("")).isApprox(rampColor(0)));
  EXPECT_GT(rampColor(0)[2], rampColor(0)[0]) << "blue at the bottom";
  EXPECT_GT(rampColor(1)[0], rampColor(1)[2]) << "red at the top";
  // Neighbouring values get neighbouring colors (no jump in the ramp).
  for (double t = 0; t < 1; t += 0.01) EXPECT_LT((rampColor(t + 0.01) - rampColor(t)).norm(), 0.06);
}

TEST(RenderingColorMap, DisplacementIsTheDistanceFromTheRestPositions) {
  Runtime runtime;
  Scene scene(runtime);
  ASSERT_TRUE(scene.loadString(R"(<Node name="root">
      <MechanicalObject name="dofs" rest_position="0 0 0  1 0 0  0 1 0"
                        position="0 0 0  1 0.3 0.4  0 1 -2"/>
    </Node>)"));
  std::vector<PointField> fields;
  std::string error;
  ASSERT_TRUE(computePointFields(scene.root(), ColorMapKind::displacement, fields, error)) << error;
  ASSERT_EQ(fields.size(), 1u);
  EXPECT_EQ(fields[0].values, (std::vector<double>{0.0, 0.5, 2.0}));
  double min = -1, max = -1;
  fieldRange(fields, min, max);
  EXPECT_EQ(min, 0.0);
  EXPECT_EQ(max, 2.0);
}

TEST(RenderingColorMap, VonMisesWithoutAStressFieldSaysSo) {
  Runtime runtime;
  Scene scene(runtime);
  ASSERT_TRUE(scene.loadString(R"(<Node name="root"><MechanicalObject position="0 0 0"/></Node>)"));
  std::vector<PointField> fields;
  std::string error;
  EXPECT_FALSE(computePointFields(scene.root(), ColorMapKind::vonMises, fields, error));
  EXPECT_NE(error.find("provides stress"), std::string::npos) << error;
}

TEST(RenderingColorMap, LegendNumbersHaveThreeSignificantDigits) {
  EXPECT_EQ(legendNumber(0), "0");
  EXPECT_EQ(legendNumber(0.31234), "0.312");
  EXPECT_EQ(legendNumber(15234.0), "1.52e+04");
  EXPECT_EQ(legendNumber(-2.5e-7), "-2.5e-07");
}

TEST(RenderingBitmapFont, HasADistinctGlyphForEveryCharacterANumberOrLabelNeeds) {
  const std::string needed = "0123456789ABCDEFGHIJKLMNOPQRSTUVWXYZe .,-+:/=%()_";
  std::set<std::array<std::uint8_t, kGlyphHeight>> seen;
  for (char c : needed) {
    EXPECT_TRUE(hasGlyph(c)) << "'" << c << "'";
    EXPECT_TRUE(seen.insert(glyphRows(c)).second) << "'" << c << "' looks like another glyph";
  }
  EXPECT_EQ(glyphRows('a'), glyphRows('A')) << "lower case is drawn as upper case";
  EXPECT_NE(glyphRows('e'), glyphRows('E')) << "except e, for exponents";
  EXPECT_FALSE(hasGlyph('~'));
  EXPECT_EQ(textWidth("1.5e+04", 2), (7 * kGlyphAdvance - 1) * 2);
  EXPECT_EQ(textWidth("", 3), 0);
}

TEST(RenderingPngImage, WritesAndReadsBackTheSamePixels) {
  test::TempDir dir;
  Image image;
  image.width = 7;
  image.height = 3;
  for (int i = 0; i < 7 * 3 * 4; ++i) image.rgba.push_back(static_cast<std::uint8_t>(i * 11));
  std::string error;
  ASSERT_TRUE(writePng(dir.path() / "a.png", image, error)) << error;
  Image read;
  ASSERT_TRUE(readPng(dir.path() / "a.png", read, error)) << error;
  EXPECT_EQ(read.width, 7);
  EXPECT_EQ(read.height, 3);
  EXPECT_EQ(read.rgba, image.rgba);
  Image flipped = read;
  flipRows(flipped);
  EXPECT_TRUE(std::equal(flipped.rgba.begin(), flipped.rgba.begin() + 28, image.rgba.end() - 28));
}

TEST(RenderingPngImage, CorruptOrMissingFilesAreRefusedWithAReason) {
  test::TempDir dir;
  Image image;
  std::string error;
  EXPECT_FALSE(readPng(dir.path() / "missing.png", image, error));
  EXPECT_FALSE(error.empty());
  const auto junk = dir.write("junk.png", "this is not a picture");
  error.clear();
  EXPECT_FALSE(readPng(junk, image, error));
  EXPECT_FALSE(error.empty());
  // A real header followed by truncated data.
  Image small;
  small.width = small.height = 64;
  small.rgba.assign(64 * 64 * 4, 200);
  ASSERT_TRUE(writePng(dir.path() / "ok.png", small, error));
  std::ifstream in(dir.path() / "ok.png", std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), {});
  const auto truncated = dir.write("truncated.png", bytes.substr(0, bytes.size() / 2));
  error.clear();
  EXPECT_FALSE(readPng(truncated, image, error));
  EXPECT_FALSE(error.empty());
  EXPECT_FALSE(writePng(dir.path() / "no-such-folder" / "x.png", small, error));
}

}  // namespace
}  // namespace stroma::rendering
