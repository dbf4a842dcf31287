// SPDX-License-Identifier: MIT
// SparseGridTopology built from volume images in small scenes: fileImage (MetaImage, NRRD),
// SOFA's filename with an image extension, SOFA's .raw with dataResolution and voxelSize,
// threshold and labels, the image's box, nbVirtualFinerLevels; the bad input (no inside voxel,
// a .raw without its resolution, a bad header); the bundled scene
// scenes/sparsegrid/VolumeImage.scn run for 20 steps.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <numbers>
#include <sstream>

#include "image/VolumeImage.h"
#include "plugins/MeshIO/SceneFixture.h"
#include "topology/MeshGeometry.h"

namespace stroma::test {
namespace {

class SparseGridImageTest : public SceneFixture {
 protected:
  static std::string wrap(const std::string& body) {
    return "<Node name=\"root\" gravity=\"0 -9.81 0\" dt=\"0.01\">\n" + body + "</Node>\n";
  }
  /// Sum over the hexahedra of volume fraction x hexahedron volume.
  double filledVolume(const std::string& path) {
    const Topology* t = topology(path);
    std::istringstream in(value(path, "volumeFractions"));
    double volume = 0;
    for (std::size_t e = 0; e < t->hexahedra().size(); ++e) {
      double f = 0;
      in >> f;
      volume += f * signedVolume(t->positions(), t->hexahedra()[e]);
    }
    return volume;
  }
  std::size_t count(const std::string& path, const std::string& type) {
    std::istringstream in(value(path, "cellTypes"));
    std::size_t n = 0;
    for (std::string word; in >> word;) n += word == type;
    return n;
  }
  std::size_t warnings() { return scene.log().count(MessageLevel::warning); }

  /// n^3 8-bit voxels of size 1/n on [0, 1]^3: value 200 inside the sphere of radius 0.4 around
  /// the centre, 100 in the shell out to 0.45, 0 outside; also the count of each value.
  std::string sphereVoxels(int n, std::array<int, 3>& counts) {
    std::string bytes;
    counts = {0, 0, 0};
    for (int k = 0; k < n; ++k)
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
          const double r = (Vec3d(i + 0.5, j + 0.5, k + 0.5) / n - Vec3d::Constant(0.5)).norm();
          const int v = r <= 0.4 ? 2 : r <= 0.45 ? 1 : 0;
          ++counts[std::size_t(v)];
          bytes += char(v * 100);
        }
    return bytes;
  }
  /// The sphere as a MetaImage pair (.mhd + .raw); returns the header's path.
  std::string sphereMetaImage(int n, std::array<int, 3>& counts) {
    write("sphere.raw", sphereVoxels(n, counts));
    std::ostringstream header;
    header.precision(17);
    header << "ObjectType = Image\nNDims = 3\nDimSize = " << n << " " << n << " " << n
           << "\nElementSpacing = " << 1.0 / n << " " << 1.0 / n << " " << 1.0 / n
           << "\nOffset = " << 0.5 / n << " " << 0.5 / n << " " << 0.5 / n
           << "\nElementType = MET_UCHAR\nElementDataFile = sphere.raw\n";
    return write("sphere.mhd", header.str());
  }
};

TEST_F(SparseGridImageTest, MetaImageGridHasTheVoxelsVolume) {
  std::array<int, 3> counts{};
  const std::string file = sphereMetaImage(24, counts);
  // 9 cells across 24 voxels: cell faces cut voxels. Default selection: voxels > 0.
  ASSERT_TRUE(
      load(wrap("<SparseGridTopology name=\"grid\" fileImage=\"" + file + "\" n=\"10 10 10\"/>\n")))
      << messages();
  EXPECT_EQ(warnings(), 0u) << messages();
  const double voxel = std::pow(1.0 / 24, 3);
  const double inside = (counts[1] + counts[2]) * voxel;
  EXPECT_NEAR(filledVolume("/grid"), inside, 1e-12 * inside);
  const double ball = 4.0 / 3.0 * std::numbers::pi * std::pow(0.45, 3);
  EXPECT_NEAR(inside, ball, 0.02 * ball);
  EXPECT_GT(count("/grid", "full"), 0u);
  EXPECT_GT(count("/grid", "boundary"), 0u);
  // The grid's box is the image's: [0, 1]^3.
  Vec3d lo = Vec3d::Constant(1e9), hi = -lo;
  for (const Vec3d& p : topology("/grid")->positions()) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  EXPECT_GE(lo.minCoeff(), -1e-12);
  EXPECT_LE(hi.maxCoeff(), 1 + 1e-12);
}

TEST_F(SparseGridImageTest, ThresholdLabelsAndSofasFilename) {
  std::array<int, 3> counts{};
  const std::string mhd = sphereMetaImage(16, counts);
  const double voxel = std::pow(1.0 / 16, 3);
  // threshold: voxels >= 150 (the inner ball only); filename (SOFA's name) with .mhd.
  ASSERT_TRUE(load(wrap("<SparseGridTopology name=\"inner\" filename=\"" + mhd +
                        "\" n=\"9 9 9\" threshold=\"150\"/>\n"
                        "<SparseGridTopology name=\"shell\" fileTopology=\"" +
                        mhd +
                        "\" n=\"9 9 9\" labels=\"100\"/>\n"
                        "<SparseGridTopology name=\"both\" fileImage=\"" +
                        mhd + "\" n=\"9 9 9\" labels=\"100 200\" threshold=\"1000\"/>\n")))
      << messages();
  EXPECT_EQ(warnings(), 0u) << messages();
  EXPECT_NEAR(filledVolume("/inner"), counts[2] * voxel, 1e-12);
  EXPECT_NEAR(filledVolume("/shell"), counts[1] * voxel, 1e-12);
  // labels win over threshold.
  EXPECT_NEAR(filledVolume("/both"), (counts[1] + counts[2]) * voxel, 1e-12);
  // The shell has a hole: its core cells are dropped, so it keeps fewer full cells.
  EXPECT_LT(count("/shell", "full"), count("/both", "full"));
}

TEST_F(SparseGridImageTest, NrrdAndVirtualFinerLevels) {
  std::array<int, 3> counts{};
  const std::string voxels = sphereVoxels(32, counts);
  const std::string file = write("sphere.nrrd",
                                 "NRRD0004\ntype: uchar\ndimension: 3\nsizes: 32 32 32\n"
                                 "spacings: 0.03125 0.03125 0.03125\nencoding: raw\n\n" +
                                     voxels);
  ASSERT_TRUE(load(wrap("<SparseGridTopology name=\"fine\" fileImage=\"" + file +
                        "\" n=\"21 21 21\"/>\n"
                        "<SparseGridTopology name=\"coarse\" fileImage=\"" +
                        file + "\" n=\"6 6 6\" nbVirtualFinerLevels=\"2\"/>\n")))
      << messages();
  // Without "space origin", voxel (0,0,0) is centred at 0: the box starts half a voxel lower.
  const double inside = (counts[1] + counts[2]) * std::pow(0.03125, 3);
  EXPECT_NEAR(filledVolume("/fine"), inside, 1e-12);
  EXPECT_NEAR(filledVolume("/coarse"), inside, 1e-12);
  EXPECT_EQ(topology("/coarse")->hexahedra().size(), 125u - 8u);  // the 8 corners are empty
  EXPECT_GT(topology("/fine")->hexahedra().size(), 1000u);
}

TEST_F(SparseGridImageTest, SofasRawFileWithDataResolution) {
  std::array<int, 3> counts{};
  const std::string file = write("voxels.raw", sphereVoxels(8, counts));
  ASSERT_TRUE(load(wrap("<SparseGridTopology name=\"grid\" filename=\"" + file +
                        "\" dataResolution=\"8 8 8\" voxelSize=\"0.1 0.1 0.1\" n=\"5 5 5\"/>\n")))
      << messages();
  // The image covers [0, 0.8]^3; cells of two voxels: fractions are multiples of 1/8.
  EXPECT_NEAR(filledVolume("/grid"), (counts[1] + counts[2]) * 1e-3, 1e-14);
  for (const Vec3d& p : topology("/grid")->positions()) {
    EXPECT_GE(p.minCoeff(), -1e-12);
    EXPECT_LE(p.maxCoeff(), 0.8 + 1e-12);
  }
  std::istringstream fractions(value("/grid", "volumeFractions"));
  for (double f; fractions >> f;) EXPECT_NEAR(f * 8, std::round(f * 8), 1e-12);
}

TEST_F(SparseGridImageTest, NoInsideVoxelIsAnError) {
  std::array<int, 3> counts{};
  const std::string file = sphereMetaImage(8, counts);
  EXPECT_FALSE(load(wrap("<SparseGridTopology name=\"grid\" fileImage=\"" + file +
                         "\" threshold=\"250\" n=\"3 3 3\"/>\n")));
  const Message m = find(MessageLevel::error, "empty image: no voxel >= 250");
  EXPECT_EQ(m.field, "threshold");
  EXPECT_NE(m.text.find("values from 0 to 200"), std::string::npos) << m.text;
  scene.unload();
  EXPECT_FALSE(load(wrap("<SparseGridTopology name=\"grid\" fileImage=\"" + file +
                         "\" labels=\"7 9\" n=\"3 3 3\"/>\n")));
  EXPECT_EQ(find(MessageLevel::error, "no voxel with a label among 7 9").field, "labels");
}

TEST_F(SparseGridImageTest, BadImageInputIsAnErrorNamingTheField) {
  // A .raw without its resolution.
  const std::string raw = write("plain.raw", std::string(8, '\1'));
  EXPECT_FALSE(
      load(wrap("<SparseGridTopology name=\"grid\" filename=\"" + raw + "\" n=\"3 3 3\"/>\n")));
  EXPECT_EQ(find(MessageLevel::error, "give dataResolution").field, "dataResolution");
  scene.unload();
  // A .raw shorter than its resolution says.
  EXPECT_FALSE(load(wrap("<SparseGridTopology name=\"grid\" filename=\"" + raw +
                         "\" dataResolution=\"3 3 3\" n=\"3 3 3\"/>\n")));
  EXPECT_EQ(find(MessageLevel::error, "expected 27").field, "filename");
  scene.unload();
  // A header with an unknown type: the file, the line and the header field.
  const std::string bad = write("bad.mha",
                                "NDims = 3\nDimSize = 2 2 2\nElementType = MET_HALF\n"
                                "ElementDataFile = LOCAL\n12345678");
  EXPECT_FALSE(
      load(wrap("<SparseGridTopology name=\"grid\" fileImage=\"" + bad + "\" n=\"3 3 3\"/>\n")));
  const Message m = find(MessageLevel::error, "line 3: ElementType");
  EXPECT_EQ(m.field, "fileImage");
  EXPECT_NE(m.text.find("bad.mha"), std::string::npos) << m.text;
  scene.unload();
  // An image and a surface file: the image wins, with a warning.
  std::array<int, 3> counts{};
  const std::string mhd = sphereMetaImage(8, counts);
  const std::string obj = write("mesh.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  ASSERT_TRUE(load(wrap("<SparseGridTopology name=\"grid\" fileImage=\"" + mhd +
                        "\" fileTopology=\"" + obj + "\" n=\"3 3 3\"/>\n")))
      << messages();
  EXPECT_EQ(find(MessageLevel::warning, "the mesh file is ignored").field, "fileImage");
  scene.unload();
  // A missing image.
  EXPECT_FALSE(
      load(wrap("<SparseGridTopology name=\"grid\" fileImage=\"no/such/image.nrrd\" "
                "n=\"3 3 3\"/>\n")));
  EXPECT_EQ(find(MessageLevel::error, "image.nrrd").field, "fileImage");
}

TEST_F(SparseGridImageTest, BundledVolumeImageSceneRuns) {
  const std::filesystem::path file =
      std::filesystem::path(STROMA_SOURCE_DIR) / "scenes/sparsegrid/VolumeImage.scn";
  const std::filesystem::path image =
      std::filesystem::path(STROMA_SOURCE_DIR) / "share/image/organ_labels.nrrd";
  ASSERT_TRUE(scene.loadFile(file)) << messages();
  // The grid holds the volume of the voxels labelled 1 or 2.
  image::VolumeImage labels;
  std::string error;
  ASSERT_TRUE(image::readVolumeImage(image.string(), labels, error)) << error;
  double inside = 0;
  for (double v : labels.values) inside += v == 1 || v == 2;
  inside *= labels.spacing.prod();
  EXPECT_NEAR(filledVolume("/Organ/grid"), inside, 1e-12 * inside);
  EXPECT_GT(count("/Organ/grid", "full"), 0u);
  EXPECT_GT(count("/Organ/grid", "boundary"), 0u);

  const Topology* t = topology("/Organ/grid");
  for (int i = 0; i < 20; ++i) ASSERT_TRUE(scene.step()) << messages();
  EXPECT_EQ(scene.log().errorCount(), 0u) << messages();
  EXPECT_EQ(warnings(), 0u) << messages();
  std::istringstream in(value("/Organ/dofs", "position"));
  std::vector<Vec3d> x;
  for (double a, b, c; in >> a >> b >> c;) x.emplace_back(a, b, c);
  ASSERT_EQ(x.size(), t->positions().size());
  double lowest = 0, fixedMotion = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    ASSERT_TRUE(x[i].allFinite());
    const double dy = x[i].y() - t->positions()[i].y();
    lowest = std::min(lowest, dy);
    if (t->positions()[i].x() <= 0.02) fixedMotion = std::max(fixedMotion, std::abs(dy));
  }
  EXPECT_LT(lowest, -1e-5);     // the free end sags under gravity
  EXPECT_GT(lowest, -0.05);     // but the organ holds
  EXPECT_EQ(fixedMotion, 0.0);  // the fixed end stays
}

}  // namespace
}  // namespace stroma::test
