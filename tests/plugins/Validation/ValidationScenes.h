// SPDX-License-Identifier: MIT
// Inline scenes shared by the tests of ReferenceComparison: a body on a mesh of
// FemTestScenes.h, the REFERENCES.md cantilever solved statically, and the comparison's
// outputs.
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include "plugins/SolidMechanics/FemTestScenes.h"

namespace stroma::test {

/// A node "body" with a MeshTopology of `elements` ("tetrahedra" or "hexahedra"), a
/// MechanicalObject "dofs" at `positions` resting at the mesh's points, then `components`.
inline std::string bodyScene(const FemMesh& mesh, const std::string& elements,
                             const std::vector<Vec3d>& positions, const std::string& components) {
  const std::string list =
      elements == "hexahedra" ? elementsText(mesh.hexahedra) : elementsText(mesh.tetrahedra);
  return "<Node name=\"root\" gravity=\"0 0 0\" dt=\"1\">\n<Node name=\"body\">\n"
         "<MeshTopology name=\"mesh\" " +
         elements + "=\"" + list +
         "\"/>\n"
         "<MechanicalObject name=\"dofs\" position=\"" +
         pointsText(positions) + "\" rest_position=\"" + pointsText(mesh.points) + "\"/>\n" +
         components + "\n</Node>\n</Node>\n";
}

/// The cantilever of REFERENCES.md ([0, 1] x [0, 0.1] x [0, 0.1] m, E = 1e8 Pa, nu = 0.3,
/// 100 N along -z spread on the face x = 1, the face x = 0 fixed) in (10 k, k, k) cells of
/// linear (small) `elements`, a StaticSolver with SparseLDL, then `compare` (XML).
inline std::string cantileverScene(const std::string& elements, int k, const std::string& compare) {
  const FemMesh mesh = makeBoxMesh(Vec3d(1, 0.1, 0.1), Vec3i(10 * k, k, k));
  std::string clamped, tip;
  for (unsigned i = 0; i < mesh.points.size(); ++i) {
    if (mesh.points[i].x() < 1e-12) clamped += std::to_string(i) + " ";
    if (mesh.points[i].x() > 1 - 1e-12) tip += std::to_string(i) + " ";
  }
  const std::string forceField =
      elements == "hexahedra" ? "HexahedronFEMForceField" : "TetrahedronFEMForceField";
  return bodyScene(mesh, elements, mesh.points,
                   "<StaticSolver/><SparseLDLSolver/><" + forceField +
                       " youngModulus=\"1e8\" poissonRatio=\"0.3\" method=\"small\"/>"
                       "<FixedProjectiveConstraint indices=\"" +
                       clamped +
                       "\"/>"
                       "<ConstantForceField indices=\"" +
                       tip + "\" totalForce=\"0 0 -100\"/>" + compare);
}

/// Output `field` of the component /body/compare, as a number (NaN when absent).
inline double comparisonOutput(Scene& scene, const std::string& field) {
  Base* c = objectAt<Base>(scene, "/body/compare");
  return c && c->findData(field) ? std::stod(c->findData(field)->valueText()) : NAN;
}

}  // namespace stroma::test
