// SPDX-License-Identifier: MIT
// The non-linear (St Venant-Kirchhoff) tensor-mass model of Picinbono, Delingette, Ayache
// (seed 004, section 3.1, eqs. 13 to 16 and table 1).
//
// The energy of every tetrahedron (eq. 13, TetrahedronTensors.h) is a polynomial of degree 4
// in the displacements U = x - X. Its terms are grouped by the vertices they involve and
// accumulated over the tetrahedra onto the vertices, edges, triangles and tetrahedra of the
// mesh (table 1). With g_ij = U_i . U_j:
//
//   vertex p:       1/2 U_p^T K U_p + (c . U_p) g_pp + d g_pp^2
//   edge (a, b):    U_a^T K U_b + (c1.U_a) g_ab + (c2.U_a) g_bb + (c3.U_b) g_aa + (c4.U_b) g_ab
//                   + d1 g_aa g_ab + d2 g_bb g_ab + d3 g_aa g_bb + d4 g_ab^2
//   triangle (a, b, c): (ca.U_a) g_bc + (cb.U_b) g_ac + (cc.U_c) g_ab
//                   + e1 g_aa g_bc + e2 g_bb g_ac + e3 g_cc g_ab
//                   + e4 g_ab g_ac + e5 g_ab g_bc + e6 g_ac g_bc
//   tetrahedron (a, b, c, d): t1 g_ab g_cd + t2 g_ac g_bd + t3 g_ad g_bc
//
// K: the stiffness tensors B of eq. 8 (K = 2B); c: the vectors C of eq. 14 (summed over the
// index orders giving the same term); d, e, t: the scalars D of eq. 14 likewise. The table's
// entries are the same numbers, its symmetric duplicates merged. The force on each vertex is
// minus the gradient of these polynomials (eq. 15), computed primitive by primitive: vertices,
// edges, triangles, then tetrahedra. The tangent stiffness is minus their Hessian: since every
// pair of vertices in a term shares an edge, it is a VertexEdgeTensors (computeTangent).
#pragma once

#include <array>
#include <span>
#include <vector>

#include "TensorMass/kernels/LinearTensorMass.h"
#include "TensorMass/kernels/TetrahedronTensors.h"
#include "TensorMass/kernels/VertexEdgeTensors.h"

namespace stroma::tensormass {

struct StVKTensorMass {
  struct VertexTerms {
    Eigen::Matrix3d K = Eigen::Matrix3d::Zero();  ///< N/m
    Eigen::Vector3d c = Eigen::Vector3d::Zero();  ///< N/m^2
    double d = 0;                                 ///< N/m^3
  };
  struct EdgeTerms {
    Eigen::Matrix3d K = Eigen::Matrix3d::Zero();
    std::array<Eigen::Vector3d, 4> c{Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(),
                                     Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
    std::array<double, 4> d{};
  };
  struct TriangleTerms {
    std::array<Eigen::Vector3d, 3> c{Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(),
                                     Eigen::Vector3d::Zero()};
    std::array<double, 6> e{};
  };

  std::vector<VertexTerms> vertices;  ///< one per point
  std::vector<Edge> edges;            ///< the mesh's edges (a, b)
  std::vector<EdgeTerms> edgeTerms;   ///< one per edge
  std::vector<Triangle> triangles;    ///< the mesh's faces (a, b, c)
  std::vector<TriangleTerms> triangleTerms;
  std::vector<Tetrahedron> tetrahedra;
  std::vector<std::array<double, 3>> tetrahedronTerms;  ///< t1, t2, t3
  /// For the tangent: the edges (a, b), (b, c), (a, c) of each triangle, and the edges of each
  /// tetrahedron (kTetrahedronEdges order), as indices into `edges`.
  std::vector<std::array<Index, 3>> triangleEdges;
  std::vector<std::array<Index, 6>> tetrahedronEdges;
};

/// Accumulates the terms of every tetrahedron of `mesh` (its edges and faces must be those of
/// its tetrahedra) onto its vertices, edges, triangles and tetrahedra.
void buildStVKTensorMass(const TensorMassMesh& mesh, const fem::LameParameters& lame,
                         StVKTensorMass& model);

/// Adds sign times the terms of one tetrahedron (vertices v, tensors T) to its vertices, to its
/// edges (indices into model.edges, kTetrahedronEdges order) and to its triangles (indices into
/// model.triangles), each in the orientation stored there; its own tetrahedron terms are not
/// touched. What buildStVKTensorMass does per tetrahedron (sign 1) and a removal undoes (-1).
void addStVKTetrahedronTerms(const Tetrahedron& v, const TetrahedronTensors& T,
                             const std::array<Index, 6>& edgesOfTetrahedron,
                             const std::array<Index, 4>& trianglesOfTetrahedron, double sign,
                             StVKTensorMass& model);

/// f -= dW/dU at displacements u (one per point): the elastic forces of eq. 15.
void addStVKForce(const StVKTensorMass& model, std::span<const Eigen::Vector3d> u,
                  std::span<Eigen::Vector3d> f);

/// The energy W(u) (J).
double computeStVKEnergy(const StVKTensorMass& model, std::span<const Eigen::Vector3d> u);

/// The Hessian d2W/dU2 at u into `hessian` (sized by the caller with the model's edges); the
/// tangent stiffness df/dx is its opposite.
void computeStVKHessian(const StVKTensorMass& model, std::span<const Eigen::Vector3d> u,
                        VertexEdgeTensors& hessian);

}  // namespace stroma::tensormass
