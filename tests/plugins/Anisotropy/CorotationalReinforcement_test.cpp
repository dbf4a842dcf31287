// SPDX-License-Identifier: MIT
// The corotational reinforcement of one tetrahedron (CorotationalReinforcement.h): the force is
// minus the gradient of the energy and the Hessian the derivative of the gradient (central
// differences), it is the linear element at rest and for small displacements, and rotating
// the element rotates its forces and leaves its energy.
#include "Anisotropy/kernels/CorotationalReinforcement.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <random>

#include "Anisotropy/kernels/TransverselyIsotropicMaterial.h"

namespace stroma::anisotropy {
namespace {

using fem::Matrix12d;
using fem::TetrahedronVectors;

struct Element {
  fem::TetrahedronShape shape;
  TetrahedronVectors rest;
  fem::Matrix6d Cr;
};

Element makeElement() {
  Element e;
  e.rest << 0, 0.1, 0.01, 0.02, 0.01, 0.0, 0.12, 0.03, -0.01, 0.02, 0.01, 0.09;
  EXPECT_EQ(fem::computeTetrahedronShape(e.rest, e.shape), fem::ElementStatus::ok);
  EXPECT_GT(e.shape.volume, 0);
  const SpencerParameters p = computeSpencerParameters({.youngModulusL = 30e3,
                                                        .youngModulusT = 5e3,
                                                        .poissonRatioLT = 0.35,
                                                        .poissonRatioTT = 0.45,
                                                        .shearModulusLT = 4e3});
  e.Cr = computeReinforcementElasticity(Eigen::Vector3d(1, 0.5, -0.3).normalized(), p.alpha, p.beta,
                                        p.muL, p.muT);
  return e;
}

/// The rest shape rotated by 70 degrees and strained by up to `strain`, reproducibly.
TetrahedronVectors deformed(const Element& e, double strain, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> uniform(-1, 1);
  TetrahedronVectors u;
  for (int i = 0; i < 12; ++i) u(i) = strain * 0.1 * uniform(rng);
  const Eigen::Matrix3d Q =
      Eigen::AngleAxisd(1.2, Eigen::Vector3d(0.3, 1, 0.2).normalized()).toRotationMatrix();
  return Q * (e.rest + u);
}

double energyAt(const Element& e, const TetrahedronVectors& x) {
  double energy = 0;
  TetrahedronVectors f;
  computeCorotationalReinforcement(e.shape, e.Cr, x, energy, f, nullptr);
  return energy;
}

TEST(CorotationalReinforcement, ForceIsMinusTheGradientAndTheHessianItsDerivative) {
  const Element e = makeElement();
  const double h = 1e-7;  // m, for coordinates of 0.1 m
  for (unsigned seed : {1u, 2u, 3u}) {
    const TetrahedronVectors x = deformed(e, 0.2, seed);
    double energy = 0;
    TetrahedronVectors f;
    Matrix12d H;
    ASSERT_EQ(computeCorotationalReinforcement(e.shape, e.Cr, x, energy, f, &H),
              CorotationalStatus::ok);
    TetrahedronVectors gradient;
    Matrix12d differences;
    for (int d = 0; d < 12; ++d) {
      TetrahedronVectors plus = x, minus = x;
      plus(d) += h;
      minus(d) -= h;
      gradient(d) = (energyAt(e, plus) - energyAt(e, minus)) / (2 * h);
      double unused = 0;
      TetrahedronVectors fPlus, fMinus;
      computeCorotationalReinforcement(e.shape, e.Cr, plus, unused, fPlus, nullptr);
      computeCorotationalReinforcement(e.shape, e.Cr, minus, unused, fMinus, nullptr);
      const TetrahedronVectors column = -(fPlus - fMinus) / (2 * h);
      differences.col(d) = Eigen::Map<const fem::ElementVector<4>>(column.data());
    }
    EXPECT_LT((f + gradient).norm(), 1e-6 * f.norm()) << "seed " << seed;
    EXPECT_LT((H - differences).norm(), 1e-6 * H.norm()) << "seed " << seed;
    // Not the classical corotational force R sigma: the rotation's derivative matters here.
  }
}

TEST(CorotationalReinforcement, IsTheLinearElementAtRestAndTurnsWithTheElement) {
  const Element e = makeElement();
  double energy = 1;
  TetrahedronVectors f;
  Matrix12d H;
  computeCorotationalReinforcement(e.shape, e.Cr, e.rest, energy, f, &H);
  const Matrix12d Ke = fem::computeTetrahedronStiffness(e.shape, e.Cr);
  EXPECT_LT((H - Ke).norm(), 1e-12 * Ke.norm());
  EXPECT_LT(f.norm(), 1e-12 * Ke.norm() * 0.1);
  EXPECT_LT(energy, 1e-20);
  // A rotation Q of the deformed element: the same energy, forces Q f.
  const TetrahedronVectors x = deformed(e, 0.1, 7);
  double rotatedEnergy = 0;
  TetrahedronVectors rotatedForce;
  computeCorotationalReinforcement(e.shape, e.Cr, x, energy, f, nullptr);
  const Eigen::Matrix3d Q = Eigen::AngleAxisd(2.5, Eigen::Vector3d::UnitY()).toRotationMatrix();
  computeCorotationalReinforcement(e.shape, e.Cr, Q * x, rotatedEnergy, rotatedForce, nullptr);
  EXPECT_NEAR(rotatedEnergy, energy, 1e-12 * energy);
  EXPECT_LT((rotatedForce - Q * f).norm(), 1e-12 * f.norm());
}

}  // namespace
}  // namespace stroma::anisotropy
