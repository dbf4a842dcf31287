// SPDX-License-Identifier: MIT
// Stiffness tensors stored on the vertices and the edges of a mesh (Cotin, Delingette, Ayache;
// Checoury's report, seed 000, eqs. 1.11 and 1.12): a symmetric 3N x 3N matrix whose
// diagonal blocks K^pp live on the vertices and whose off-diagonal blocks K^pj live on the
// edges (p, j), K^jp = (K^pj)^T. The linear tensor-mass stiffness, and the tangent stiffness
// of the St Venant-Kirchhoff one, are such matrices: every pair of vertices that interact
// shares a tetrahedron, hence an edge.
//
// The product is computed as seed 000 section 3.3 says: edge by edge (K^pj u_j on p, and
// (K^pj)^T u_p on j), then vertex by vertex (K^pp u_p). Sequential and in a fixed order, so
// results are the same at every run.
#pragma once

#include <Eigen/Core>
#include <span>
#include <vector>

#include "topology/TopologyTypes.h"

namespace stroma::tensormass {

struct VertexEdgeTensors {
  std::vector<Eigen::Matrix3d> vertexTensors;  ///< K^pp, one per point (N/m)
  std::vector<Edge> edges;                     ///< (p, j), one per edge
  std::vector<Eigen::Matrix3d> edgeTensors;    ///< K^pj of edges[e] (N/m)

  /// Sets the sizes, every tensor zero.
  void reset(std::size_t pointCount, std::span<const Edge> edgeList);
  void setZero();
};

/// out += scale * K u (u and out: one vector per point).
void addProduct(const VertexEdgeTensors& K, std::span<const Eigen::Vector3d> u, double scale,
                std::span<Eigen::Vector3d> out);

/// 1/2 u^T K u.
double computeQuadraticEnergy(const VertexEdgeTensors& K, std::span<const Eigen::Vector3d> u);

}  // namespace stroma::tensormass
