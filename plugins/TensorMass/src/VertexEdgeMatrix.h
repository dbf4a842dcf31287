// SPDX-License-Identifier: MIT
// Assembly of vertex and edge tensors (VertexEdgeTensors.h) into a solver's matrix.
#pragma once

#include "TensorMass/kernels/VertexEdgeTensors.h"
#include "linalg/AssembledMatrix.h"

namespace stroma {

/// Adds scale * K, with the state's first row at `offset`: blocks (p, j) and (j, p) of each
/// edge, then (p, p) of each vertex.
inline void addToMatrix(const tensormass::VertexEdgeTensors& K, double scale,
                        MatrixAccumulator& matrix, std::size_t offset) {
  for (std::size_t e = 0; e < K.edges.size(); ++e) {
    const std::size_t p = offset + 3 * std::size_t{K.edges[e][0]};
    const std::size_t j = offset + 3 * std::size_t{K.edges[e][1]};
    const Eigen::Matrix3d block = scale * K.edgeTensors[e];
    matrix.addBlock(p, j, block);
    matrix.addBlock(j, p, block.transpose());
  }
  for (std::size_t p = 0; p < K.vertexTensors.size(); ++p)
    matrix.addBlock(offset + 3 * p, offset + 3 * p, scale * K.vertexTensors[p]);
}

}  // namespace stroma
