// SPDX-License-Identifier: MIT
// SphereLoader in scenes: SOFA's sphere files through the data path, the transformation of the
// centers and the radii, outputs linked by a state, and the errors a user sees for a bad file
// (the file, the line in it and the field of that line, on the loader's filename field).
#include <gtest/gtest.h>

#include <sstream>

#include "plugins/MeshIO/SceneFixture.h"

namespace stroma::test {
namespace {

using SphereLoaderTest = SceneFixture;

std::string wrap(const std::string& body) { return "<Node name=\"root\">\n" + body + "</Node>\n"; }

std::vector<double> numbers(const std::string& text) {
  std::vector<double> values;
  std::istringstream in(text);
  for (double x; in >> x;) values.push_back(x);
  return values;
}

const char* kTwoSpheres =
    "sph 1.0\n"
    "nums 2\n"
    "sphe 1 1 0 0 0.5\n"
    "sphe 2 0 0 1 0.25\n";

TEST_F(SphereLoaderTest, SofaFilesThroughTheDataPath) {
  const auto share = std::filesystem::path(STROMA_SHARED_DIR) / "sofa/share";
  if (!std::filesystem::exists(share / "mesh/liver.sph"))
    GTEST_SKIP() << "no SOFA sphere files (../shared absent)";
  runtime.addDataDirectory(share);
  ASSERT_TRUE(
      load(wrap("<SphereLoader name=\"liver\" filename=\"mesh/liver.sph\"/>\n"
                "<SphereLoader name=\"floor\" filename=\"mesh/floor.sph\"/>\n"
                "<SphereLoader name=\"dragon\" filename=\"mesh/dragon.sph\"/>\n"
                "<SphereLoader name=\"cube\" filename=\"mesh/smCube27b.sph\"/>\n"
                "<Node name=\"n\"><MechanicalObject name=\"dofs\" "
                "position=\"@../cube.position\"/></Node>\n")))
      << messages();
  EXPECT_EQ(scene.log().count(MessageLevel::warning), 0u) << messages();
  const std::pair<const char*, std::size_t> counts[] = {
      {"/liver", 34}, {"/floor", 2520}, {"/dragon", 59}, {"/cube", 27}};
  for (const auto& [loader, count] : counts) {
    EXPECT_EQ(numbers(value(loader, "position")).size(), 3 * count) << loader;
    EXPECT_EQ(numbers(value(loader, "listRadius")).size(), count) << loader;
  }
  EXPECT_EQ(value("/n/dofs", "position"), value("/cube", "position"));
  EXPECT_EQ(value("/cube", "listRadius").substr(0, 8), "2.5 2.5 ");
}

TEST_F(SphereLoaderTest, TransformMovesCentersAndScalesRadii) {
  const std::string file = write("two.sph", kTwoSpheres);
  ASSERT_TRUE(load(wrap("<SphereLoader name=\"a\" filename=\"" + file +
                        "\" scale=\"2\" rotation=\"0 0 90\" translation=\"10 0 0\"/>\n"
                        "<SphereLoader name=\"b\" filename=\"" +
                        file +
                        "\" scale3d=\"-3 3 3\"/>\n"
                        "<MechanicalObject name=\"dofs\" src=\"@a\"/>\n")))
      << messages();
  EXPECT_EQ(scene.log().count(MessageLevel::warning), 0u) << messages();
  // (1, 0, 0) scaled to (2, 0, 0), turned 90 degrees about z to (0, 2, 0), moved by (10, 0, 0);
  // (0, 0, 1) to (0, 0, 2), then (10, 0, 2). Radii times 2.
  const auto a = numbers(value("/a", "position"));
  const std::vector<double> expected = {10, 2, 0, 10, 0, 2};
  ASSERT_EQ(a.size(), 6u);
  for (std::size_t i = 0; i < 6; ++i) EXPECT_NEAR(a[i], expected[i], 1e-15) << i;
  EXPECT_EQ(value("/a", "listRadius"), "1 0.5");
  // A mirror with |s| = 3 on every axis is uniform: radii times 3.
  EXPECT_EQ(value("/b", "position"), "-3 0 0 0 0 3");
  EXPECT_EQ(value("/b", "listRadius"), "1.5 0.75");
  // src copies the outputs once, not the transformation.
  EXPECT_EQ(value("/dofs", "position"), value("/a", "position"));
  EXPECT_EQ(value("/dofs", "translation"), "0 0 0");
}

TEST_F(SphereLoaderTest, NonUniformScaleWarnsAndCoversTheEllipsoid) {
  const std::string file = write("two.sph", kTwoSpheres);
  ASSERT_TRUE(
      load(wrap("<SphereLoader name=\"a\" filename=\"" + file + "\" scale3d=\"1 2 3\"/>\n")))
      << messages();
  EXPECT_EQ(value("/a", "position"), "1 0 0 0 0 3");
  EXPECT_EQ(value("/a", "listRadius"), "1.5 0.75");  // times the largest factor, 3
  const Message m = find(MessageLevel::warning, "turns spheres into ellipsoids");
  EXPECT_EQ(m.field, "scale3d");
}

TEST_F(SphereLoaderTest, BadFileNamesFileLineAndField) {
  struct Case {
    const char* name;
    std::string bytes;
    std::string expected;
  };
  const Case cases[] = {
      {"empty.sph", "", "line 1: the file is empty"},
      {"junk.sph",
       std::string("\x7f"
                   "ELF\x02\x01\x01\0\0\0",
                   10),
       "line 1: expected the header 'sph 1.0'"},
      {"short.sph", "sph 1.0\nsphe 1 0 0 0\n", "line 2: expected 5 numbers after 'sphe'"},
      {"word.sph", "sph 1.0\n# a comment\nsphe 1 0 zero 0 1\n",
       "line 3: expected the y coordinate of the center, a finite number, got 'zero'"},
      {"negative.sph", "sph 1.0\nsphe 1 0 0 0 -2\n",
       "line 2: the radius of the sphere '-2' is negative"},
      {"infinite.sph", "sph 1.0\nsphe 1 0 0 0 inf\n",
       "line 2: expected the radius of the sphere, a finite number >= 0, got 'inf'"},
      {"nums.sph", "sph 1.0\nnums 3\nsphe 1 0 0 0 1\n",
       "line 2: 'nums' announces 3 spheres, the file has 1"},
      {"keyword.sph", "sph 1.0\nsphere 1 0 0 0 1\n",
       "line 2: expected 'sphe', 'nums' or a comment '#', got 'sphere'"},
  };
  std::string body;
  std::vector<std::string> paths;
  for (const Case& c : cases) {
    paths.push_back(write(c.name, c.bytes));
    body += "<SphereLoader filename=\"" + paths.back() + "\"/>\n";
  }
  EXPECT_FALSE(load(wrap(body)));
  const auto errors = messagesAt(MessageLevel::error);
  ASSERT_EQ(errors.size(), std::size(cases)) << messages();
  for (std::size_t i = 0; i < std::size(cases); ++i) {
    SCOPED_TRACE(cases[i].name);
    const Message m = find(MessageLevel::error, cases[i].expected);
    EXPECT_NE(m.text.find("cannot read sphere file '" + paths[i] + "'"), std::string::npos)
        << m.text;
    EXPECT_EQ(m.field, "filename");
    EXPECT_EQ(m.componentClass, "SphereLoader");
    EXPECT_EQ(m.where.line, static_cast<int>(i) + 2);  // the loader's line in the scene
  }
}

TEST_F(SphereLoaderTest, MissingFileIsReportedOnce) {
  EXPECT_FALSE(
      load(wrap("<SphereLoader name=\"a\" filename=\"no/such/spheres.sph\"/>\n"
                "<MechanicalObject position=\"@a.position\"/>\n")));
  const auto errors = messagesAt(MessageLevel::error);
  ASSERT_EQ(errors.size(), 1u) << messages();
  EXPECT_NE(errors[0].text.find("no/such/spheres.sph' not found"), std::string::npos)
      << errors[0].text;
  EXPECT_EQ(errors[0].field, "filename");
  EXPECT_EQ(errors[0].where.line, 2);
}

TEST_F(SphereLoaderTest, NoFileAndBadScale) {
  const std::string file = write("two.sph", kTwoSpheres);
  EXPECT_FALSE(load(wrap("<SphereLoader name=\"b\"/>\n<SphereLoader name=\"c\" filename=\"" + file +
                         "\" scale=\"1 2\"/>\n")));
  EXPECT_EQ(find(MessageLevel::error, "no file given: set filename to a sphere file").field,
            "filename");
  EXPECT_EQ(find(MessageLevel::error, "expected one number (or three), got 2").field, "scale");
}

}  // namespace
}  // namespace stroma::test
