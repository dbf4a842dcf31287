// SPDX-License-Identifier: MIT
// Linear bending of a pair of triangles sharing an edge (Volino and Magnenat-Thalmann, "Simple
// linear bending stiffness in particle systems", SCA 2006), the model of SOFA's
// FastTriangularBendingSprings. Knows nothing of components.
//
// For the hinge (a, b, c, d) of TriangleHinge (edge a-c, b and d opposite it), let H_b, H_d be
// the distances of b and d from the edge's line and s_b, s_d the parameters of their feet along
// a -> c, all at the rest positions. The bending vector
//   R = sum_i alpha_i x_i = (x_b - foot_b) / H_b + (x_d - foot_d) / H_d,
//   alpha_b = 1 / H_b,  alpha_d = 1 / H_d,
//   alpha_a = -(1 - s_b) / H_b - (1 - s_d) / H_d,  alpha_c = -s_b / H_b - s_d / H_d,
// is the sum of the two triangles' unit normals to the edge in their planes (their rest
// directions carried linearly): zero for the flat pair, of length about the fold angle for small
// folds. With the material's bending stiffness B and the edge length |e|,
//   E = lambda |R|^2 / 2,   lambda = (2/3) B |e| / (H_b + H_d),
//   f_i = -lambda alpha_i R,   df_i/dx_j = -lambda alpha_i alpha_j I   (constant, symmetric).
// The alphas are constant, so the force is linear in the positions and the stiffness exact.
// sum alpha_i = 0 and sum alpha_i x_i x f_i = -lambda R x R = 0: no net force or moment; a rigid
// motion of a flat pair keeps R = 0. The flat pair is the rest shape of every hinge: a mesh that
// is curved at rest is pulled flat (SOFA does the same; its forces, measured with runSofa on
// flat, folded and skewed pairs, match these to the 6 digits it prints).
#pragma once

#include <array>

#include "SpringPairs.h"
#include "core/Types.h"

namespace stroma {

struct LinearBendingHinge {
  std::array<Index, 4> vertex{};  ///< a, b, c, d
  std::array<double, 4> alpha{};  ///< weight of each vertex in R (1/m)
  double lambda = 0;              ///< (2/3) B |e| / (H_b + H_d) (N m)
};

/// The hinge's constants from its rest positions; false when the edge or a height is shorter
/// than `minDistance` (a degenerate triangle: no direction to bend about).
bool makeLinearBendingHinge(const TriangleHinge& hinge, const std::array<Vec3d, 4>& rest,
                            double bendingStiffness, double minDistance, LinearBendingHinge& out);

/// R = sum alpha_i x_i.
inline Vec3d bendingVector(const LinearBendingHinge& h, const std::vector<Vec3d>& x) {
  Vec3d R = Vec3d::Zero();
  for (int i = 0; i < 4; ++i) R += h.alpha[i] * x[h.vertex[i]];
  return R;
}

}  // namespace stroma
