// SPDX-License-Identifier: MIT
#include "GridMeshCreator.h"

#include <algorithm>
#include <set>
#include <utility>

#include "formats/MeshProcessing.h"

namespace stroma {

MeshData makeGridMesh(int nx, int ny, GridTrianglePattern pattern) {
  MeshData mesh;
  auto point = [nx](int i, int j) { return static_cast<Index>(i + nx * j); };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      mesh.positions.emplace_back(i / double(nx - 1), j / double(ny - 1), 0.0);
  for (int j = 0; j + 1 < ny; ++j)
    for (int i = 0; i + 1 < nx; ++i) {
      const Index a = point(i, j), b = point(i + 1, j), c = point(i + 1, j + 1), d = point(i, j + 1);
      const bool upward = pattern == GridTrianglePattern::upward ||
                          (pattern == GridTrianglePattern::alternate && (i + j) % 2 == 0);
      if (pattern == GridTrianglePattern::quads) {
        mesh.quads.push_back({a, b, c, d});
      } else if (upward) {
        mesh.triangles.push_back({a, b, c});
        mesh.triangles.push_back({a, c, d});
      } else {
        mesh.triangles.push_back({a, b, d});
        mesh.triangles.push_back({b, c, d});
      }
    }
  // Edges: each once, in the direction of the first element around it, then sorted.
  std::set<std::pair<Index, Index>> seen;
  auto addLoop = [&](const auto& element) {
    for (std::size_t k = 0; k < element.size(); ++k) {
      const Index p = element[k], q = element[(k + 1) % element.size()];
      if (seen.count({q, p}) == 0) seen.insert({p, q});
    }
  };
  for (const Quad& q : mesh.quads) addLoop(q);
  for (const Triangle& t : mesh.triangles) addLoop(t);
  for (const auto& [p, q] : seen) mesh.edges.push_back({p, q});
  return mesh;
}

GridMeshCreator::GridMeshCreator() {
  for (BaseData* input : std::initializer_list<BaseData*>{
           &d_resolution, &d_trianglePattern, &m_placement.translation, &m_placement.rotation,
           &m_placement.scale3d, &m_placement.scale, &m_placement.transformation,
           &m_placement.flipNormals})
    addInput(input);
  for (BaseData* output : std::initializer_list<BaseData*>{&d_position, &d_edges, &d_triangles,
                                                          &d_quads})
    addOutput(output);
}

void GridMeshCreator::init() {
  d_position.value();  // make the mesh now, so that bad input is reported by this component
}

void GridMeshCreator::doUpdate() {
  const Vec2i n = d_resolution.value();
  Eigen::Matrix4d transform = Eigen::Matrix4d::Identity();
  if (n.x() < 2 || n.y() < 2) {
    msgError("needs at least 2 points along x and y, got '" + d_resolution.valueText() + "'",
             "resolution");
  } else if (m_placement.matrix(*this, transform)) {
    MeshData mesh = makeGridMesh(n.x(), n.y(),
                                 static_cast<GridTrianglePattern>(d_trianglePattern.value()));
    if (transform != Eigen::Matrix4d::Identity()) transformMesh(mesh, transform);
    if (m_placement.flipNormals.value()) flipOrientation(mesh);
    d_position.setValue(std::move(mesh.positions));
    d_edges.setValue(std::move(mesh.edges));
    d_triangles.setValue(std::move(mesh.triangles));
    d_quads.setValue(std::move(mesh.quads));
    return;
  }
  d_position.setValue({});
  d_edges.setValue({});
  d_triangles.setValue({});
  d_quads.setValue({});
}

}  // namespace stroma
