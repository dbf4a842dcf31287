// SPDX-License-Identifier: MIT
#include "TensorMass/kernels/StVKTensorMass.h"

#include "TensorMass/kernels/TetrahedronTensors.h"
#include "topology/MeshAdjacency.h"

namespace stroma::tensormass {

using Eigen::Matrix3d;
using Eigen::Vector3d;

namespace {

// Local edge index (kTetrahedronEdges order) of the vertices (i, j) of a tetrahedron.
constexpr std::array<std::array<int, 4>, 4> kLocalEdge = [] {
  std::array<std::array<int, 4>, 4> table{};
  for (int e = 0; e < 6; ++e) {
    table[kTetrahedronEdges[e][0]][kTetrahedronEdges[e][1]] = e;
    table[kTetrahedronEdges[e][1]][kTetrahedronEdges[e][0]] = e;
  }
  return table;
}();

// The Hessian blocks of one primitive's polynomial in the displacements of its N vertices,
// built term by term. With g_kl = U_k . U_l, dg_kl/dU_x = [x = k] U_l + [x = l] U_k and
// d2g_kl/dU_x dU_y = ([x = k][y = l] + [x = l][y = k]) I.
template <int N>
class LocalHessian {
 public:
  explicit LocalHessian(const std::array<Vector3d, N>& u) : m_u(u) {
    for (auto& row : m_blocks)
      for (Matrix3d& block : row) block.setZero();
  }

  Matrix3d& block(int x, int y) { return m_blocks[x][y]; }

  // w d2g_kl.
  void addGramSecond(double w, int k, int l) {
    m_blocks[k][l].diagonal().array() += w;
    m_blocks[l][k].diagonal().array() += w;
  }

  // (c . U_i) g_kl.
  void addCubic(const Vector3d& c, int i, int k, int l) {
    for (int x : distinct(k, l)) {
      const Vector3d dg = gramDerivative(k, l, x);
      m_blocks[i][x].noalias() += c * dg.transpose();
      m_blocks[x][i].noalias() += dg * c.transpose();
    }
    addGramSecond(c.dot(m_u[i]), k, l);
  }

  // d g_ij g_kl.
  void addQuartic(double d, int i, int j, int k, int l) {
    addGramSecond(d * m_u[k].dot(m_u[l]), i, j);
    addGramSecond(d * m_u[i].dot(m_u[j]), k, l);
    for (int x : distinct(i, j)) {
      const Vector3d dgx = gramDerivative(i, j, x);
      for (int y : distinct(k, l)) {
        const Matrix3d outer = d * dgx * gramDerivative(k, l, y).transpose();
        m_blocks[x][y] += outer;
        m_blocks[y][x] += outer.transpose();
      }
    }
  }

 private:
  // The vertices a g_kl depends on: {k, l}, or {k} when k = l.
  struct Support {
    std::array<int, 2> vertices;
    int count;
    const int* begin() const { return vertices.data(); }
    const int* end() const { return vertices.data() + count; }
  };
  static Support distinct(int k, int l) { return {{k, l}, k == l ? 1 : 2}; }
  Vector3d gramDerivative(int k, int l, int x) const {
    Vector3d r = Vector3d::Zero();
    if (x == k) r += m_u[l];
    if (x == l) r += m_u[k];
    return r;
  }

  const std::array<Vector3d, N>& m_u;
  std::array<std::array<Matrix3d, N>, N> m_blocks;
};

// Adds block (x, y) of a primitive to the edge (points[x], points[y]) of the global tensors,
// transposed when the edge is stored the other way round.
void addEdgeBlock(VertexEdgeTensors& hessian, Index edge, Index pointX, const Matrix3d& blockXY) {
  if (hessian.edges[edge][0] == pointX)
    hessian.edgeTensors[edge] += blockXY;
  else
    hessian.edgeTensors[edge] += blockXY.transpose();
}

}  // namespace

void buildStVKTensorMass(const TensorMassMesh& mesh, const fem::LameParameters& lame,
                         StVKTensorMass& model) {
  model.vertices.assign(mesh.pointCount, {});
  model.edges.assign(mesh.edges.begin(), mesh.edges.end());
  model.edgeTerms.assign(mesh.edges.size(), {});
  model.triangles.assign(mesh.triangles.begin(), mesh.triangles.end());
  model.triangleTerms.assign(mesh.triangles.size(), {});
  model.tetrahedra.assign(mesh.tetrahedra.begin(), mesh.tetrahedra.end());
  model.tetrahedronTerms.assign(mesh.tetrahedra.size(), {});
  model.triangleEdges.assign(mesh.triangles.size(), {kInvalidIndex, kInvalidIndex, kInvalidIndex});
  model.tetrahedronEdges.assign(mesh.edgesInTetrahedron.begin(), mesh.edgesInTetrahedron.end());

  for (std::size_t t = 0; t < mesh.tetrahedra.size(); ++t) {
    const Tetrahedron& v = mesh.tetrahedra[t];
    const TetrahedronTensors T(mesh.shapes[t], lame);
    addStVKTetrahedronTerms(v, T, mesh.edgesInTetrahedron[t], mesh.trianglesInTetrahedron[t], 1.0,
                            model);
    // The edges of each triangle, from the first tetrahedron that has it.
    for (Index f : mesh.trianglesInTetrahedron[t]) {
      if (model.triangleEdges[f][0] != kInvalidIndex) continue;
      const Triangle& tri = mesh.triangles[f];
      const int a = localVertex(v, tri[0]), b = localVertex(v, tri[1]), c = localVertex(v, tri[2]);
      const auto& edges = mesh.edgesInTetrahedron[t];
      model.triangleEdges[f] = {edges[kLocalEdge[a][b]], edges[kLocalEdge[b][c]],
                                edges[kLocalEdge[a][c]]};
    }
    // Terms of four vertices.
    model.tetrahedronTerms[t] = {T.quartic(0, 1, 2, 3), T.quartic(0, 2, 1, 3),
                                 T.quartic(0, 3, 1, 2)};
  }
}

void addStVKTetrahedronTerms(const Tetrahedron& v, const TetrahedronTensors& T,
                             const std::array<Index, 6>& edgesOfTetrahedron,
                             const std::array<Index, 4>& trianglesOfTetrahedron, double sign,
                             StVKTensorMass& model) {
  // Terms of one vertex (table 1, first row).
  for (int p = 0; p < 4; ++p) {
    StVKTensorMass::VertexTerms& vertex = model.vertices[v[p]];
    vertex.K += sign * T.stiffness(p, p);
    vertex.c += sign * T.cubic(p, p, p);
    vertex.d += sign * T.quartic(p, p, p, p);
  }
  // Terms of two vertices, in the edge's orientation (a, b).
  for (Index e : edgesOfTetrahedron) {
    const int a = localVertex(v, model.edges[e][0]), b = localVertex(v, model.edges[e][1]);
    StVKTensorMass::EdgeTerms& edge = model.edgeTerms[e];
    edge.K += sign * T.stiffness(a, b);
    edge.c[0] += sign * T.cubic(a, a, b);
    edge.c[1] += sign * T.cubic(a, b, b);
    edge.c[2] += sign * T.cubic(b, a, a);
    edge.c[3] += sign * T.cubic(b, a, b);
    edge.d[0] += sign * T.quartic(a, a, a, b);
    edge.d[1] += sign * T.quartic(b, b, a, b);
    edge.d[2] += sign * T.quartic(a, a, b, b);
    edge.d[3] += sign * T.quartic(a, b, a, b);
  }
  // Terms of three vertices, in the triangle's order (a, b, c).
  for (Index f : trianglesOfTetrahedron) {
    const Triangle& tri = model.triangles[f];
    const int a = localVertex(v, tri[0]), b = localVertex(v, tri[1]), c = localVertex(v, tri[2]);
    StVKTensorMass::TriangleTerms& triangle = model.triangleTerms[f];
    triangle.c[0] += sign * T.cubic(a, b, c);
    triangle.c[1] += sign * T.cubic(b, a, c);
    triangle.c[2] += sign * T.cubic(c, a, b);
    triangle.e[0] += sign * T.quartic(a, a, b, c);
    triangle.e[1] += sign * T.quartic(b, b, a, c);
    triangle.e[2] += sign * T.quartic(c, c, a, b);
    triangle.e[3] += sign * T.quartic(a, b, a, c);
    triangle.e[4] += sign * T.quartic(a, b, b, c);
    triangle.e[5] += sign * T.quartic(a, c, b, c);
  }
}

void addStVKForce(const StVKTensorMass& model, std::span<const Vector3d> u, std::span<Vector3d> f) {
  // Vertices: grad = K U + c g + 2 (c.U) U + 4 d g U.
  for (std::size_t p = 0; p < model.vertices.size(); ++p) {
    const StVKTensorMass::VertexTerms& v = model.vertices[p];
    const Vector3d& U = u[p];
    const double g = U.squaredNorm();
    f[p] -= v.K * U + g * v.c + (2 * v.c.dot(U) + 4 * v.d * g) * U;
  }
  // Edges: with s = dW/dg_ab, grad_a = K U_b + c1 g_ab + c2 g_bb + 2 (dW/dg_aa) U_a + s U_b.
  for (std::size_t e = 0; e < model.edges.size(); ++e) {
    const StVKTensorMass::EdgeTerms& t = model.edgeTerms[e];
    const Index a = model.edges[e][0], b = model.edges[e][1];
    const Vector3d& Ua = u[a];
    const Vector3d& Ub = u[b];
    const double gaa = Ua.squaredNorm(), gbb = Ub.squaredNorm(), gab = Ua.dot(Ub);
    const double c1a = t.c[0].dot(Ua), c2a = t.c[1].dot(Ua), c3b = t.c[2].dot(Ub),
                 c4b = t.c[3].dot(Ub);
    const double wab = c1a + c4b + t.d[0] * gaa + t.d[1] * gbb + 2 * t.d[3] * gab;
    const double waa = c3b + t.d[0] * gab + t.d[2] * gbb;  // dW/dg_aa
    const double wbb = c2a + t.d[1] * gab + t.d[2] * gaa;  // dW/dg_bb
    f[a] -= t.K * Ub + gab * t.c[0] + gbb * t.c[1] + 2 * waa * Ua + wab * Ub;
    f[b] -= t.K.transpose() * Ua + gaa * t.c[2] + gab * t.c[3] + 2 * wbb * Ub + wab * Ua;
  }
  // Triangles: the same with the derivatives of W in each g_ij.
  for (std::size_t i = 0; i < model.triangles.size(); ++i) {
    const StVKTensorMass::TriangleTerms& t = model.triangleTerms[i];
    const Index a = model.triangles[i][0], b = model.triangles[i][1], c = model.triangles[i][2];
    const Vector3d& Ua = u[a];
    const Vector3d& Ub = u[b];
    const Vector3d& Uc = u[c];
    const double gaa = Ua.squaredNorm(), gbb = Ub.squaredNorm(), gcc = Uc.squaredNorm();
    const double gab = Ua.dot(Ub), gac = Ua.dot(Uc), gbc = Ub.dot(Uc);
    const double wab = t.c[2].dot(Uc) + t.e[2] * gcc + t.e[3] * gac + t.e[4] * gbc;
    const double wac = t.c[1].dot(Ub) + t.e[1] * gbb + t.e[3] * gab + t.e[5] * gbc;
    const double wbc = t.c[0].dot(Ua) + t.e[0] * gaa + t.e[4] * gab + t.e[5] * gac;
    f[a] -= gbc * t.c[0] + 2 * t.e[0] * gbc * Ua + wab * Ub + wac * Uc;
    f[b] -= gac * t.c[1] + 2 * t.e[1] * gac * Ub + wab * Ua + wbc * Uc;
    f[c] -= gab * t.c[2] + 2 * t.e[2] * gab * Uc + wac * Ua + wbc * Ub;
  }
  // Tetrahedra: t1 g_ab g_cd + t2 g_ac g_bd + t3 g_ad g_bc.
  for (std::size_t i = 0; i < model.tetrahedra.size(); ++i) {
    const auto& t = model.tetrahedronTerms[i];
    const Tetrahedron& v = model.tetrahedra[i];
    const Vector3d& Ua = u[v[0]];
    const Vector3d& Ub = u[v[1]];
    const Vector3d& Uc = u[v[2]];
    const Vector3d& Ud = u[v[3]];
    const double wab = t[0] * Uc.dot(Ud), wcd = t[0] * Ua.dot(Ub);
    const double wac = t[1] * Ub.dot(Ud), wbd = t[1] * Ua.dot(Uc);
    const double wad = t[2] * Ub.dot(Uc), wbc = t[2] * Ua.dot(Ud);
    f[v[0]] -= wab * Ub + wac * Uc + wad * Ud;
    f[v[1]] -= wab * Ua + wbd * Ud + wbc * Uc;
    f[v[2]] -= wcd * Ud + wac * Ua + wbc * Ub;
    f[v[3]] -= wcd * Uc + wbd * Ub + wad * Ua;
  }
}

double computeStVKEnergy(const StVKTensorMass& model, std::span<const Vector3d> u) {
  double energy = 0;
  for (std::size_t p = 0; p < model.vertices.size(); ++p) {
    const StVKTensorMass::VertexTerms& v = model.vertices[p];
    const double g = u[p].squaredNorm();
    energy += 0.5 * u[p].dot(v.K * u[p]) + v.c.dot(u[p]) * g + v.d * g * g;
  }
  for (std::size_t e = 0; e < model.edges.size(); ++e) {
    const StVKTensorMass::EdgeTerms& t = model.edgeTerms[e];
    const Vector3d& Ua = u[model.edges[e][0]];
    const Vector3d& Ub = u[model.edges[e][1]];
    const double gaa = Ua.squaredNorm(), gbb = Ub.squaredNorm(), gab = Ua.dot(Ub);
    energy += Ua.dot(t.K * Ub) + t.c[0].dot(Ua) * gab + t.c[1].dot(Ua) * gbb +
              t.c[2].dot(Ub) * gaa + t.c[3].dot(Ub) * gab + t.d[0] * gaa * gab +
              t.d[1] * gbb * gab + t.d[2] * gaa * gbb + t.d[3] * gab * gab;
  }
  for (std::size_t i = 0; i < model.triangles.size(); ++i) {
    const StVKTensorMass::TriangleTerms& t = model.triangleTerms[i];
    const Vector3d& Ua = u[model.triangles[i][0]];
    const Vector3d& Ub = u[model.triangles[i][1]];
    const Vector3d& Uc = u[model.triangles[i][2]];
    const double gaa = Ua.squaredNorm(), gbb = Ub.squaredNorm(), gcc = Uc.squaredNorm();
    const double gab = Ua.dot(Ub), gac = Ua.dot(Uc), gbc = Ub.dot(Uc);
    energy += t.c[0].dot(Ua) * gbc + t.c[1].dot(Ub) * gac + t.c[2].dot(Uc) * gab +
              t.e[0] * gaa * gbc + t.e[1] * gbb * gac + t.e[2] * gcc * gab + t.e[3] * gab * gac +
              t.e[4] * gab * gbc + t.e[5] * gac * gbc;
  }
  for (std::size_t i = 0; i < model.tetrahedra.size(); ++i) {
    const auto& t = model.tetrahedronTerms[i];
    const Tetrahedron& v = model.tetrahedra[i];
    const Vector3d& Ua = u[v[0]];
    const Vector3d& Ub = u[v[1]];
    const Vector3d& Uc = u[v[2]];
    const Vector3d& Ud = u[v[3]];
    energy += t[0] * Ua.dot(Ub) * Uc.dot(Ud) + t[1] * Ua.dot(Uc) * Ub.dot(Ud) +
              t[2] * Ua.dot(Ud) * Ub.dot(Uc);
  }
  return energy;
}

void computeStVKHessian(const StVKTensorMass& model, std::span<const Vector3d> u,
                        VertexEdgeTensors& hessian) {
  hessian.setZero();
  for (std::size_t p = 0; p < model.vertices.size(); ++p) {
    const StVKTensorMass::VertexTerms& v = model.vertices[p];
    const std::array<Vector3d, 1> U{u[p]};
    LocalHessian<1> H(U);
    H.block(0, 0) += v.K;
    H.addCubic(v.c, 0, 0, 0);
    H.addQuartic(v.d, 0, 0, 0, 0);
    hessian.vertexTensors[p] += H.block(0, 0);
  }
  for (std::size_t e = 0; e < model.edges.size(); ++e) {
    const StVKTensorMass::EdgeTerms& t = model.edgeTerms[e];
    const Index a = model.edges[e][0], b = model.edges[e][1];
    const std::array<Vector3d, 2> U{u[a], u[b]};
    LocalHessian<2> H(U);
    H.block(0, 1) += t.K;
    H.block(1, 0) += t.K.transpose();
    H.addCubic(t.c[0], 0, 0, 1);
    H.addCubic(t.c[1], 0, 1, 1);
    H.addCubic(t.c[2], 1, 0, 0);
    H.addCubic(t.c[3], 1, 0, 1);
    H.addQuartic(t.d[0], 0, 0, 0, 1);
    H.addQuartic(t.d[1], 1, 1, 0, 1);
    H.addQuartic(t.d[2], 0, 0, 1, 1);
    H.addQuartic(t.d[3], 0, 1, 0, 1);
    hessian.vertexTensors[a] += H.block(0, 0);
    hessian.vertexTensors[b] += H.block(1, 1);
    hessian.edgeTensors[e] += H.block(0, 1);
  }
  for (std::size_t i = 0; i < model.triangles.size(); ++i) {
    const StVKTensorMass::TriangleTerms& t = model.triangleTerms[i];
    const Triangle& v = model.triangles[i];
    const std::array<Vector3d, 3> U{u[v[0]], u[v[1]], u[v[2]]};
    LocalHessian<3> H(U);
    H.addCubic(t.c[0], 0, 1, 2);
    H.addCubic(t.c[1], 1, 0, 2);
    H.addCubic(t.c[2], 2, 0, 1);
    H.addQuartic(t.e[0], 0, 0, 1, 2);
    H.addQuartic(t.e[1], 1, 1, 0, 2);
    H.addQuartic(t.e[2], 2, 2, 0, 1);
    H.addQuartic(t.e[3], 0, 1, 0, 2);
    H.addQuartic(t.e[4], 0, 1, 1, 2);
    H.addQuartic(t.e[5], 0, 2, 1, 2);
    for (int x = 0; x < 3; ++x) hessian.vertexTensors[v[x]] += H.block(x, x);
    const auto& edges = model.triangleEdges[i];  // (a, b), (b, c), (a, c)
    addEdgeBlock(hessian, edges[0], v[0], H.block(0, 1));
    addEdgeBlock(hessian, edges[1], v[1], H.block(1, 2));
    addEdgeBlock(hessian, edges[2], v[0], H.block(0, 2));
  }
  for (std::size_t i = 0; i < model.tetrahedra.size(); ++i) {
    const auto& t = model.tetrahedronTerms[i];
    const Tetrahedron& v = model.tetrahedra[i];
    const std::array<Vector3d, 4> U{u[v[0]], u[v[1]], u[v[2]], u[v[3]]};
    LocalHessian<4> H(U);
    H.addQuartic(t[0], 0, 1, 2, 3);
    H.addQuartic(t[1], 0, 2, 1, 3);
    H.addQuartic(t[2], 0, 3, 1, 2);
    for (int x = 0; x < 4; ++x) hessian.vertexTensors[v[x]] += H.block(x, x);
    for (int e = 0; e < 6; ++e) {
      const int x = kTetrahedronEdges[e][0], y = kTetrahedronEdges[e][1];
      addEdgeBlock(hessian, model.tetrahedronEdges[i][e], v[x], H.block(x, y));
    }
  }
}

}  // namespace stroma::tensormass
