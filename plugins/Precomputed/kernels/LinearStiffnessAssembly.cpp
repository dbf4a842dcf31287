// SPDX-License-Identifier: MIT
#include "Precomputed/kernels/LinearStiffnessAssembly.h"

#include "SolidMechanics/kernels/IsotropicMaterial.h"
#include "SolidMechanics/kernels/LinearTetrahedron.h"

namespace stroma::precomputed {

bool assembleLinearStiffness(const std::vector<Eigen::Vector3d>& points,
                             const std::vector<TetrahedronNodes>& tetrahedra, double youngModulus,
                             double poissonRatio, Eigen::SparseMatrix<double>& K,
                             std::string& error) {
  if (!fem::isValidIsotropicMaterial(youngModulus, poissonRatio)) {
    error = "material E = " + std::to_string(youngModulus) +
            ", nu = " + std::to_string(poissonRatio) +
            " is out of range (expected E > 0, -1 < nu < 0.5)";
    return false;
  }
  const fem::Matrix6d C =
      fem::computeElasticityMatrix(fem::computeLameParameters(youngModulus, poissonRatio));
  const auto pointCount = points.size();
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(tetrahedra.size() * 144);
  for (size_t e = 0; e < tetrahedra.size(); ++e) {
    const TetrahedronNodes& tet = tetrahedra[e];
    fem::TetrahedronVectors rest;
    for (int i = 0; i < 4; ++i) {
      if (tet[size_t(i)] >= pointCount) {
        error = "tetrahedron " + std::to_string(e) + " names point " +
                std::to_string(tet[size_t(i)]) + ", out of range [0, " +
                std::to_string(pointCount) + ")";
        return false;
      }
      rest.col(i) = points[tet[size_t(i)]];
    }
    fem::TetrahedronShape shape;
    if (fem::computeTetrahedronShape(rest, shape) != fem::ElementStatus::ok) {
      error = "tetrahedron " + std::to_string(e) +
              " is degenerate (zero volume or non-finite "
              "coordinates)";
      return false;
    }
    const fem::Matrix12d Ke = fem::computeTetrahedronStiffness(shape, C);
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b)
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j)
            triplets.emplace_back(int(3 * tet[size_t(a)]) + i, int(3 * tet[size_t(b)]) + j,
                                  Ke(3 * a + i, 3 * b + j));
  }
  const auto dofCount = Eigen::Index(3 * pointCount);
  K.resize(dofCount, dofCount);
  K.setFromTriplets(triplets.begin(), triplets.end());
  return true;
}

}  // namespace stroma::precomputed
