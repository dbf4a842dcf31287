// SPDX-License-Identifier: MIT
// The deviatoric / volumetric split of isotropic linear elasticity, and the element pieces of
// the locking-free options built on it (issue 7, item 6).
//
// Near incompressibility (nu -> 1/2) makes the bulk modulus kappa = lambda + 2 mu / 3 grow
// without bound while mu stays finite. An element that asks its volumetric strain tr(eps) to
// vanish at every integration point has more constraints than degrees of freedom, and its
// displacements shrink with 1 - 2 nu: volumetric locking (Hughes, "The finite element method",
// 1987, ch. 4; Nesme thesis, seed 001, ch. 2 sec. 2.5 on nu close to 1/2). The cure used here
// counts the volumetric constraint less often: the split
//
//   C = C_dev + kappa m m^T,   m = (1, 1, 1, 0, 0, 0),
//   C_dev = mu diag(2, 2, 2, 1, 1, 1) - (2 mu / 3) m m^T              (Pa, Voigt, engineering
//                                                                     shear as FemTypes.h)
//
// keeps the deviatoric energy 1/2 eps^T C_dev eps at the element's own integration points,
// and integrates the volumetric energy 1/2 kappa (tr eps)^2 on fewer points:
// - hexahedra, mean dilatation (Nagtegaal, Parks and Rice 1974; Hughes 1980, "Generalization
//   of selective integration procedures to anisotropic and nonlinear media", IJNME 15, the
//   B-bar form): one volumetric strain per element, the volume average of tr eps,
//     theta_e = bbar . u,   bbar_i = (1/V) integral grad N_i dV,
//     Ke = integral B^T C_dev B dV + kappa V bbar bbar^T.
//   On a parallelepiped (constant det J) this is the one-point (centre) rule of selective
//   reduced integration; on any shape it keeps the patch test (a linear field has
//   theta_e = tr eps exactly). The deviatoric part keeps 2 x 2 x 2 Gauss points: no
//   hourglass mode.
// - tetrahedra, averaged nodal pressure (Bonet and Burton 1998, "A simple average nodal
//   pressure tetrahedral element for incompressible and nearly incompressible dynamic explicit
//   applications", Commun. Numer. Meth. Engng 14): one volumetric strain per vertex, the
//   volume-weighted mean of the divergences of the tetrahedra around it. The elements keep
//   C_dev only; the mesh-level part is src/AveragedNodalPressure.h.
#pragma once

#include "SolidMechanics/kernels/FemTypes.h"
#include "SolidMechanics/kernels/IsotropicMaterial.h"

namespace stroma::fem {

/// How the volumetric part 1/2 kappa (tr eps)^2 of the energy enters an element's stiffness Ke.
enum class VolumetricStiffness {
  full,            ///< C at the element's integration points (the usual element)
  meanDilatation,  ///< C_dev at its points plus kappa V bbar bbar^T (hexahedra, B-bar)
  deviatoric,      ///< C_dev only: the volumetric part is added by a mesh-level term
};

/// Bulk modulus kappa = lambda + 2 mu / 3 (Pa).
double computeBulkModulus(const LameParameters& lame);

/// The deviatoric elasticity matrix C_dev = C - kappa m m^T (6 x 6, Pa), see above. Its
/// kernel is the pure dilatation m: eps = t m gives no deviatoric stress.
Matrix6d computeDeviatoricElasticityMatrix(const LameParameters& lame);

/// The volume-averaged gradients bbar_i = (1/V) integral grad N_i dV (column i, 1/m) of a
/// trilinear hexahedron (TrilinearHexahedron.h, 2 x 2 x 2 Gauss, |det J|), and its volume
/// V = integral |det J| (m^3). Reports `degenerate` as computeHexahedronGradients does.
ElementStatus computeHexahedronMeanGradients(const HexahedronVectors& rest,
                                             HexahedronVectors& meanGradients, double& volume);

/// Ke += kappa V bbar bbar^T (N/m): the mean-dilatation volumetric stiffness of an element of
/// volume V (m^3) whose volume-averaged gradients are bbar (column i, 1/m).
template <int N>
void addMeanDilatationStiffness(const NodalVectors<N>& meanGradients, double volume,
                                double bulkModulus, ElementMatrix<N>& Ke) {
  const auto b = asElementVector<N>(meanGradients);
  Ke.noalias() += (bulkModulus * volume) * b * b.transpose();
}

/// The divergence tr(eps) of the corotated displacement of a tetrahedron (dimensionless):
///   d = sum_i g_i . u_i,   u_i = R^T (v_i - v_0) - (X_i - X_0)
/// with g_i = grad N_i at rest (column i, 1/m). Pass X = 0 for a position differential dv (then
/// d is the linear change of the divergence, dR/dx ignored).
inline double computeCorotatedDivergence(const TetrahedronVectors& gradients,
                                         const Eigen::Matrix3d& R, const TetrahedronVectors& v,
                                         const TetrahedronVectors& X) {
  double d = 0;
  for (int i = 1; i < 4; ++i)
    d += gradients.col(i).dot(R.transpose() * (v.col(i) - v.col(0)) - (X.col(i) - X.col(0)));
  return d;
}

}  // namespace stroma::fem
