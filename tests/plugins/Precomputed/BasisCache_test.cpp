// SPDX-License-Identifier: MIT
// The basis cache file: FNV-1a reference values, a round trip that restores the basis bit for
// bit, and the refusal (with its reason) of foreign, corrupt, truncated and non-basis files.
#include "Precomputed/kernels/BasisCache.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "plugins/SolidMechanics/FemTestScenes.h"

namespace stroma::precomputed {
namespace {

TEST(BasisCache, Fnv1aMatchesItsReferenceValues) {
  // Published FNV-1a 64 values (Fowler, Noll, Vo): "" and "a".
  EXPECT_EQ(fnv1a64("", 0), 0xcbf29ce484222325ULL);
  EXPECT_EQ(fnv1a64("a", 1), 0xaf63dc4c8601ec8cULL);
}

TEST(BasisCache, RoundTripAndRefusals) {
  const test::FemMesh mesh = test::makeBoxMesh(Vec3d(2, 1, 1), Vec3i(2, 1, 1));
  SparseMatrix K;
  std::string error;
  ASSERT_TRUE(assembleLinearStiffness(mesh.points, mesh.tetrahedra, 1e5, 0.3, K, error));
  std::vector<int> fixedDofs, basis, rows;
  for (int i = 0; i < int(mesh.points.size()); ++i) {
    rows.push_back(i);
    if (mesh.points[size_t(i)].x() == 0)
      for (int c = 0; c < 3; ++c) fixedDofs.push_back(3 * i + c);
    else
      basis.push_back(i);
  }
  const auto original = DeformationBasis::compute(K, fixedDofs, basis, error);
  ASSERT_TRUE(original) << error;
  const std::uint64_t key =
      computeBasisKey(mesh.points, mesh.tetrahedra, 1e5, 0.3, fixedDofs, basis, rows);
  EXPECT_NE(key, computeBasisKey(mesh.points, mesh.tetrahedra, 1e5, 0.31, fixedDofs, basis, rows));
  auto moved = mesh.points;
  moved[3].x() += 1e-12;
  EXPECT_NE(key, computeBasisKey(moved, mesh.tetrahedra, 1e5, 0.3, fixedDofs, basis, rows));

  const auto path = (std::filesystem::temp_directory_path() /
                     ("stroma-basis-cache-test-" + std::to_string(::getpid()) + ".basis"))
                        .string();
  ASSERT_TRUE(writeBasisCache(path, key, *original, error)) << error;
  EXPECT_EQ(std::filesystem::file_size(path), basisCacheBytes(*original));
  auto loaded = readBasisCache(path, key, error);
  ASSERT_TRUE(loaded) << error;
  EXPECT_EQ(loaded->columns(), original->columns());
  EXPECT_EQ(loaded->basisNodes(), original->basisNodes());
  EXPECT_EQ(loaded->fixedColumns(), original->fixedColumns());

  EXPECT_FALSE(readBasisCache(path, key + 1, error));
  EXPECT_NE(error.find("another mesh"), std::string::npos) << error;
  const auto size = std::filesystem::file_size(path);
  {
    std::fstream f(path, std::ios::binary | std::ios::in | std::ios::out);
    f.seekp(std::streamoff(size - 5));
    f.put('\x11');
  }
  EXPECT_FALSE(readBasisCache(path, key, error));
  EXPECT_NE(error.find("corrupt"), std::string::npos) << error;
  std::filesystem::resize_file(path, size - 8);
  EXPECT_FALSE(readBasisCache(path, key, error));
  EXPECT_NE(error.find("truncated"), std::string::npos) << error;
  std::ofstream(path, std::ios::binary | std::ios::trunc) << "solid cube\nfacet normal 0 0 1\n"
                                                          << std::string(100, ' ');
  EXPECT_FALSE(readBasisCache(path, key, error));
  EXPECT_NE(error.find("not a precomputed-basis file"), std::string::npos) << error;
  std::filesystem::remove(path);
  EXPECT_FALSE(readBasisCache(path, key, error));
  EXPECT_NE(error.find("no cache file"), std::string::npos) << error;
}

}  // namespace
}  // namespace stroma::precomputed
