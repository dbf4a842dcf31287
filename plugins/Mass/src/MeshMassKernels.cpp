// SPDX-License-Identifier: MIT
#include "MeshMassKernels.h"

#include <Eigen/Dense>
#include <cmath>

namespace stroma {

namespace {

// Gauss-Legendre, 3 points on [0, 1].
constexpr std::array<double, 3> kGaussPoint{0.5 - 0.3872983346207417, 0.5,
                                            0.5 + 0.3872983346207417};
constexpr std::array<double, 3> kGaussWeight{5.0 / 18, 8.0 / 18, 5.0 / 18};

template <int N>
Eigen::Matrix<double, N, N> simplexMass(double measure, double denominator) {
  Eigen::Matrix<double, N, N> m = Eigen::Matrix<double, N, N>::Constant(measure / denominator);
  m.diagonal() *= 2;
  return m;
}

}  // namespace

Eigen::Matrix2d edgeMassMatrix(const Vec3d& a, const Vec3d& b) {
  return simplexMass<2>((b - a).norm(), 6);
}

Eigen::Matrix3d triangleMassMatrix(const Vec3d& a, const Vec3d& b, const Vec3d& c) {
  return simplexMass<3>(0.5 * (b - a).cross(c - a).norm(), 12);
}

Eigen::Matrix4d tetrahedronMassMatrix(const Vec3d& a, const Vec3d& b, const Vec3d& c,
                                      const Vec3d& d) {
  return simplexMass<4>(std::abs((b - a).dot((c - a).cross(d - a))) / 6, 20);
}

Eigen::Matrix4d quadMassMatrix(const std::array<Vec3d, 4>& x) {
  // Bilinear map over (u, v) in [0, 1]^2: vertices (0,0) (1,0) (1,1) (0,1).
  Eigen::Matrix4d m = Eigen::Matrix4d::Zero();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const double u = kGaussPoint[i], v = kGaussPoint[j];
      const Eigen::Vector4d N((1 - u) * (1 - v), u * (1 - v), u * v, (1 - u) * v);
      const Vec3d xu = (1 - v) * (x[1] - x[0]) + v * (x[2] - x[3]);
      const Vec3d xv = (1 - u) * (x[3] - x[0]) + u * (x[2] - x[1]);
      m += kGaussWeight[i] * kGaussWeight[j] * xu.cross(xv).norm() * N * N.transpose();
    }
  return m;
}

Eigen::Matrix<double, 8, 8> hexahedronMassMatrix(const std::array<Vec3d, 8>& x) {
  // Trilinear map over (u, v, w) in [0, 1]^3, vertex k at the corner of TopologyTypes.h.
  static constexpr int corner[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                       {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  Eigen::Matrix<double, 8, 8> m = Eigen::Matrix<double, 8, 8>::Zero();
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b)
      for (int c = 0; c < 3; ++c) {
        const double p[3] = {kGaussPoint[a], kGaussPoint[b], kGaussPoint[c]};
        Eigen::Matrix<double, 8, 1> N;
        Mat3d J = Mat3d::Zero();  // columns dx/du, dx/dv, dx/dw
        for (int k = 0; k < 8; ++k) {
          double f[3], df[3];
          for (int d = 0; d < 3; ++d) {
            f[d] = corner[k][d] ? p[d] : 1 - p[d];
            df[d] = corner[k][d] ? 1 : -1;
          }
          N[k] = f[0] * f[1] * f[2];
          J.col(0) += df[0] * f[1] * f[2] * x[k];
          J.col(1) += f[0] * df[1] * f[2] * x[k];
          J.col(2) += f[0] * f[1] * df[2] * x[k];
        }
        const double w = kGaussWeight[a] * kGaussWeight[b] * kGaussWeight[c];
        m += w * std::abs(J.determinant()) * N * N.transpose();
      }
  return m;
}

namespace {

template <std::size_t N, class ElementMatrix>
void scatter(std::vector<Eigen::Triplet<double>>& triplets, std::span<const Vec3d> points,
             std::span<const std::array<Index, N>> elements, ElementMatrix&& elementMatrix) {
  for (const auto& e : elements) {
    std::array<Vec3d, N> x;
    for (std::size_t k = 0; k < N; ++k) x[k] = points[e[k]];
    const auto m = elementMatrix(x);
    for (std::size_t i = 0; i < N; ++i)
      for (std::size_t j = 0; j < N; ++j)
        triplets.emplace_back(static_cast<int>(e[i]), static_cast<int>(e[j]),
                              m(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)));
  }
}

}  // namespace

MeshMassMatrix assembleMeshMass(std::span<const Vec3d> points, const MassElements& elements) {
  std::vector<Eigen::Triplet<double>> triplets;
  MeshMassMatrix result;
  if (!elements.tetrahedra.empty() || !elements.hexahedra.empty()) {
    scatter<4>(triplets, points, elements.tetrahedra, [](const std::array<Vec3d, 4>& x) {
      return tetrahedronMassMatrix(x[0], x[1], x[2], x[3]);
    });
    scatter<8>(triplets, points, elements.hexahedra, hexahedronMassMatrix);
    result.elements = elements.hexahedra.empty()    ? "tetrahedra"
                      : elements.tetrahedra.empty() ? "hexahedra"
                                                    : "tetrahedra and hexahedra";
  } else if (!elements.triangles.empty() || !elements.quads.empty()) {
    scatter<3>(triplets, points, elements.triangles,
               [](const std::array<Vec3d, 3>& x) { return triangleMassMatrix(x[0], x[1], x[2]); });
    scatter<4>(triplets, points, elements.quads, quadMassMatrix);
    result.elements = elements.quads.empty()       ? "triangles"
                      : elements.triangles.empty() ? "quads"
                                                   : "triangles and quads";
  } else if (!elements.edges.empty()) {
    scatter<2>(triplets, points, elements.edges,
               [](const std::array<Vec3d, 2>& x) { return edgeMassMatrix(x[0], x[1]); });
    result.elements = "edges";
  }
  const auto n = static_cast<Eigen::Index>(points.size());
  result.matrix.resize(n, n);
  result.matrix.setFromTriplets(triplets.begin(), triplets.end());
  result.lumped = result.matrix * Eigen::VectorXd::Ones(n);
  result.measure = result.lumped.sum();
  return result;
}

}  // namespace stroma
