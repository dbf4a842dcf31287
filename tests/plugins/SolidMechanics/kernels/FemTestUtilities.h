// SPDX-License-Identifier: MIT
// Shapes, random motions and finite differences shared by the FEM kernel tests.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <random>

#include "SolidMechanics/kernels/FemTypes.h"
#include "SolidMechanics/kernels/IsotropicMaterial.h"

namespace stroma::fem::test {

/// Elasticity matrix of E = 1000 Pa, nu = 0.3 unless told otherwise.
inline Matrix6d testElasticity(double youngModulus = 1000, double poissonRatio = 0.3) {
  return computeElasticityMatrix(computeLameParameters(youngModulus, poissonRatio));
}

/// A uniformly distributed rotation (normalized Gaussian quaternion).
inline Eigen::Matrix3d randomRotation(std::mt19937& rng) {
  std::normal_distribution<double> gauss;
  Eigen::Quaterniond q(gauss(rng), gauss(rng), gauss(rng), gauss(rng));
  return q.normalized().toRotationMatrix();
}

/// Nodal vectors with coordinates uniform in [-scale, scale].
template <int N>
NodalVectors<N> randomVectors(std::mt19937& rng, double scale) {
  std::uniform_real_distribution<double> uniform(-scale, scale);
  NodalVectors<N> v;
  for (int i = 0; i < v.size(); ++i) v.data()[i] = uniform(rng);
  return v;
}

/// An irregular, right-handed tetrahedron of size about 1 m.
inline TetrahedronVectors irregularTetrahedron() {
  TetrahedronVectors X;
  X << 0.0, 1.0, 0.2, 0.1,  //
      0.0, 0.1, 0.9, 0.2,   //
      0.0, 0.0, 0.1, 1.1;
  return X;
}

/// The unit cube [0, 1]^3 in SOFA's hexahedron node order.
inline HexahedronVectors unitCube() {
  HexahedronVectors X;
  X << 0, 1, 1, 0, 0, 1, 1, 0,  //
      0, 0, 1, 1, 0, 0, 1, 1,   //
      0, 0, 0, 0, 1, 1, 1, 1;
  return X;
}

/// The unit cube with each corner moved by up to 0.15 m (a non-parallelepiped hexahedron).
inline HexahedronVectors distortedHexahedron() {
  HexahedronVectors offsets;
  offsets << 0.05, -0.1, 0.12, 0.0, -0.08, 0.1, 0.15, -0.05,  //
      -0.02, 0.07, -0.1, 0.1, 0.04, -0.06, 0.08, 0.02,        //
      0.1, 0.0, -0.05, 0.06, -0.1, 0.05, 0.12, -0.07;
  return unitCube() + offsets;
}

/// A deformed state of the rest shape X: a random rotation Q and translation, a homogeneous
/// stretch of size `strain` and node noise of size `noise` (relative to the size of X).
template <int N>
NodalVectors<N> randomDeformedState(std::mt19937& rng, const NodalVectors<N>& X, double strain,
                                    double noise) {
  const Eigen::Matrix3d A = Eigen::Matrix3d::Identity() + randomVectors<3>(rng, strain);
  const Eigen::Vector3d t = randomVectors<1>(rng, 1.0);
  const NodalVectors<N> deformed = A * X + randomVectors<N>(rng, noise);
  return (randomRotation(rng) * deformed).colwise() + t;
}

/// Central-difference gradient of a scalar function of nodal positions.
template <int N, class Function>
NodalVectors<N> finiteDifferenceGradient(Function&& energy, const NodalVectors<N>& x, double h) {
  NodalVectors<N> gradient;
  for (int k = 0; k < x.size(); ++k) {
    NodalVectors<N> plus = x, minus = x;
    plus.data()[k] += h;
    minus.data()[k] -= h;
    gradient.data()[k] = (energy(plus) - energy(minus)) / (2 * h);
  }
  return gradient;
}

/// Central-difference Jacobian d(force)/dx (3N x 3N) of a nodal-vector function.
template <int N, class Function>
ElementMatrix<N> finiteDifferenceJacobian(Function&& force, const NodalVectors<N>& x, double h) {
  ElementMatrix<N> jacobian;
  for (int k = 0; k < x.size(); ++k) {
    NodalVectors<N> plus = x, minus = x;
    plus.data()[k] += h;
    minus.data()[k] -= h;
    const NodalVectors<N> difference = (force(plus) - force(minus)) / (2 * h);
    jacobian.col(k) = asElementVector<N>(difference);
  }
  return jacobian;
}

}  // namespace stroma::fem::test
