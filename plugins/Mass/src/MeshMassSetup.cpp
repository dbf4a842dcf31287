// SPDX-License-Identifier: MIT
#include "MeshMassSetup.h"

#include "core/Node.h"

namespace stroma {

const Topology* findMassTopology(Base& owner, const Link<Topology>& link) {
  if (link) return link.get();
  if (owner.node())
    if (const Topology* topology = owner.node()->getUp<Topology>()) return topology;
  owner.msgError(
      "needs a topology (MeshTopology, TetrahedronSetTopologyContainer, "
      "RegularGridTopology, ...) in its node or above, or a 'topology' link: the mass "
      "is computed from the elements",
      "topology");
  return nullptr;
}

namespace {

// Reports the elements of `list` that use a point >= n; false when there is one.
template <std::size_t N>
bool checkElements(Base& owner, const Topology& topology, const char* list,
                   std::span<const std::array<Index, N>> elements, std::size_t n) {
  std::size_t bad = 0, first = 0;
  for (std::size_t e = 0; e < elements.size(); ++e)
    for (Index v : elements[e])
      if (v >= n) {
        if (bad++ == 0) first = e;
        break;
      }
  if (bad == 0) return true;
  std::string vertices;
  for (Index v : elements[first]) vertices += ' ' + std::to_string(v);
  owner.msgError(std::to_string(bad) + " " + list + " of " + topology.path() +
                     " use points out of range of the " + std::to_string(n) +
                     " points of the state (the first: element " + std::to_string(first) + ":" +
                     vertices + ")",
                 "topology");
  return false;
}

}  // namespace

bool computeMeshMass(Base& owner, const Topology& topology, std::span<const Vec3d> points,
                     MeshMassMatrix& out) {
  const MassElements elements{topology.edges(), topology.triangles(), topology.quads(),
                              topology.tetrahedra(), topology.hexahedra()};
  const std::size_t n = points.size();
  bool ok = checkElements<2>(owner, topology, "edges", elements.edges, n);
  ok &= checkElements<3>(owner, topology, "triangles", elements.triangles, n);
  ok &= checkElements<4>(owner, topology, "quads", elements.quads, n);
  ok &= checkElements<4>(owner, topology, "tetrahedra", elements.tetrahedra, n);
  ok &= checkElements<8>(owner, topology, "hexahedra", elements.hexahedra, n);
  if (!ok) return false;
  out = assembleMeshMass(points, elements);
  if (out.elements.empty()) {
    owner.msgError("the topology " + topology.path() +
                       " has no edge, triangle, quad, tetrahedron or hexahedron to carry the mass",
                   "topology");
    return false;
  }
  if (!(out.measure > 0)) {
    owner.msgError("the " + out.elements + " of " + topology.path() +
                       " have no volume (or area, or length): every point would have no mass",
                   "topology");
    return false;
  }
  return true;
}

void removeTetrahedronMasses(const TopologyChange& change, std::span<const Vec3d> points,
                             Eigen::SparseMatrix<double, Eigen::RowMajor>* matrix,
                             Eigen::VectorXd& lumped, double& measure) {
  for (const Tetrahedron& t : change.tetrahedra.removedElements) {
    const Eigen::Matrix4d m =
        tetrahedronMassMatrix(points[t[0]], points[t[1]], points[t[2]], points[t[3]]);
    for (int i = 0; i < 4; ++i) {
      lumped[t[i]] -= m.row(i).sum();
      if (matrix)
        for (int j = 0; j < 4; ++j) matrix->coeffRef(t[i], t[j]) -= m(i, j);
    }
    measure -= m.sum();
  }
  // Exact zeros where nothing is left.
  for (Index p : change.freedPoints) {
    lumped[p] = 0;
    if (!matrix) continue;
    for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(*matrix, p); it; ++it) {
      matrix->coeffRef(it.col(), p) = 0;
      it.valueRef() = 0;
    }
  }
  if (change.tetrahedra.sizeAfter == 0) measure = 0;
}

}  // namespace stroma
