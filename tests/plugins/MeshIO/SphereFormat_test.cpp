// SPDX-License-Identifier: MIT
// The sphere file parser (parseSpheres, plugins/MeshIO/src/formats/SphereFormat.cpp): SOFA's
// files when ../shared is present, the layout variants it must accept (comments, CRLF, blank
// lines, inline comments), and every kind of bad input, each an error naming the line and the
// field of that line, never a crash.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <random>

#include "formats/SphereData.h"

namespace stroma::test {
namespace {

namespace fs = std::filesystem;

#define EXPECT_CONTAINS(text, part) \
  EXPECT_NE(std::string(text).find(part), std::string::npos) << "in: " << (text)

SphereData parseOk(std::string_view bytes) {
  SphereData spheres;
  std::string error;
  EXPECT_TRUE(parseSpheres(bytes, spheres, error)) << error;
  return spheres;
}

std::string parseError(std::string_view bytes) {
  SphereData spheres;
  std::string error;
  EXPECT_FALSE(parseSpheres(bytes, spheres, error)) << "parsed although bad";
  EXPECT_TRUE(spheres.centers.empty() && spheres.radii.empty()) << "spheres left after a failure";
  EXPECT_FALSE(error.empty());
  return error;
}

TEST(SphereFormat, CommentsBlankLinesCrlfAndInlineComments) {
  const SphereData spheres = parseOk(
      "\xEF\xBB\xBFsph 1.0\r\n"
      "# a comment line\r\n"
      "#nums 7   (a commented nums, as in SOFA's liver.sph)\r\n"
      "nums 3\r\n"
      "\r\n"
      "   sphe 1 -1.75 0 +1.75 2.5\r\n"
      "sphe 1 1e-3 -2 3 0   # the index repeats, as in liver.sph\r\n"
      "\tsphe\t-4\t0.5\t0.25\t0.125\t1\n");
  ASSERT_EQ(spheres.centers.size(), 3u);
  EXPECT_EQ(spheres.centers[0], Vec3d(-1.75, 0, 1.75));
  EXPECT_EQ(spheres.centers[1], Vec3d(1e-3, -2, 3));
  EXPECT_EQ(spheres.centers[2], Vec3d(0.5, 0.25, 0.125));
  EXPECT_EQ(spheres.radii, (std::vector<double>{2.5, 0, 1}));
}

TEST(SphereFormat, EveryBadInputNamesTheLineAndTheField) {
  struct Case {
    std::string bytes;
    std::string expected;
  };
  const Case cases[] = {
      {"", "line 1: the file is empty (expected the header 'sph 1.0')"},
      {std::string("\x7f"
                   "ELF\x02\x01\x01\0\0\0",
                   10),
       "line 1: expected the header 'sph 1.0', got '?ELF"},
      {"\nsph 1.0\nsphe 1 0 0 0 1\n", "line 1: expected the header 'sph 1.0', got an empty line"},
      {"sph 2.0\nsphe 1 0 0 0 1\n", "line 1: unsupported version '2.0' in the header"},
      {"sph\nsphe 1 0 0 0 1\n", "line 1: unsupported version (none) in the header"},
      {"sph 1.0 extra\n", "line 1: expected the end of the header 'sph 1.0', got 'extra'"},
      {"sph 1.0\nsphe 1 0 0 0\n",
       "line 2: expected 5 numbers after 'sphe' (index x y z radius), got 4"},
      {"sph 1.0\nsphe 1 0 0 0 1 2\n",
       "line 2: expected 5 numbers after 'sphe' (index x y z radius), got 6"},
      {"sph 1.0\nsphe\n", "line 2: expected 5 numbers after 'sphe' (index x y z radius), got 0"},
      {"sph 1.0\n\nsphe x 0 0 0 1\n",
       "line 3: expected the index of the sphere, an integer, got 'x'"},
      {"sph 1.0\nsphe 1.5 0 0 0 1\n",
       "line 2: expected the index of the sphere, an integer, got '1.5'"},
      {"sph 1.0\nsphe 1 zero 0 0 1\n",
       "line 2: expected the x coordinate of the center, a finite number, got 'zero'"},
      {"sph 1.0\nsphe 1 0 inf 0 1\n",
       "line 2: expected the y coordinate of the center, a finite number, got 'inf'"},
      {"sph 1.0\nsphe 1 0 0 1e999 1\n",
       "line 2: expected the z coordinate of the center, a finite number, got '1e999'"},
      {"sph 1.0\nsphe 1 0 0 0 -0.5\n",
       "line 2: the radius of the sphere '-0.5' is negative (expected a finite number >= 0)"},
      {"sph 1.0\nsphe 1 0 0 0 nan\n",
       "line 2: expected the radius of the sphere, a finite number >= 0, got 'nan'"},
      {"sph 1.0\nsphe 1 0 0 0 -inf\n",
       "line 2: expected the radius of the sphere, a finite number >= 0, got '-inf'"},
      {"sph 1.0\nsphe 1 0 0 0 1,5\n",
       "line 2: expected the radius of the sphere, a finite number >= 0, got '1,5'"},
      {"sph 1.0\nsphere 1 0 0 0 1\n",
       "line 2: expected 'sphe', 'nums' or a comment '#', got 'sphere'"},
      {"sph 1.0\nsphe 1 0 0 0 1\n\x01\x02\x03\x04 junk\n",
       "line 3: expected 'sphe', 'nums' or a comment '#', got '\?\?\?\?'"},
      {"sph 1.0\nnums 3\nsphe 1 0 0 0 1\nsphe 2 0 0 0 1\n",
       "line 2: 'nums' announces 3 spheres, the file has 2"},
      {"sph 1.0\nsphe 1 0 0 0 1\nnums 0\n", "line 3: 'nums' announces 0 spheres, the file has 1"},
      {"sph 1.0\nnums 99999999999999\nsphe 1 0 0 0 1\n",
       "line 2: 'nums' announces 99999999999999 spheres, the file has 1"},
      {"sph 1.0\nnums 1\nnums 1\nsphe 1 0 0 0 1\n",
       "line 3: a second 'nums' line (the first is line 2)"},
      {"sph 1.0\nnums -1\n",
       "line 2: expected the number of spheres after 'nums', an integer >= 0, got '-1'"},
      {"sph 1.0\nnums\n",
       "line 2: expected the number of spheres after 'nums', an integer >= 0, got nothing"},
      {"sph 1.0\nnums 1 2\n", "line 2: expected one number after 'nums', got also '2'"},
      {"sph 1.0\n# only a comment\n",
       "line 2: no sphere in the file (expected lines 'sphe index x y z radius' after the "
       "header)"},
      {"sph 1.0\n", "line 1: no sphere in the file"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.expected);
    EXPECT_CONTAINS(parseError(c.bytes), c.expected);
  }
}

TEST(SphereFormat, RandomBytesAfterAValidStartNeverCrash) {
  // Bytes drawn from the characters of the format and some binary ones, after a valid start:
  // each parse succeeds with consistent spheres or fails naming a line.
  const std::string alphabet = "sphenum#0123456789.-+e \n\r\t\xff";
  std::mt19937 random(15);
  for (int trial = 0; trial < 2000; ++trial) {
    std::string bytes = "sph 1.0\nsphe 1 0 0 0 1\n";
    const int length = static_cast<int>(random() % 80);
    for (int k = 0; k < length; ++k) bytes += alphabet[random() % alphabet.size()];
    SphereData spheres;
    std::string error;
    if (parseSpheres(bytes, spheres, error)) {
      ASSERT_EQ(spheres.centers.size(), spheres.radii.size());
      for (double r : spheres.radii) ASSERT_TRUE(std::isfinite(r) && r >= 0);
    } else {
      ASSERT_EQ(error.rfind("line ", 0), 0u) << error;
    }
  }
}

TEST(SphereFormat, MissingFileAndDirectory) {
  SphereData spheres;
  std::string error;
  EXPECT_FALSE(readSphereFile("/no/such/file.sph", spheres, error));
  EXPECT_EQ(error, "no such file");
  EXPECT_FALSE(readSphereFile(fs::temp_directory_path().string(), spheres, error));
  EXPECT_EQ(error, "not a regular file");
}

// --- SOFA's files -------------------------------------------------------------------------------

class SofaSphereFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!fs::exists(meshDir() / "liver.sph"))
      GTEST_SKIP() << "no SOFA sphere files at " << meshDir() << " (../shared absent)";
  }
  static fs::path meshDir() { return fs::path(STROMA_SHARED_DIR) / "sofa/share/mesh"; }
  SphereData read(const std::string& name) {
    SphereData spheres;
    std::string error;
    EXPECT_TRUE(readSphereFile((meshDir() / name).string(), spheres, error))
        << name << ": " << error;
    EXPECT_EQ(spheres.centers.size(), spheres.radii.size());
    return spheres;
  }
};

TEST_F(SofaSphereFiles, CountsAndValues) {
  // Counts: the uncommented sphe lines (dragon.sph and liver.sph comment their nums line out and
  // some spheres too).
  EXPECT_EQ(read("dragon.sph").centers.size(), 59u);
  EXPECT_EQ(read("liver.sph").centers.size(), 34u);
  const SphereData floor = read("floor.sph");  // nums 2520
  ASSERT_EQ(floor.centers.size(), 2520u);
  EXPECT_EQ(floor.centers.back(), Vec3d(-74.7167816162, -3.32967638969, -70.5059585571));
  EXPECT_EQ(floor.radii.back(), 2.92510700226);
  const SphereData cube = read("smCube27b.sph");  // nums 27
  ASSERT_EQ(cube.centers.size(), 27u);
  EXPECT_EQ(cube.centers.front(), Vec3d(-1.75, -1.75, -1.75));
  EXPECT_EQ(cube.centers.back(), Vec3d(1.75, 1.75, 1.75));
  for (double r : cube.radii) EXPECT_EQ(r, 2.5);
  const SphereData dragon = read("dragon.sph");
  EXPECT_EQ(dragon.centers.front(), Vec3d(-6, -5.2, -1.2));
  EXPECT_EQ(dragon.radii.front(), 2.2);
}

}  // namespace
}  // namespace stroma::test
