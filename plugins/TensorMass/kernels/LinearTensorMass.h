// SPDX-License-Identifier: MIT
// The linear tensor-mass model (Cotin, Delingette, Ayache; seed 000 chapter 1, eqs. 1.9 to
// 1.12; Picinbono et al., seed 004, eqs. 8 and 16): the stiffness tensors of every tetrahedron
// accumulated on the vertices and the edges of the mesh,
//
//   K^pp = sum_{T around p} K_T^pp,   K^pj = sum_{T around edge (p, j)} K_T^pj    (eq. 1.11)
//
// with K_T^jk = 2 B_T^jk (TetrahedronTensors.h). The force on vertex p is then (eq. 1.12)
//
//   F_p = -(K^pp U_p + sum_{edges (p, j)} K^pj U_j),   U = x - X,
//
// the linear elastic energy 1/2 U^T K U, and K the (constant) stiffness: -K is the tangent.
#pragma once

#include <array>
#include <span>

#include "SolidMechanics/kernels/IsotropicMaterial.h"
#include "SolidMechanics/kernels/LinearTetrahedron.h"
#include "TensorMass/kernels/VertexEdgeTensors.h"

namespace stroma::tensormass {

/// The mesh the tensor-mass models are built on: tetrahedra with their rest shapes, and the
/// edges and faces of a topology (topology/MeshAdjacency.h: kTetrahedronEdges and
/// kTetrahedronFaces give the local order of the per-tetrahedron indices).
struct TensorMassMesh {
  std::size_t pointCount = 0;
  std::span<const Tetrahedron> tetrahedra;
  std::span<const fem::TetrahedronShape> shapes;                 ///< rest shape of each tetrahedron
  std::span<const Edge> edges;                                   ///< unique edges
  std::span<const std::array<Index, 6>> edgesInTetrahedron;      ///< indices into edges
  std::span<const Triangle> triangles;                           ///< unique faces
  std::span<const std::array<Index, 4>> trianglesInTetrahedron;  ///< indices into triangles
};

/// The position (0 to 3) of point `point` in tetrahedron `t`; -1 when absent.
inline int localVertex(const Tetrahedron& t, Index point) {
  for (int i = 0; i < 4; ++i)
    if (t[i] == point) return i;
  return -1;
}

/// K^pp and K^pj of eq. 1.11 (edges and edgesInTetrahedron of `mesh` are used, not the faces).
void buildLinearTensorMass(const TensorMassMesh& mesh, const fem::LameParameters& lame,
                           VertexEdgeTensors& tensors);

}  // namespace stroma::tensormass
