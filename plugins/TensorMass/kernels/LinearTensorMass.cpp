// SPDX-License-Identifier: MIT
#include "TensorMass/kernels/LinearTensorMass.h"

#include "TensorMass/kernels/TetrahedronTensors.h"

namespace stroma::tensormass {

void buildLinearTensorMass(const TensorMassMesh& mesh, const fem::LameParameters& lame,
                           VertexEdgeTensors& tensors) {
  tensors.reset(mesh.pointCount, mesh.edges);
  for (std::size_t t = 0; t < mesh.tetrahedra.size(); ++t) {
    const Tetrahedron& v = mesh.tetrahedra[t];
    const TetrahedronTensors T(mesh.shapes[t], lame);
    for (int p = 0; p < 4; ++p) tensors.vertexTensors[v[p]] += T.stiffness(p, p);
    for (Index e : mesh.edgesInTetrahedron[t]) {
      // The edge's own orientation (p, j): K^pj, not K^jp.
      const int p = localVertex(v, mesh.edges[e][0]), j = localVertex(v, mesh.edges[e][1]);
      tensors.edgeTensors[e] += T.stiffness(p, j);
    }
  }
}

}  // namespace stroma::tensormass
