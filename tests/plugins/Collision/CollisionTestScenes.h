// SPDX-License-Identifier: MIT
// Scenes of the collision tests, as XML text.
#pragma once

#include <random>
#include <sstream>
#include <string>

namespace stroma::test {

/// The pipeline of the root node: brute-force broad phase, BVH narrow phase, `intersection`
/// (an element with its attributes), penalty response.
inline std::string collisionPipeline(const std::string& intersection,
                                     const std::string& narrowPhase = "<BVHNarrowPhase/>") {
  return "<CollisionPipeline/><BruteForceBroadPhase/>" + narrowPhase + intersection +
         "<CollisionResponse/>";
}

/// A bumpy n x n sheet of points at height z over [0, 1]^2, heights perturbed by `bump`
/// (seeded), as positions and triangles attributes.
inline std::string sheetAttributes(int n, double z, double bump, unsigned seed, bool flip) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> u(-bump, bump);
  std::ostringstream positions, triangles;
  positions.precision(17);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      positions << double(i) / (n - 1) << ' ' << double(j) / (n - 1) << ' ' << z + u(random)
                << "  ";
  for (int j = 0; j + 1 < n; ++j)
    for (int i = 0; i + 1 < n; ++i) {
      const int a = j * n + i, b = a + 1, c = a + n, d = c + 1;
      if (flip)
        triangles << a << ' ' << c << ' ' << b << "  " << b << ' ' << c << ' ' << d << "  ";
      else
        triangles << a << ' ' << b << ' ' << c << "  " << b << ' ' << d << ' ' << c << "  ";
    }
  return "position=\"" + positions.str() + "\" triangles=\"" + triangles.str() + "\"";
}

/// A node holding a surface with point, line and triangle models (no solver: it does not move
/// unless the test moves it).
inline std::string surfaceNode(const std::string& name, const std::string& meshAttributes,
                               const std::string& modelAttributes = "") {
  return "<Node name=\"" + name + "\"><MeshTopology name=\"mesh\" " + meshAttributes +
         "/><MechanicalObject name=\"dofs\" position=\"@mesh.position\"/>"
         "<PointCollisionModel " +
         modelAttributes + "/><LineCollisionModel " + modelAttributes +
         "/><TriangleCollisionModel " + modelAttributes + "/></Node>";
}

}  // namespace stroma::test
