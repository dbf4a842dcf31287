// SPDX-License-Identifier: MIT
#include "TensorMass/kernels/VertexEdgeTensors.h"

namespace stroma::tensormass {

void VertexEdgeTensors::reset(std::size_t pointCount, std::span<const Edge> edgeList) {
  vertexTensors.assign(pointCount, Eigen::Matrix3d::Zero());
  edges.assign(edgeList.begin(), edgeList.end());
  edgeTensors.assign(edges.size(), Eigen::Matrix3d::Zero());
}

void VertexEdgeTensors::setZero() {
  for (Eigen::Matrix3d& t : vertexTensors) t.setZero();
  for (Eigen::Matrix3d& t : edgeTensors) t.setZero();
}

void addProduct(const VertexEdgeTensors& K, std::span<const Eigen::Vector3d> u, double scale,
                std::span<Eigen::Vector3d> out) {
  // Edges first: each one pushes on both of its vertices (seed 000 section 3.3).
  for (std::size_t e = 0; e < K.edges.size(); ++e) {
    const Index p = K.edges[e][0], j = K.edges[e][1];
    const Eigen::Matrix3d& Kpj = K.edgeTensors[e];
    out[p].noalias() += scale * (Kpj * u[j]);
    out[j].noalias() += scale * (Kpj.transpose() * u[p]);
  }
  // Then each vertex, by its own displacement.
  for (std::size_t p = 0; p < K.vertexTensors.size(); ++p)
    out[p].noalias() += scale * (K.vertexTensors[p] * u[p]);
}

double computeQuadraticEnergy(const VertexEdgeTensors& K, std::span<const Eigen::Vector3d> u) {
  double energy = 0;
  for (std::size_t e = 0; e < K.edges.size(); ++e)
    energy += u[K.edges[e][0]].dot(K.edgeTensors[e] * u[K.edges[e][1]]);
  for (std::size_t p = 0; p < K.vertexTensors.size(); ++p)
    energy += 0.5 * u[p].dot(K.vertexTensors[p] * u[p]);
  return energy;
}

}  // namespace stroma::tensormass
