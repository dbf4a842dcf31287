// SPDX-License-Identifier: MIT
#include "RegularGrid.h"

namespace stroma {

std::vector<Vec3d> makeGridPoints(const GridSize& n, const Vec3d& origin, const Vec3d& spacing) {
  std::vector<Vec3d> points;
  points.reserve(n.points());
  for (int k = 0; k < n.nz; ++k)
    for (int j = 0; j < n.ny; ++j)
      for (int i = 0; i < n.nx; ++i)
        points.push_back(origin + Vec3d(i * spacing.x(), j * spacing.y(), k * spacing.z()));
  return points;
}

std::vector<Hexahedron> makeGridHexahedra(const GridSize& n) {
  std::vector<Hexahedron> hexahedra;
  for (int k = 0; k + 1 < n.nz; ++k)
    for (int j = 0; j + 1 < n.ny; ++j)
      for (int i = 0; i + 1 < n.nx; ++i)
        hexahedra.push_back({n.point(i, j, k), n.point(i + 1, j, k), n.point(i + 1, j + 1, k),
                             n.point(i, j + 1, k), n.point(i, j, k + 1), n.point(i + 1, j, k + 1),
                             n.point(i + 1, j + 1, k + 1), n.point(i, j + 1, k + 1)});
  return hexahedra;
}

std::vector<Quad> makeGridQuads(const GridSize& n) {
  std::vector<Quad> quads;
  for (int k = 0; k < n.nz; ++k)  // xy planes
    for (int j = 0; j + 1 < n.ny; ++j)
      for (int i = 0; i + 1 < n.nx; ++i)
        quads.push_back({n.point(i, j, k), n.point(i + 1, j, k), n.point(i + 1, j + 1, k),
                         n.point(i, j + 1, k)});
  for (int k = 0; k + 1 < n.nz; ++k)  // xz planes
    for (int j = 0; j < n.ny; ++j)
      for (int i = 0; i + 1 < n.nx; ++i)
        quads.push_back({n.point(i, j, k), n.point(i + 1, j, k), n.point(i + 1, j, k + 1),
                         n.point(i, j, k + 1)});
  for (int k = 0; k + 1 < n.nz; ++k)  // yz planes
    for (int j = 0; j + 1 < n.ny; ++j)
      for (int i = 0; i < n.nx; ++i)
        quads.push_back({n.point(i, j, k), n.point(i, j + 1, k), n.point(i, j + 1, k + 1),
                         n.point(i, j, k + 1)});
  return quads;
}

std::vector<Edge> makeGridEdges(const GridSize& n) {
  std::vector<Edge> edges;
  for (int k = 0; k < n.nz; ++k)
    for (int j = 0; j < n.ny; ++j)
      for (int i = 0; i + 1 < n.nx; ++i) edges.push_back({n.point(i, j, k), n.point(i + 1, j, k)});
  for (int k = 0; k < n.nz; ++k)
    for (int j = 0; j + 1 < n.ny; ++j)
      for (int i = 0; i < n.nx; ++i) edges.push_back({n.point(i, j, k), n.point(i, j + 1, k)});
  for (int k = 0; k + 1 < n.nz; ++k)
    for (int j = 0; j < n.ny; ++j)
      for (int i = 0; i < n.nx; ++i) edges.push_back({n.point(i, j, k), n.point(i, j, k + 1)});
  return edges;
}

}  // namespace stroma
