// SPDX-License-Identifier: MIT
// The corotational constant-strain triangle: a linear elastic membrane (plane stress, or plane
// strain) on a 3-node triangle in 3D, the element of SOFA's TriangularFEMForceField and
// TriangleFEMForceField.
//
// Element frame. For corners x0, x1, x2 the frame R = [e1 e2 n] has e1 along the edge 0-1, n the
// unit normal (x1 - x0) x (x2 - x0) / |.|, e2 = n x e1 (in the plane, towards x2). P = [I2 0] keeps
// the in-plane coordinates, so a corner's local position is q_i = P R^T (x_i - x0) (q_0 = 0).
//
// Rest shape. p_i = s P R0^T (X_i - X0), with R0 the frame of the rest corners X and s the
// rest scale (1, or SOFA TriangularFEMForceFieldOptim's restScale: s < 1 pre-stretches). The
// element stiffness acts on the in-plane displacements (u0x u0y u1x u1y u2x u2y):
//
//   Ke = t A B^T D B   (6 x 6),
//
// A the area of p, t the thickness, B (3 x 6) the constant strain-displacement matrix of the
// linear triangle (strain (eps_xx, eps_yy, gamma_xy), gamma engineering shear: column pair of
// corner i = [b_i 0; 0 c_i; c_i b_i], (b_i, c_i) the gradient of its shape function), and D the
// plane-stress elasticity matrix E / (1 - nu^2) [1 nu 0; nu 1 0; 0 0 (1 - nu) / 2] (Zienkiewicz
// and Taylor, The Finite Element Method, vol. 1, 5th ed. 2000, sec. 4.2, eqs. 4.13-4.16; plane
// strain: eq. 4.19). Ke does not depend on s: B scales as 1/s and A as s^2.
//
// Forces (R = R0 for `small`, the frame of the current corners for `large`):
//
//   u_i = P R^T (x_i - x0) - p_i,   f_i = R P^T (-Ke u)_i,   E = 1/2 u^T Ke u,
//   df = -K dx with K = T Ke T^T,  T = diag(R P^T, R P^T, R P^T)   (9 x 6), dR/dx ignored.
//
// `small` is linear elasticity in the rest plane: f = -dE/dx and K exact, no stiffness across
// the plane. `large` is invariant under rigid motions; its tangent leaves out dR/dx (exact at
// the rest shape, an O(strain) relative error elsewhere, as for the corotational tetrahedra);
// since Ke u is not a pure in-plane stress of the current frame, f is -dE/dx only to O(strain).
// The triangle has no bending stiffness: a flat sheet is free to fold at zero force.
#pragma once

#include <Eigen/Core>

#include "SolidMechanics/kernels/FemTypes.h"

namespace stroma::fem {

using TriangleVectors = NodalVectors<3>;
using Matrix9d = ElementMatrix<3>;

/// How the triangle's rotation is found (SOFA's keywords).
enum class TriangleMethod { small, large };

/// In-plane material law of the membrane.
enum class MembraneLaw { planeStress, planeStrain };

/// The constants of one triangle, computed once from its rest corners.
struct CorotationalTriangle {
  /// Rest corners in the rest frame, times the rest scale (column i = p_i, p_0 = 0).
  Eigen::Matrix<double, 2, 3> restLocal = Eigen::Matrix<double, 2, 3>::Zero();
  /// Frame of the rest corners [e1 e2 n] (the rotation of `small`).
  Eigen::Matrix3d restFrame = Eigen::Matrix3d::Identity();
  /// t A B^T D B on the in-plane displacements (u0x u0y u1x u1y u2x u2y).
  Eigen::Matrix<double, 6, 6> stiffness = Eigen::Matrix<double, 6, 6>::Zero();
  /// Rest area A (m^2), before the rest scale.
  double area = 0;
};

/// The 3 x 3 in-plane elasticity matrix D on (eps_xx, eps_yy, gamma_xy) (Pa), isotropic.
Eigen::Matrix3d computeMembraneElasticity(double youngModulus, double poissonRatio,
                                          MembraneLaw law);

/// The frame [e1 e2 n] of corners x (see the header). Returns false, leaving R unchanged, when
/// the corners are (nearly) collinear or coincide: area below 1e-12 times the squared longest
/// edge, or non-finite.
bool computeTriangleFrame(const TriangleVectors& x, Eigen::Matrix3d& R);

/// The constants of the triangle with rest corners `rest`, material D (computeMembraneElasticity),
/// thickness t (m) and rest scale s. Reports `degenerate` (outputs unspecified) for a rest triangle
/// whose corners are collinear or coincide (computeTriangleFrame).
ElementStatus computeTriangleConstants(const TriangleVectors& rest, const Eigen::Matrix3d& D,
                                       double thickness, double restScale,
                                       CorotationalTriangle& out);

/// The rotation of `method` at corners x: the rest frame (small), else the current frame;
/// `previous` when the current corners are collinear (no frame).
Eigen::Matrix3d computeTriangleRotation(TriangleMethod method, const CorotationalTriangle& c,
                                        const TriangleVectors& x, const Eigen::Matrix3d& previous);

/// The in-plane displacements u = P R^T (x_i - x0) - p_i, node-major (6).
Eigen::Matrix<double, 6, 1> computeTriangleDisplacement(const CorotationalTriangle& c,
                                                        const Eigen::Matrix3d& R,
                                                        const TriangleVectors& x);

/// The corner forces f_i = R P^T (-Ke u)_i at corners x with rotation R.
TriangleVectors computeTriangleForce(const CorotationalTriangle& c, const Eigen::Matrix3d& R,
                                     const TriangleVectors& x);

/// df = -T Ke T^T dx (the corotational product, dR/dx ignored).
TriangleVectors computeTriangleDForce(const CorotationalTriangle& c, const Eigen::Matrix3d& R,
                                      const TriangleVectors& dx);

/// K = T Ke T^T (9 x 9, symmetric positive semi-definite), so that df = -K dx.
Matrix9d computeTriangleStiffness(const CorotationalTriangle& c, const Eigen::Matrix3d& R);

/// E = 1/2 u^T Ke u at corners x with rotation R (J).
double computeTriangleEnergy(const CorotationalTriangle& c, const Eigen::Matrix3d& R,
                             const TriangleVectors& x);

}  // namespace stroma::fem
