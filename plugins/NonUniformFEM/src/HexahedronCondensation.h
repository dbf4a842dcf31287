// SPDX-License-Identifier: MIT
// Condensation of nested trilinear hexahedra (Nesme thesis, seed 001, ch. 4 sec. 3, "elements
// non uniformes"): a coarse hexahedron whose 8 children (each the octant at one of its corners)
// carry their own stiffness and mass gets
//
//   K_parent = sum_c L_c^T K_c L_c,        M_parent = sum_c L_c^T M_c L_c
//
// where L_c maps the parent's 8 corner displacements to the child's 8 corner displacements by
// the parent's trilinear interpolation: L_c(i, j) = N_j(xi_i), xi_i the reference position of
// the child's corner i in the parent (corner q's octant: xi_i = (s_q + s_i) / 2). For the
// 24 x 24 matrices L_c acts as L_c (x) I_3. Recursively, children are condensed from their own
// children, down to the finest level where each cell is a full trilinear hexahedron of its
// shape, weighted by its filled volume fraction (empty cells contribute nothing).
//
// Why it is exact for a full homogeneous parent (tested): the child's displacement field
// u_c = N(xi_c) L_c U is the parent's field restricted to the child, so u_c^T K_c u_c is the
// parent's strain energy over the child's volume, and the children's volumes tile the parent.
// The integrals of K_c (2 x 2 x 2 Gauss of a trilinear field on a parallelepiped) and M_c
// (3 x 3 x 3 Gauss) are exact for the parent's polynomial field, so the sum equals the parent's
// own Ke and M to round-off. For a non-parallelepiped parent the 2 x 2 x 2 rule is not exact
// and the condensed K is the (more accurate) integral on the children's Gauss points.
//
// Node order and reference corners: SolidMechanics/kernels/TrilinearHexahedron.h (SOFA's).
#pragma once

#include <functional>
#include <span>

#include "SolidMechanics/kernels/FemTypes.h"
#include "SolidMechanics/kernels/TrilinearHexahedron.h"
#include "topology/SparseGridLevels.h"

namespace stroma::fem {

/// L_c (8 x 8): row i = corner i of child `child` (the octant at parent corner `child`),
/// column j = parent corner j; each row sums to 1.
Matrix8d computeChildInterpolation(int child);

/// K_parent += (L (x) I_3)^T K_child (L (x) I_3).
void addCondensedStiffness(const Matrix24d& childStiffness, const Matrix8d& L,
                           Matrix24d& parentStiffness);

/// What a finest-level cell is made of: filled volume fraction in [0, 1] (0: contributes
/// nothing), Young's modulus (Pa, > 0 when the fraction is > 0) and density (kg/m^3, >= 0).
struct CellMaterial {
  double fraction = 1;
  double youngModulus = 1;
  double density = 1;
};

/// The condensed rest stiffness (24 x 24, N/m) and consistent mass (8 x 8, kg; the 24 x 24 mass
/// is M (x) I_3) of one simulated hexahedron.
struct CondensedHexahedron {
  Matrix24d stiffness = Matrix24d::Zero();
  Matrix8d mass = Matrix8d::Zero();
};

/// Condenses one cell of a sparse grid from its nested finer levels.
///
/// `levels`: the finer levels used, finest first (Topology::sparseGridFinerLevels(), possibly
/// only its last ones); the last level's parentsChildren index the simulated cells. With no
/// level the cell itself is the finest one. `material(c)` gives the material of cell c of the
/// finest level (levels[0], or the simulated grid when `levels` is empty).
/// `rest`: the simulated cell's rest corners (any trilinear shape: each finer cell's corners
/// are the trilinear interpolation of these, so a grid moved or rotated in the state keeps its
/// mechanics). Returns `degenerate` when a finest cell with material has a degenerate shape.
ElementStatus condenseHexahedron(const HexahedronVectors& rest, Index cell,
                                 std::span<const sparsegrid::FinerLevel> levels,
                                 const std::function<CellMaterial(Index)>& material,
                                 double poissonRatio, CondensedHexahedron& result);

}  // namespace stroma::fem
