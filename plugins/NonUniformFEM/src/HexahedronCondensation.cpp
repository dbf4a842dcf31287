// SPDX-License-Identifier: MIT
#include "HexahedronCondensation.h"

#include <array>

#include "SolidMechanics/kernels/IsotropicMaterial.h"

namespace stroma::fem {

namespace {

/// L_c (x) I_3, for the 8 children, computed once.
const std::array<Matrix24d, 8>& expandedInterpolations() {
  static const std::array<Matrix24d, 8> table = [] {
    std::array<Matrix24d, 8> result;
    for (int q = 0; q < 8; ++q) {
      const Matrix8d L = computeChildInterpolation(q);
      result[q].setZero();
      for (int i = 0; i < 8; ++i)
        for (int j = 0; j < 8; ++j)
          for (int k = 0; k < 3; ++k) result[q](3 * i + k, 3 * j + k) = L(i, j);
    }
    return result;
  }();
  return table;
}

const std::array<Matrix8d, 8>& interpolations() {
  static const std::array<Matrix8d, 8> table = [] {
    std::array<Matrix8d, 8> result;
    for (int q = 0; q < 8; ++q) result[q] = computeChildInterpolation(q);
    return result;
  }();
  return table;
}

/// True when the trilinear map of X is affine (a parallelepiped): its bilinear and trilinear
/// coefficients vanish relative to its size. Then all the cells of one finer level are
/// translates of each other and share their unit stiffness and mass.
bool isParallelepiped(const HexahedronVectors& X) {
  Eigen::Matrix<double, 8, 4> h;
  for (int i = 0; i < 8; ++i) {
    const Eigen::Vector3d s = hexahedronReferenceCorner(i);
    h.row(i) << s.x() * s.y(), s.y() * s.z(), s.x() * s.z(), s.x() * s.y() * s.z();
  }
  const double size = (X.colwise() - X.col(0)).norm();
  return (X * h).norm() <= 1e-12 * size;
}

struct Condenser {
  std::span<const sparsegrid::FinerLevel> levels;
  const std::function<CellMaterial(Index)>& material;
  Matrix6d unitElasticity;  // C for E = 1
  bool shareFinestShape = false;
  bool haveFinestShape = false;
  Matrix24d unitStiffness = Matrix24d::Zero();  // of the finest shape, E = 1
  Matrix8d unitMass = Matrix8d::Zero();         // of the finest shape, rho = 1
  bool degenerate = false;

  // Adds the condensed matrices of `cell` of level `level` (0: the finest; levels.size(): the
  // simulated grid), whose rest corners are X, to `out`.
  void condense(std::size_t level, Index cell, const HexahedronVectors& X,
                CondensedHexahedron& out) {
    if (level == 0) {
      const CellMaterial m = material(cell);
      if (!(m.fraction > 0)) return;  // empty: contributes nothing
      if (!shareFinestShape || !haveFinestShape) {
        if (computeHexahedronStiffness(X, unitElasticity, unitStiffness) != ElementStatus::ok) {
          degenerate = true;
          return;
        }
        unitMass = computeHexahedronConsistentMass(X, 1.0);
        haveFinestShape = true;
      }
      out.stiffness += (m.fraction * m.youngModulus) * unitStiffness;
      out.mass += (m.fraction * m.density) * unitMass;
      return;
    }
    const std::array<Index, 8>& children = levels[level - 1].parentsChildren[cell];
    for (int q = 0; q < 8; ++q) {
      if (children[q] == kInvalidIndex) continue;
      const Matrix8d& L = interpolations()[q];
      CondensedHexahedron child;
      condense(level - 1, children[q], X * L.transpose(), child);
      const Matrix24d& Lx = expandedInterpolations()[q];
      out.stiffness.noalias() += Lx.transpose() * (child.stiffness * Lx);
      out.mass.noalias() += L.transpose() * (child.mass * L);
    }
  }
};

}  // namespace

Matrix8d computeChildInterpolation(int child) {
  const Eigen::Vector3d centre = 0.5 * hexahedronReferenceCorner(child);
  Matrix8d L;
  for (int i = 0; i < 8; ++i)
    L.row(i) =
        computeHexahedronShapeFunctions(centre + 0.5 * hexahedronReferenceCorner(i)).transpose();
  return L;
}

void addCondensedStiffness(const Matrix24d& childStiffness, const Matrix8d& L,
                           Matrix24d& parentStiffness) {
  Matrix24d Lx = Matrix24d::Zero();
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < 8; ++j)
      for (int k = 0; k < 3; ++k) Lx(3 * i + k, 3 * j + k) = L(i, j);
  parentStiffness.noalias() += Lx.transpose() * (childStiffness * Lx);
}

ElementStatus condenseHexahedron(const HexahedronVectors& rest, Index cell,
                                 std::span<const sparsegrid::FinerLevel> levels,
                                 const std::function<CellMaterial(Index)>& material,
                                 double poissonRatio, CondensedHexahedron& result) {
  Condenser condenser{levels, material,
                      computeElasticityMatrix(computeLameParameters(1.0, poissonRatio))};
  condenser.shareFinestShape = isParallelepiped(rest);
  result = CondensedHexahedron{};
  condenser.condense(levels.size(), cell, rest, result);
  // K and M are symmetric in exact arithmetic; remove the round-off asymmetry of the products.
  result.stiffness = 0.5 * (result.stiffness + result.stiffness.transpose()).eval();
  result.mass = 0.5 * (result.mass + result.mass.transpose()).eval();
  return condenser.degenerate ? ElementStatus::degenerate : ElementStatus::ok;
}

}  // namespace stroma::fem
