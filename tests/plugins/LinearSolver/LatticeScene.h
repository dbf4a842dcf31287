// SPDX-License-Identifier: MIT
// A cube lattice of points joined by springs (edges and face diagonals of every cell), held on
// its x = 0 face, for the linear solver tests: a sparse symmetric positive definite system with
// the structure of a 3D mesh.
#pragma once

#include <cmath>
#include <sstream>
#include <string>

namespace stroma::test {

/// n^3 points 1 m apart; positions moved from rest by a deterministic pseudo-random offset of
/// up to `perturbation` m (so that the springs are stretched and K has geometric terms).
/// `solvers` goes into the body node (ODE and linear solvers).
inline std::string latticeScene(int n, const std::string& solvers, double perturbation = 0.1,
                                double dt = 0.01, double stiffness = 1000) {
  auto index = [n](int i, int j, int k) { return (i * n + j) * n + k; };
  std::ostringstream rest, position, springs, fixed;
  position.precision(17);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) {
        const int p = index(i, j, k);
        rest << i << ' ' << j << ' ' << k << "  ";
        auto offset = [&](int axis) {
          return perturbation * std::sin(12.9898 * p + 78.233 * axis);
        };
        position << i + offset(0) << ' ' << j + offset(1) << ' ' << k + offset(2) << "  ";
        if (i == 0) fixed << p << ' ';
        // Edges towards +x, +y, +z and both diagonals of the three faces at this corner.
        const int di[] = {1, 0, 0, 1, 1, 1, 1, 0, 0};
        const int dj[] = {0, 1, 0, 1, -1, 0, 0, 1, 1};
        const int dk[] = {0, 0, 1, 0, 0, 1, -1, 1, -1};
        for (int e = 0; e < 9; ++e) {
          const int a = i + di[e], b = j + dj[e], c = k + dk[e];
          if (a < 0 || b < 0 || c < 0 || a >= n || b >= n || c >= n) continue;
          springs << p << ' ' << index(a, b, c) << "  ";
        }
      }
  std::ostringstream xml;
  xml << "<Node name=\"root\" dt=\"" << dt << "\" gravity=\"0 -9.81 0\">\n"
      << "  <Node name=\"Body\">\n    " << solvers << "\n"
      << "    <MechanicalObject name=\"dofs\" position=\"" << position.str()
      << "\" rest_position=\"" << rest.str() << "\"/>\n"
      << "    <UniformMass name=\"mass\" totalMass=\"" << n * n * n << "\"/>\n"
      << "    <TestSpringForceField name=\"springs\" stiffness=\"" << stiffness << "\" springs=\""
      << springs.str() << "\"/>\n"
      << "    <FixedProjectiveConstraint name=\"fixed\" indices=\"" << fixed.str() << "\"/>\n"
      << "  </Node>\n</Node>\n";
  return xml.str();
}

}  // namespace stroma::test
