// SPDX-License-Identifier: MIT
#include "RegularGridTopology.h"

#include <cmath>

namespace stroma {

namespace {
constexpr double kMaxGridPoints = 1e7;  // a scene must not make the loader exhaust memory
}

RegularGridTopology::RegularGridTopology() : TopologyContainer(kinds::all, false) {
  for (BaseData* input : std::initializer_list<BaseData*>{
           &d_n, &d_nx, &d_ny, &d_nz, &d_min, &d_max, &d_xmin, &d_ymin, &d_zmin, &d_xmax, &d_ymax,
           &d_zmax, &d_p0, &d_cellWidth, &d_computeHexaList, &d_computeQuadList,
           &d_computeTriangleList, &d_computeEdgeList, &d_computePointList})
    addInput(input);
  for (BaseData* output : std::initializer_list<BaseData*>{&d_position, &d_edges, &d_triangles,
                                                           &d_quads, &d_hexahedra})
    addOutput(output);
}

GridSize RegularGridTopology::gridSize() const {
  GridSize n{d_n.value().x(), d_n.value().y(), d_n.value().z()};
  if (d_nx.isSet() && d_ny.isSet() && d_nz.isSet())
    n = GridSize{d_nx.value(), d_ny.value(), d_nz.value()};
  if (d_cellWidth.value() > 0) {
    const Vec3d extent = d_max.value() - d_min.value();
    auto count = [&](double length) {
      const double cells = std::ceil(std::abs(length) / d_cellWidth.value());
      return cells < kMaxGridPoints ? static_cast<int>(cells) + 1
                                    : static_cast<int>(kMaxGridPoints);
    };
    n = GridSize{count(extent.x()), count(extent.y()), count(extent.z())};
  }
  return n;
}

void RegularGridTopology::doUpdate() {
  const GridSize n = gridSize();
  auto clear = [&] {
    d_position.setValue({});
    d_edges.setValue({});
    d_triangles.setValue({});
    d_quads.setValue({});
    d_hexahedra.setValue({});
  };
  if (n.nx < 1 || n.ny < 1 || n.nz < 1) {
    msgError("the grid needs at least one point along each axis; got " + std::to_string(n.nx) +
                 " x " + std::to_string(n.ny) + " x " + std::to_string(n.nz),
             d_nx.isSet() ? "nx" : "n");
    clear();
    return;
  }
  if (double(n.nx) * n.ny * n.nz > kMaxGridPoints) {
    msgError("a grid of " + std::to_string(n.nx) + " x " + std::to_string(n.ny) + " x " +
                 std::to_string(n.nz) + " points is larger than the 10^7 points allowed",
             "n");
    clear();
    return;
  }
  // Extent: min and max, coordinate by coordinate replaced by xmin ... zmax when given.
  Vec3d lo = d_min.value(), hi = d_max.value();
  if (d_xmin.isSet()) lo.x() = d_xmin.value();
  if (d_ymin.isSet()) lo.y() = d_ymin.value();
  if (d_zmin.isSet()) lo.z() = d_zmin.value();
  if (d_xmax.isSet()) hi.x() = d_xmax.value();
  if (d_ymax.isSet()) hi.y() = d_ymax.value();
  if (d_zmax.isSet()) hi.z() = d_zmax.value();
  const int counts[3] = {n.nx, n.ny, n.nz};
  Vec3d spacing, origin = lo;
  for (int a = 0; a < 3; ++a) {
    if (counts[a] > 1) {
      spacing[a] = (hi[a] - lo[a]) / (counts[a] - 1);
    } else {
      spacing[a] = hi[a] - lo[a];
      if (a < 2) origin[a] = (lo[a] + hi[a]) / 2;  // SOFA centres x and y, keeps z at min
    }
  }
  if (d_p0.isSet()) origin = d_p0.value();

  if (d_computePointList.value()) d_position.setValue(makeGridPoints(n, origin, spacing));
  if (d_computeHexaList.value()) d_hexahedra.setValue(makeGridHexahedra(n));
  std::vector<Quad> quads;
  if (d_computeQuadList.value() || d_computeTriangleList.value()) quads = makeGridQuads(n);
  std::vector<Triangle> triangles;
  if (d_computeTriangleList.value()) {
    triangles.reserve(quads.size() * 2);
    for (const Quad& q : quads) {
      triangles.push_back({q[0], q[1], q[2]});
      triangles.push_back({q[0], q[2], q[3]});
    }
  }
  if (d_computeEdgeList.value()) {
    d_edges.setValue(triangles.empty() ? makeGridEdges(n) : computeTriangleEdges(triangles).edges);
  }
  if (d_computeTriangleList.value()) d_triangles.setValue(std::move(triangles));
  if (d_computeQuadList.value()) d_quads.setValue(std::move(quads));
}

}  // namespace stroma
