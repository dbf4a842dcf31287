// SPDX-License-Identifier: MIT
// Mass matrices of linear finite elements, for unit density: the consistent element matrices
//   M_ij = integral over the element of N_i N_j
// (N_i the shape functions), and their assembly over a mesh. The 3D mass matrix of a state is
// M (x) I3: the same scalar matrix for each coordinate. Knows nothing of components.
//
// Closed forms for simplices (Zienkiewicz, Taylor and Zhu, The Finite Element Method: Its
// Basis and Fundamentals, 7th ed. 2013, section 16.2.4):
//   edge of length L:           M = L/6  [2 1; 1 2]
//   triangle of area A:         M = A/12 (1 + delta_ij)
//   tetrahedron of volume V:    M = V/20 (1 + delta_ij)
// Hexahedra (trilinear, SOFA's vertex order) and quads (bilinear) are integrated with 3 Gauss
// points per direction, exact for the trilinear map of any hexahedron (N_i N_j det J is of
// degree <= 4 per direction) and for planar quads.
// Lumping by row sums gives each vertex the integral of its shape function: V/4 per tetrahedron
// vertex, A/3 per triangle vertex, V/8 per vertex of a parallelepiped (Hughes, The Finite
// Element Method, 2000, section 7.3.2).
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <array>
#include <span>
#include <string>
#include <vector>

#include "core/Types.h"
#include "topology/TopologyTypes.h"

namespace stroma {

Eigen::Matrix2d edgeMassMatrix(const Vec3d& a, const Vec3d& b);
Eigen::Matrix3d triangleMassMatrix(const Vec3d& a, const Vec3d& b, const Vec3d& c);
Eigen::Matrix4d quadMassMatrix(const std::array<Vec3d, 4>& x);
Eigen::Matrix4d tetrahedronMassMatrix(const Vec3d& a, const Vec3d& b, const Vec3d& c,
                                      const Vec3d& d);
Eigen::Matrix<double, 8, 8> hexahedronMassMatrix(const std::array<Vec3d, 8>& x);

/// The elements a mass is computed on (a topology's lists).
struct MassElements {
  std::span<const Edge> edges;
  std::span<const Triangle> triangles;
  std::span<const Quad> quads;
  std::span<const Tetrahedron> tetrahedra;
  std::span<const Hexahedron> hexahedra;
};

/// The unit-density mass matrix of a mesh (n x n, scalar) and its measure (the total volume,
/// area or length: the sum of the entries).
struct MeshMassMatrix {
  Eigen::SparseMatrix<double, Eigen::RowMajor> matrix;
  Eigen::VectorXd lumped;  ///< row sums
  double measure = 0;
  /// Which elements carry the mass: "tetrahedra and hexahedra", "triangles", ... or "".
  std::string elements;
};

/// Assembles over the elements of the highest dimension present: volumes (tetrahedra and
/// hexahedra), else surfaces (triangles and quads), else edges, as SOFA's masses do. Every
/// index must be < points.size() (checked by the caller).
MeshMassMatrix assembleMeshMass(std::span<const Vec3d> points, const MassElements& elements);

}  // namespace stroma
