// SPDX-License-Identifier: MIT
// Meshes and inline scenes shared by the tests of the FEM force fields: boxes of hexahedra or
// tetrahedra written into a MeshTopology, the MacNeal-Harder patch, and the static solve of an
// assembled system.
#pragma once

#include <gtest/gtest.h>

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#include <array>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "core/PathResolver.h"
#include "core/Runtime.h"
#include "core/StateTypes.h"
#include "simulation/MechanicalOperations.h"
#include "simulation/MechanicalState.h"
#include "simulation/Scene.h"

namespace stroma::test {

/// Points and elements of a mesh (SOFA's vertex orders, TopologyTypes.h).
struct FemMesh {
  std::vector<Vec3d> points;
  std::vector<std::array<unsigned, 8>> hexahedra;
  std::vector<std::array<unsigned, 4>> tetrahedra;
};

/// The grid of cells.x() x cells.y() x cells.z() hexahedra filling [0, size] (points x first,
/// then y, then z, as RegularGridTopology), and its split into 6 tetrahedra per hexahedron
/// around the 0-6 diagonal (conforming: neighbours share their face diagonals).
inline FemMesh makeBoxMesh(const Vec3d& size, const Vec3i& cells) {
  FemMesh mesh;
  const int nx = cells.x() + 1, ny = cells.y() + 1, nz = cells.z() + 1;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
        mesh.points.emplace_back(size.x() * i / cells.x(), size.y() * j / cells.y(),
                                 size.z() * k / cells.z());
  auto id = [&](int i, int j, int k) { return static_cast<unsigned>(i + nx * (j + ny * k)); };
  for (int k = 0; k < cells.z(); ++k)
    for (int j = 0; j < cells.y(); ++j)
      for (int i = 0; i < cells.x(); ++i)
        mesh.hexahedra.push_back({id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k),
                                  id(i, j + 1, k), id(i, j, k + 1), id(i + 1, j, k + 1),
                                  id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)});
  static constexpr std::array<std::array<int, 4>, 6> kSplit{
      {{0, 1, 2, 6}, {0, 1, 6, 5}, {0, 3, 6, 2}, {0, 3, 7, 6}, {0, 4, 5, 6}, {0, 4, 6, 7}}};
  for (const auto& h : mesh.hexahedra)
    for (const auto& t : kSplit) mesh.tetrahedra.push_back({h[t[0]], h[t[1]], h[t[2]], h[t[3]]});
  return mesh;
}

/// MacNeal and Harder's patch (REFERENCES.md, "Patch test"): the unit cube cut into seven
/// distorted hexahedra; points 0-7 are the cube's corners (SOFA's order), 8-15 the interior
/// points, 8 + i next to corner i.
inline FemMesh makeMacNealHarderPatch() {
  FemMesh mesh;
  mesh.points = {{0, 0, 0},
                 {1, 0, 0},
                 {1, 1, 0},
                 {0, 1, 0},
                 {0, 0, 1},
                 {1, 0, 1},
                 {1, 1, 1},
                 {0, 1, 1},
                 {0.249, 0.342, 0.192},
                 {0.826, 0.288, 0.288},
                 {0.850, 0.649, 0.263},
                 {0.273, 0.750, 0.230},
                 {0.320, 0.186, 0.643},
                 {0.677, 0.305, 0.683},
                 {0.788, 0.693, 0.644},
                 {0.165, 0.745, 0.702}};
  // The central hexahedron, then one per face of the cube: z = 0, z = 1, y = 0, y = 1, x = 0,
  // x = 1, each numbered with its local axes along x, y, z.
  mesh.hexahedra = {{8, 9, 10, 11, 12, 13, 14, 15}, {0, 1, 2, 3, 8, 9, 10, 11},
                    {12, 13, 14, 15, 4, 5, 6, 7},   {0, 1, 9, 8, 4, 5, 13, 12},
                    {11, 10, 2, 3, 15, 14, 6, 7},   {0, 8, 11, 3, 4, 12, 15, 7},
                    {9, 1, 2, 10, 13, 5, 6, 14}};
  return mesh;
}

/// Moves the interior points of a grid mesh (those not on the boundary of [0, size]) by up to
/// `fraction` of `spacing` in each direction, reproducibly.
inline void distortInterior(FemMesh& mesh, const Vec3d& size, double spacing, double fraction,
                            unsigned seed = 7) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> uniform(-fraction * spacing, fraction * spacing);
  for (Vec3d& p : mesh.points) {
    bool boundary = false;
    for (int a = 0; a < 3; ++a)
      boundary |= std::abs(p[a]) < 1e-12 || std::abs(p[a] - size[a]) < 1e-12;
    if (!boundary) p += Vec3d(uniform(rng), uniform(rng), uniform(rng));
  }
}

inline std::string pointsText(const std::vector<Vec3d>& points) {
  std::string text;
  char buffer[96];
  for (const Vec3d& p : points) {
    std::snprintf(buffer, sizeof buffer, "%.17g %.17g %.17g  ", p.x(), p.y(), p.z());
    text += buffer;
  }
  return text;
}

template <std::size_t N>
std::string elementsText(const std::vector<std::array<unsigned, N>>& elements) {
  std::string text;
  for (const auto& e : elements) {
    for (unsigned v : e) text += std::to_string(v) + ' ';
    text += ' ';
  }
  return text;
}

/// A scene with one node "body": a MeshTopology holding `elements` ("tetrahedra" or
/// "hexahedra") of the mesh, a MechanicalObject "dofs" at the mesh's points, then `components`
/// (the force field under test and whatever else, as XML).
inline std::string femScene(const FemMesh& mesh, const std::string& elements,
                            const std::string& components,
                            const std::string& rootAttributes = "gravity=\"0 0 0\" dt=\"0.01\"") {
  const std::string list =
      elements == "hexahedra" ? elementsText(mesh.hexahedra) : elementsText(mesh.tetrahedra);
  return "<Node name=\"root\" " + rootAttributes + ">\n<Node name=\"body\">\n" +
         "<MeshTopology name=\"mesh\" " + elements + "=\"" + list + "\"/>\n" +
         "<MechanicalObject name=\"dofs\" position=\"" + pointsText(mesh.points) + "\"/>\n" +
         components + "\n</Node>\n</Node>\n";
}

/// Loads `xml`; fails the test (with the messages) when it did not load or gave a warning.
inline bool loadQuietly(Scene& scene, const std::string& xml) {
  const bool loaded = scene.loadString(xml);
  std::string messages;
  for (const Message& m : scene.log().messages())
    if (m.level == MessageLevel::error || m.level == MessageLevel::warning)
      messages += formatForConsole(m) + '\n';
  EXPECT_TRUE(loaded && messages.empty()) << messages;
  return loaded && messages.empty();
}

/// The object at `path`, cast to T (nullptr with a test failure when absent).
template <class T>
T* objectAt(Scene& scene, const std::string& path) {
  std::string why;
  T* object = dynamic_cast<T*>(resolveObjectPath(scene.root(), path, why));
  EXPECT_NE(object, nullptr) << path << ": " << why;
  return object;
}

/// The assembled stiffness K = df/dx (kFactor 1, no mass) of the scene at its current
/// positions, with fixed rows as the identity (MechanicalOperations::assemble).
inline Eigen::SparseMatrix<double> assembleStiffness(Scene& scene) {
  MechanicalOperations mop(scene.root(), scene.timing());
  // Forces first: corotational fields take their rotations from the last addForce.
  const VecId f = mop.allocDeriv();
  mop.computeForce(MechanicalParams{}, f);
  MechanicalParams mp;
  mp.kFactor = 1;
  mp.mFactor = 0;
  AssembledMatrix A;
  mop.assemble(mp, A);
  return A.matrix();
}

/// -K restricted to the free degrees of freedom: freeIndex[k] is the row of dof k among the free
/// ones, or -1 when it is fixed (the system matrix of a static solve, freeCount x freeCount).
inline Eigen::SparseMatrix<double> restrictNegated(const Eigen::SparseMatrix<double>& K,
                                                   const std::vector<Eigen::Index>& freeIndex,
                                                   Eigen::Index freeCount) {
  std::vector<Eigen::Triplet<double>> triplets;
  for (Eigen::Index col = 0; col < K.outerSize(); ++col)
    for (Eigen::SparseMatrix<double>::InnerIterator it(K, col); it; ++it)
      if (freeIndex[it.row()] >= 0 && freeIndex[it.col()] >= 0)
        triplets.emplace_back(freeIndex[it.row()], freeIndex[it.col()], -it.value());
  Eigen::SparseMatrix<double> A(freeCount, freeCount);
  A.setFromTriplets(triplets.begin(), triplets.end());
  return A;
}

/// Forces of every field of the scene at its current positions, as one vector.
inline Eigen::VectorXd computeForces(Scene& scene) {
  MechanicalOperations mop(scene.root(), scene.timing());
  const VecId f = mop.allocDeriv();
  mop.computeForce(MechanicalParams{}, f);
  Eigen::VectorXd out;
  mop.gather(f, out);
  return out;
}

}  // namespace stroma::test
