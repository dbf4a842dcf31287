// SPDX-License-Identifier: MIT
// The incompressibility penalty of Picinbono, Delingette, Ayache (seed 004, section 3.2): on
// each vertex p of a tetrahedron, a force along the normal of the face opposite p, whose norm
// grows as the square of the relative volume variation s = (V - V0) / V0 and whose sense
// restores the volume:
//
//   F_p = -gamma sign(s) s^2 dV/dx_p,    dV/dx_p = (A_p / 3) n_p,
//
// n_p the unit normal of the face opposite p (area A_p) pointing towards p. The paper's
// unit normal is weighted here by A_p / 3 (the same for the four vertices of a regular
// tetrahedron), which makes F the gradient of an energy:
//
//   W = gamma |V0| |s|^3 / 3,  F = -dW/dx,
//   d2W/dx2 = gamma (2 |s| / |V0|) dV/dx dV/dx^T + gamma sign(V0) s |s| d2V/dx2,
//
// so that implicit solvers get a symmetric tangent. gamma is a pressure (Pa): the pressure
// that pushes the faces back is gamma s |s|. The penalty and its tangent vanish at s = 0.
#pragma once

#include "SolidMechanics/kernels/FemTypes.h"

namespace stroma::tensormass {

/// dV/dx_p for each vertex p (column p, m^2) of a tetrahedron at positions x (column p).
fem::TetrahedronVectors computeVolumeGradients(const fem::TetrahedronVectors& x);

/// The energy W (J) at positions x of a tetrahedron of signed rest volume restVolume != 0.
double computeVolumePenaltyEnergy(const fem::TetrahedronVectors& x, double restVolume,
                                  double gamma);

/// The forces F_p (N, column p).
fem::TetrahedronVectors computeVolumePenaltyForce(const fem::TetrahedronVectors& x,
                                                  double restVolume, double gamma);

/// d2W/dx2 times dx (column p = the change of dW/dx_p).
fem::TetrahedronVectors computeVolumePenaltyHessianProduct(const fem::TetrahedronVectors& x,
                                                           double restVolume, double gamma,
                                                           const fem::TetrahedronVectors& dx);

/// d2W/dx2 (12 x 12, node-major).
fem::Matrix12d computeVolumePenaltyHessian(const fem::TetrahedronVectors& x, double restVolume,
                                           double gamma);

}  // namespace stroma::tensormass
