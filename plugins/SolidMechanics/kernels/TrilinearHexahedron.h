// SPDX-License-Identifier: MIT
// Trilinear (8-node, Q1) hexahedron: shape functions, 2 x 2 x 2 Gauss stiffness and mass, for
// any non-degenerate rest shape (not only boxes).
//
// Node order, SOFA's HexahedronFEMForceField (its header comment draws it; also the order of
// SOFA's hexahedron topologies and of the VTK hexahedron), with reference corners s_i in
// [-1, 1]^3:
//
//        7---------6        node  s_i           node  s_i
//       /|        /|        0     (-1,-1,-1)    4     (-1,-1,+1)
//      / |       / |        1     (+1,-1,-1)    5     (+1,-1,+1)
//     4---------5  |        2     (+1,+1,-1)    6     (+1,+1,+1)
//     |  3------|--2        3     (-1,+1,-1)    7     (-1,+1,+1)
//     | /       | /
//     |/        |/       z up, x to the right, y into the page;
//     0---------1        the unit cube is (0,0,0),(1,0,0),(1,1,0),(0,1,0),(0,0,1),...,(0,1,1)
//
//   N_i(xi) = (1 + s_i,x xi)(1 + s_i,y eta)(1 + s_i,z zeta) / 8
//   J(xi) = dx/dxi = sum_i x_i dN_i/dxi^T,   grad N_i = J^-T dN_i/dxi
//   Ke = sum over the 8 Gauss points (+-1/sqrt 3) of |det J| B^T C B     (N/m)
//   M_ij = rho integral N_i N_j dV (3 x 3 x 3 Gauss: exact for any trilinear shape)  (kg)
//
// (Nesme thesis, seed 001, ch. 4 sec. 2 and appendix D; Zienkiewicz and Taylor, vol. 1,
// ch. 6 and 9). 2 x 2 x 2 Gauss integrates the volume exactly and Ke fully (no hourglass modes):
// Ke has exactly 6 zero eigenvalues. The element passes the patch test on distorted shapes.
// A left-handed numbering (det J < 0 everywhere) is accepted: |det J| is used.
#pragma once

#include "SolidMechanics/kernels/FemTypes.h"

namespace stroma::fem {

using Matrix8d = Eigen::Matrix<double, 8, 8>;
using Vector8d = Eigen::Matrix<double, 8, 1>;

/// Reference corner s_i of node i (0..7), components +-1.
Eigen::Vector3d hexahedronReferenceCorner(int node);

/// The 8 shape functions N_i at reference point xi in [-1, 1]^3; they sum to 1.
Vector8d computeHexahedronShapeFunctions(const Eigen::Vector3d& xi);

/// Reference gradients dN_i/dxi at xi (column i, dimensionless).
HexahedronVectors computeHexahedronReferenceGradients(const Eigen::Vector3d& xi);

/// Jacobian J = dx/dxi (m) of the map from reference to the positions x, at xi.
Eigen::Matrix3d computeHexahedronJacobian(const HexahedronVectors& x, const Eigen::Vector3d& xi);

/// Physical gradients grad N_i (column i, 1/m) of the shape `rest` at xi, and det J there
/// (m^3 / 8 for a cube of side 1). Reports `degenerate` when
/// |det J| <= 1e-12 (|J|_F / sqrt 3)^3 or a coordinate is not finite.
ElementStatus computeHexahedronGradients(const HexahedronVectors& rest, const Eigen::Vector3d& xi,
                                         HexahedronVectors& gradients, double& detJ);

/// Signed volume integral det J (m^3), exact (2 x 2 x 2 Gauss).
double computeHexahedronVolume(const HexahedronVectors& x);

/// Element stiffness Ke (24 x 24, N/m) of the rest shape, 2 x 2 x 2 Gauss. Reports
/// `degenerate` when det J vanishes or changes sign at a Gauss point.
ElementStatus computeHexahedronStiffness(const HexahedronVectors& rest, const Matrix6d& C,
                                         Matrix24d& Ke);

/// Consistent mass M_ij = rho integral N_i N_j dV (8 x 8, kg) for a density rho (kg/m^3);
/// the 24 x 24 mass is M (x) I_3. Its entries sum to rho V.
Matrix8d computeHexahedronConsistentMass(const HexahedronVectors& rest, double density);

/// Lumped (row-sum) mass of each node (kg); equals rho V / 8 per node for a parallelepiped.
Vector8d computeHexahedronLumpedMass(const HexahedronVectors& rest, double density);

}  // namespace stroma::fem
