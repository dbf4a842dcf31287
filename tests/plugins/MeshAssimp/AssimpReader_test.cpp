// SPDX-License-Identifier: MIT
// readAssimpFile on the files share/mesh/make_formats.py writes: the organ surface in OBJ, STL,
// PLY and glTF gives the same points and triangles as Stroma's own OBJ and STL parsers, texture
// coordinates and unit normals; the node transforms of a glTF scene are applied.
#include "AssimpReader.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>

#include "plugins/TestPlugin/TestSupport.h"

namespace stroma::test {
namespace {

std::string shared(const std::string& name) {
  return (std::filesystem::path(STROMA_SOURCE_DIR) / "share/mesh" / name).string();
}

/// The organ surface as Stroma's STL parser gives it: its points merged, in first-use order
/// (the order make_formats.py writes them in), and its triangles.
const MeshData& reference() {
  static const MeshData mesh = [] {
    MeshData m;
    std::string error;
    EXPECT_TRUE(readMeshFile(shared("organ_surface.stl"), MeshFormat::stl, m, error)) << error;
    return m;
  }();
  return mesh;
}

double extent(const std::vector<Vec3d>& points) {
  Vec3d lo = points.front(), hi = points.front();
  for (const Vec3d& p : points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  return (hi - lo).norm();
}

/// A triangle by the reference indices of its corners, rotated to start at the smallest
/// (the orientation is kept).
std::array<Index, 3> canonical(std::array<Index, 3> t) {
  std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
  return t;
}

/// Maps each point of `mesh` to the reference point within `tolerance` (at most one may be),
/// and returns the triangles in reference indices; fails the test for a point with no match.
std::multiset<std::array<Index, 3>> trianglesInReference(const MeshData& mesh, double tolerance,
                                                         const std::string& what) {
  const std::vector<Vec3d>& ref = reference().positions;
  std::vector<Index> map(mesh.positions.size());
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    std::size_t best = 0;
    for (std::size_t j = 1; j < ref.size(); ++j)
      if ((ref[j] - mesh.positions[i]).norm() < (ref[best] - mesh.positions[i]).norm()) best = j;
    EXPECT_LE((ref[best] - mesh.positions[i]).norm(), tolerance) << what << ": point " << i;
    map[i] = static_cast<Index>(best);
  }
  std::multiset<std::array<Index, 3>> result;
  for (const Triangle& t : mesh.triangles)
    result.insert(canonical({map[t[0]], map[t[1]], map[t[2]]}));
  return result;
}

std::multiset<std::array<Index, 3>> referenceTriangles() {
  std::multiset<std::array<Index, 3>> result;
  for (const Triangle& t : reference().triangles) result.insert(canonical(t));
  return result;
}

MeshData readMerged(const std::string& file, const AssimpReadOptions& options = {}) {
  AssimpFile read;
  std::string error;
  EXPECT_TRUE(readAssimpFile(file, options, read, error)) << file << ": " << error;
  std::vector<const AssimpMesh*> all;
  for (const AssimpMesh& m : read.meshes) all.push_back(&m);
  return mergeMeshes(all);
}

TEST(AssimpReader, ReferenceIsTheOrganSurface) {
  EXPECT_EQ(reference().positions.size(), 643u);
  EXPECT_EQ(reference().triangles.size(), 1282u);
}

// PLY and glTF keep the file's points: the same points, in the same order, to the bit of the
// float32 the files store, and the same triangles.
TEST(AssimpReader, PlyAndGltfKeepThePointsAndTriangles) {
  for (const char* name : {"organ_surface.ply", "organ_surface.gltf"}) {
    const MeshData mesh = readMerged(shared(name));
    ASSERT_EQ(mesh.positions.size(), reference().positions.size()) << name;
    for (std::size_t i = 0; i < mesh.positions.size(); ++i)
      EXPECT_EQ(mesh.positions[i].cast<float>(), reference().positions[i].cast<float>())
          << name << " point " << i;
    EXPECT_EQ(mesh.triangles, reference().triangles) << name;
  }
}

// assimp gives STL and OBJ one point per triangle corner: compared through the reference
// points they stand at, the triangles are the same. STL stores float32 (exact); assimp's OBJ
// number parser rounds the decimal text slightly differently from strtod: within 1e-6 of the
// organ's size (float precision).
TEST(AssimpReader, StlAndObjGiveTheSameTrianglesAsStromasParsers) {
  const double size = extent(reference().positions);
  const MeshData stl = readMerged(shared("organ_surface.stl"));
  EXPECT_EQ(stl.positions.size(), 3 * reference().triangles.size());
  EXPECT_EQ(trianglesInReference(stl, 0.0, "STL"), referenceTriangles());
  EXPECT_EQ(trianglesInReference(readMerged(shared("organ_surface.obj")), 1e-6 * size, "OBJ"),
            referenceTriangles());
  // Stroma's own OBJ parser on the same file: the reference's points and triangles, in order.
  MeshData own;
  std::string error;
  ASSERT_TRUE(readMeshFile(shared("organ_surface.obj"), MeshFormat::obj, own, error)) << error;
  EXPECT_EQ(own.triangles, reference().triangles);
  for (std::size_t i = 0; i < own.positions.size(); ++i)
    EXPECT_EQ(own.positions[i].cast<float>(), reference().positions[i].cast<float>()) << i;
}

// The texture coordinates written are a planar projection of the points on x and y, with v
// from the image's bottom (glTF stores it from the top: assimp turns it over).
TEST(AssimpReader, TexcoordsAreTheProjectionWritten) {
  const std::vector<Vec3d>& points = reference().positions;
  Vec3d lo = points.front(), hi = points.front();
  for (const Vec3d& p : points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  for (const char* name : {"organ_surface.ply", "organ_surface.gltf", "organ_surface.obj"}) {
    const MeshData mesh = readMerged(shared(name));
    ASSERT_EQ(mesh.texcoords.size(), mesh.positions.size()) << name;
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
      const Vec3d& p = mesh.positions[i];
      EXPECT_NEAR(mesh.texcoords[i][0], (p[0] - lo[0]) / (hi[0] - lo[0]), 1e-5) << name << i;
      EXPECT_NEAR(mesh.texcoords[i][1], (p[1] - lo[1]) / (hi[1] - lo[1]), 1e-5) << name << i;
    }
  }
  EXPECT_TRUE(readMerged(shared("organ_surface.stl")).texcoords.empty());
}

// Normals (STL's facet normals, assimp's smooth normals for the others) are unit vectors and
// point out of the closed surface: along the outward normal of the triangles at the point.
TEST(AssimpReader, NormalsAreUnitAndOutward) {
  for (const char* name :
       {"organ_surface.ply", "organ_surface.gltf", "organ_surface.obj", "organ_surface.stl"}) {
    const MeshData mesh = readMerged(shared(name));
    ASSERT_EQ(mesh.normals.size(), mesh.positions.size()) << name;
    std::vector<Vec3d> faceSum(mesh.positions.size(), Vec3d::Zero());
    for (const Triangle& t : mesh.triangles) {
      const Vec3d n = (mesh.positions[t[1]] - mesh.positions[t[0]])
                          .cross(mesh.positions[t[2]] - mesh.positions[t[0]]);
      for (Index v : t) faceSum[v] += n;
    }
    for (std::size_t i = 0; i < mesh.normals.size(); ++i) {
      EXPECT_NEAR(mesh.normals[i].norm(), 1.0, 1e-6) << name << " point " << i;
      EXPECT_GT(mesh.normals[i].dot(faceSum[i]), 0.0) << name << " point " << i;
    }
  }
}

// two_parts.gltf: node "base" (translation t = (1, 2, 3), 90 degrees about z) places the unit
// cube "box"; its child "tip" (translation (0, 0, 2), scale 2) places the triangle "wedge".
TEST(AssimpReader, NodeTransformsAreApplied) {
  AssimpFile read;
  std::string error;
  ASSERT_TRUE(readAssimpFile(shared("two_parts.gltf"), {}, read, error)) << error;
  ASSERT_EQ(read.meshes.size(), 2u);
  const AssimpMesh& box = read.meshes[0];
  const AssimpMesh& wedge = read.meshes[1];
  EXPECT_EQ(box.name, "box");
  EXPECT_EQ(box.node, "base");
  EXPECT_EQ(wedge.name, "wedge");
  EXPECT_EQ(wedge.node, "tip");
  const Eigen::Matrix3d R = Eigen::AngleAxisd(M_PI / 2, Vec3d::UnitZ()).toRotationMatrix();
  const Vec3d t(1, 2, 3);
  std::vector<Vec3d> expected;
  for (double z : {0.0, 1.0})
    for (double y : {0.0, 1.0})
      for (double x : {0.0, 1.0}) expected.push_back(R * Vec3d(x, y, z) + t);
  ASSERT_EQ(box.mesh.positions.size(), expected.size());
  for (const Vec3d& p : box.mesh.positions) {
    double nearest = 1e9;
    for (const Vec3d& e : expected) nearest = std::min(nearest, (p - e).norm());
    EXPECT_LT(nearest, 1e-6) << p.transpose();
  }
  const Vec3d wedgePoints[3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  ASSERT_EQ(wedge.mesh.positions.size(), 3u);
  for (int i = 0; i < 3; ++i)
    EXPECT_LT((wedge.mesh.positions[i] - (R * (2 * wedgePoints[i] + Vec3d(0, 0, 2)) + t)).norm(),
              1e-6)
        << i;
  // The wedge lies in a plane z = const: its normal is R z = z (rotation about z).
  for (const Vec3d& n : wedge.mesh.normals) EXPECT_LT((n - Vec3d::UnitZ()).norm(), 1e-6);
  // Materials: the box's red with its texture next to the file, the wedge's green.
  ASSERT_LT(box.material, read.materials.size());
  const AssimpMaterial& red = read.materials[box.material];
  ASSERT_TRUE(red.diffuse.has_value());
  EXPECT_LT((*red.diffuse - Vec4d(0.8, 0.1, 0.1, 1)).norm(), 1e-6);
  EXPECT_EQ(red.texture, shared("box_texture.png"));
  ASSERT_TRUE(read.materials[wedge.material].diffuse.has_value());
  EXPECT_LT((*read.materials[wedge.material].diffuse - Vec4d(0.1, 0.7, 0.2, 1)).norm(), 1e-6);
}

// A cube of six quads: triangulated by default, kept with keepQuads; its 24 corners (one per
// face corner, as OBJ faces give them) become the 8 points with joinIdenticalVertices.
TEST(AssimpReader, QuadsAndJoinedPoints) {
  TempDir dir;
  const std::string cube = dir.write("cube.obj",
                                     "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                                     "v 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
                                     "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\n"
                                     "f 4 1 5 8\n")
                               .string();
  const MeshData triangulated = readMerged(cube);
  EXPECT_EQ(triangulated.triangles.size(), 12u);
  EXPECT_TRUE(triangulated.quads.empty());
  const MeshData quads = readMerged(cube, {.keepQuads = true});
  EXPECT_EQ(quads.quads.size(), 6u);
  EXPECT_TRUE(quads.triangles.empty());
  EXPECT_EQ(quads.positions.size(), 24u);
  const MeshData joined = readMerged(cube, {.keepQuads = true, .joinIdenticalVertices = true});
  EXPECT_EQ(joined.quads.size(), 6u);
  std::set<std::array<double, 3>> distinct;
  for (const Vec3d& p : joined.positions) distinct.insert({p[0], p[1], p[2]});
  EXPECT_EQ(distinct.size(), 8u);
  EXPECT_LT(joined.positions.size(), quads.positions.size());
}

// A format Stroma has no parser of its own for: OFF (the surface of a tetrahedron): the
// triangles as written.
TEST(AssimpReader, ReadsOff) {
  TempDir dir;
  const std::string off = dir.write("tetra.off",
                                    "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n"
                                    "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n")
                              .string();
  const MeshData mesh = readMerged(off);
  ASSERT_EQ(mesh.triangles.size(), 4u);
  std::multiset<std::array<double, 9>> expected, got;
  const Vec3d corner[4] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const Triangle faces[4] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  const auto key = [](const Vec3d& a, const Vec3d& b, const Vec3d& c) {
    return std::array<double, 9>{a[0], a[1], a[2], b[0], b[1], b[2], c[0], c[1], c[2]};
  };
  for (const Triangle& f : faces) expected.insert(key(corner[f[0]], corner[f[1]], corner[f[2]]));
  for (const Triangle& t : mesh.triangles)
    got.insert(key(mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]]));
  EXPECT_EQ(got, expected);
}

// Collada: one triangle placed by two nodes comes out twice, each moved by its node; the file's
// unit (millimeters here) is applied, and its Z_UP axis is kept as written (assimp would turn
// it to y up; URDF meshes are z up as their links).
TEST(AssimpReader, ColladaInstancesUnitAndUpAxis) {
  TempDir dir;
  const std::string dae =
      dir.write(
             "two.dae",
             "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n"
             "<COLLADA xmlns=\"http://www.collada.org/2005/11/COLLADASchema\" version=\"1.4.1\">\n"
             "  <asset><unit name=\"meter\" meter=\"0.001\"/><up_axis>Z_UP</up_axis></asset>\n"
             "  <library_geometries>\n"
             "    <geometry id=\"tri\" name=\"tri\">\n"
             "      <mesh>\n"
             "        <source id=\"tri-pos\">\n"
             "          <float_array id=\"tri-pos-array\" count=\"9\">0 0 0 1 0 0 0 1 "
             "0</float_array>\n"
             "          <technique_common><accessor source=\"#tri-pos-array\" count=\"3\" "
             "stride=\"3\">\n"
             "            <param name=\"X\" type=\"float\"/><param name=\"Y\" "
             "type=\"float\"/><param name=\"Z\" type=\"float\"/>\n"
             "          </accessor></technique_common>\n"
             "        </source>\n"
             "        <vertices id=\"tri-vtx\"><input semantic=\"POSITION\" "
             "source=\"#tri-pos\"/></vertices>\n"
             "        <triangles count=\"1\"><input semantic=\"VERTEX\" source=\"#tri-vtx\" "
             "offset=\"0\"/><p>0 1 2</p></triangles>\n"
             "      </mesh>\n"
             "    </geometry>\n"
             "  </library_geometries>\n"
             "  <library_visual_scenes>\n"
             "    <visual_scene id=\"scene\">\n"
             "      <node id=\"left\" name=\"left\"><translate>-5 0 "
             "0</translate><instance_geometry url=\"#tri\"/></node>\n"
             "      <node id=\"right\" name=\"right\"><translate>5 0 "
             "0</translate><instance_geometry url=\"#tri\"/></node>\n"
             "    </visual_scene>\n"
             "  </library_visual_scenes>\n"
             "  <scene><instance_visual_scene url=\"#scene\"/></scene>\n"
             "</COLLADA>\n")
          .string();
  AssimpFile read;
  std::string error;
  ASSERT_TRUE(readAssimpFile(dae, {}, read, error)) << error;
  ASSERT_EQ(read.meshNames.size(), 1u);
  ASSERT_EQ(read.meshes.size(), 2u);
  const Vec3d triangle[3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const double shift[2] = {-5, 5};
  for (int m = 0; m < 2; ++m) {
    EXPECT_EQ(read.meshes[m].node, m == 0 ? "left" : "right");
    ASSERT_EQ(read.meshes[m].mesh.positions.size(), 3u);
    for (int i = 0; i < 3; ++i)
      EXPECT_LT(
          (read.meshes[m].mesh.positions[i] - 1e-3 * (triangle[i] + Vec3d(shift[m], 0, 0))).norm(),
          1e-9)
          << m << " " << i;
  }
}

// Truncated files (cut at 1/16, 2/16, ... of their length) never crash: each is read or refused
// with a reason, and what is read has its indices within its points.
TEST(AssimpReader, TruncatedFilesAreReadOrRefused) {
  TempDir dir;
  for (const char* name : {"organ_surface.ply", "organ_surface.gltf", "organ_surface.obj",
                           "organ_surface.stl", "two_parts.gltf"}) {
    std::ifstream in(shared(name), std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), {});
    ASSERT_FALSE(bytes.empty()) << name;
    for (int k = 1; k < 16; ++k) {
      const std::string cut = bytes.substr(0, bytes.size() * k / 16);
      const std::string file = dir.write(std::to_string(k) + "_" + name, cut).string();
      AssimpFile read;
      std::string error;
      if (!readAssimpFile(file, {}, read, error)) {
        EXPECT_FALSE(error.empty()) << file;
        continue;
      }
      for (const AssimpMesh& m : read.meshes)
        for (const Triangle& t : m.mesh.triangles)
          for (Index v : t) ASSERT_LT(v, m.mesh.positions.size()) << file;
    }
  }
}

TEST(AssimpReader, BadFilesGiveAssimpsReason) {
  TempDir dir;
  AssimpFile read;
  std::string error;
  EXPECT_FALSE(readAssimpFile(dir.write("noise.xyz", "hello\n").string(), {}, read, error));
  EXPECT_NE(error.find("No suitable reader"), std::string::npos) << error;
  EXPECT_FALSE(readAssimpFile((dir.path() / "missing.ply").string(), {}, read, error));
  EXPECT_FALSE(error.empty());
  EXPECT_FALSE(readAssimpFile(shared("empty_scene.gltf"), {}, read, error));
  EXPECT_NE(error.find("no mesh"), std::string::npos) << error;
}

}  // namespace
}  // namespace stroma::test
