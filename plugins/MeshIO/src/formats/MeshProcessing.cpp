// SPDX-License-Identifier: MIT
#include "MeshProcessing.h"

#include <Eigen/LU>
#include <algorithm>
#include <numbers>
#include <unordered_set>

#include "topology/MeshAdjacency.h"

namespace stroma {

namespace {

template <std::size_t N>
std::array<Index, N> sorted(std::array<Index, N> a) {
  std::sort(a.begin(), a.end());
  return a;
}

template <std::size_t N>
struct SortedHash {
  std::size_t operator()(const std::array<Index, N>& a) const {
    std::uint64_t h = 1469598103934665603ull;
    for (Index v : a) h = (h ^ v) * 1099511628211ull;
    return static_cast<std::size_t>(h);
  }
};

/// Appends to `list` the `candidates` whose vertex set is not already in `list`.
template <std::size_t N>
void addMissing(std::vector<std::array<Index, N>>& list,
                const std::vector<std::array<Index, N>>& candidates) {
  std::unordered_set<std::array<Index, N>, SortedHash<N>> present;
  for (const auto& e : list) present.insert(sorted(e));
  for (const auto& e : candidates)
    if (present.insert(sorted(e)).second) list.push_back(e);
}

}  // namespace

void triangulateQuads(MeshData& mesh) {
  for (const Quad& q : mesh.quads) {
    mesh.triangles.push_back({q[0], q[1], q[2]});
    mesh.triangles.push_back({q[0], q[2], q[3]});
  }
  mesh.quads.clear();
}

void createSubelements(MeshData& mesh) {
  if (!mesh.tetrahedra.empty())
    addMissing(mesh.triangles, computeTetrahedronFaces(mesh.tetrahedra).faces);
  if (!mesh.hexahedra.empty()) addMissing(mesh.quads, computeHexahedronFaces(mesh.hexahedra).faces);
  if (!mesh.triangles.empty()) addMissing(mesh.edges, computeTriangleEdges(mesh.triangles).edges);
  if (!mesh.quads.empty()) addMissing(mesh.edges, computeQuadEdges(mesh.quads).edges);
}

std::vector<Index> removeUnattachedPoints(MeshData& mesh) {
  std::vector<Index> newIndex(mesh.positions.size(), kInvalidIndex);
  auto mark = [&](const auto& elements) {
    for (const auto& e : elements)
      for (Index v : e)
        if (v < newIndex.size()) newIndex[v] = 0;
  };
  mark(mesh.edges);
  mark(mesh.triangles);
  mark(mesh.quads);
  mark(mesh.tetrahedra);
  mark(mesh.hexahedra);
  std::vector<Index> kept;
  for (std::size_t i = 0; i < newIndex.size(); ++i)
    if (newIndex[i] != kInvalidIndex) {
      newIndex[i] = static_cast<Index>(kept.size());
      kept.push_back(static_cast<Index>(i));
    }
  auto renumber = [&](auto& elements) {
    for (auto& e : elements)
      for (Index& v : e) v = newIndex[v];
  };
  renumber(mesh.edges);
  renumber(mesh.triangles);
  renumber(mesh.quads);
  renumber(mesh.tetrahedra);
  renumber(mesh.hexahedra);
  auto select = [&](auto& values) {
    if (values.empty()) return;
    std::remove_reference_t<decltype(values)> selected;
    selected.reserve(kept.size());
    for (Index i : kept) selected.push_back(values[i]);
    values = std::move(selected);
  };
  select(mesh.positions);
  select(mesh.normals);
  select(mesh.texcoords);
  return kept;
}

Eigen::Matrix4d makeTransform(const Vec3d& scale, const Vec3d& rotationDegrees,
                              const Vec3d& translation) {
  const Vec3d r = rotationDegrees * (std::numbers::pi / 180.0);
  const Mat3d rotation =
      (Eigen::AngleAxisd(r.z(), Vec3d::UnitZ()) * Eigen::AngleAxisd(r.y(), Vec3d::UnitY()) *
       Eigen::AngleAxisd(r.x(), Vec3d::UnitX()))
          .toRotationMatrix();
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.topLeftCorner<3, 3>() = rotation * scale.asDiagonal();
  m.topRightCorner<3, 1>() = translation;
  return m;
}

void transformMesh(MeshData& mesh, const Eigen::Matrix4d& transform) {
  const Mat3d linear = transform.topLeftCorner<3, 3>();
  const Vec3d shift = transform.topRightCorner<3, 1>();
  for (Vec3d& p : mesh.positions) p = linear * p + shift;
  if (mesh.normals.empty()) return;
  Mat3d normalMap = Mat3d::Identity();
  bool invertible = false;
  linear.computeInverseWithCheck(normalMap, invertible);
  normalMap = invertible ? Mat3d(normalMap.transpose()) : linear;
  for (Vec3d& n : mesh.normals) {
    n = normalMap * n;
    if (n.squaredNorm() > 0) n.normalize();
  }
}

void flipOrientation(MeshData& mesh) {
  for (Triangle& t : mesh.triangles) std::swap(t[1], t[2]);
  for (Quad& q : mesh.quads) std::swap(q[1], q[3]);
  for (Vec3d& n : mesh.normals) n = -n;
}

}  // namespace stroma
