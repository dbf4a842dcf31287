// SPDX-License-Identifier: MIT
// Properties every corotational element must have, for tetrahedra and hexahedra and each
// rotation method: rigid modes, rigid-motion invariance, force = -grad energy (where exact),
// stiffness = force Jacobian at rest, and recovery from inversion.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <random>

#include "FemTestUtilities.h"
#include "SolidMechanics/kernels/CorotationalHexahedron.h"
#include "SolidMechanics/kernels/CorotationalTetrahedron.h"
#include "SolidMechanics/kernels/IsotropicMaterial.h"
#include "SolidMechanics/kernels/LinearTetrahedron.h"
#include "SolidMechanics/kernels/TrilinearHexahedron.h"

namespace stroma::fem {
namespace {

constexpr RotationMethod kAllMethods[] = {RotationMethod::small, RotationMethod::large,
                                          RotationMethod::polar, RotationMethod::svd};
constexpr RotationMethod kRotatingMethods[] = {RotationMethod::large, RotationMethod::polar,
                                               RotationMethod::svd};

struct TetrahedronCase {
  using Element = CorotationalTetrahedron;
  static TetrahedronVectors rest() { return test::irregularTetrahedron(); }
  static ElementStatus build(const TetrahedronVectors& X, const Matrix6d& C, Element& e) {
    return computeCorotationalTetrahedron(X, C, e);
  }
  static double volume(const TetrahedronVectors& x) { return computeTetrahedronVolume(x); }
  /// Whether f = -dE/dx exactly (see CorotationalElement.h).
  static bool isConservative(RotationMethod m) { return m != RotationMethod::large; }
};

struct HexahedronCase {
  using Element = CorotationalHexahedron;
  static HexahedronVectors rest() { return test::distortedHexahedron(); }
  static ElementStatus build(const HexahedronVectors& X, const Matrix6d& C, Element& e) {
    return computeCorotationalHexahedron(X, C, e);
  }
  static double volume(const HexahedronVectors& x) { return computeHexahedronVolume(x); }
  static bool isConservative(RotationMethod m) { return m == RotationMethod::small; }
};

template <class Case>
class CorotationalElementTest : public ::testing::Test {
 protected:
  using Element = typename Case::Element;
  static constexpr int N = Element::nodeCount;
  using Vectors = NodalVectors<N>;

  void SetUp() override { ASSERT_EQ(Case::build(Case::rest(), C, element), ElementStatus::ok); }

  double energy(RotationMethod m, const Vectors& x) const {
    return computeEnergy(element, computeRotation(m, element, x), x);
  }
  Vectors force(RotationMethod m, const Vectors& x) const {
    return computeForce(element, computeRotation(m, element, x), x);
  }
  /// |f + grad E| / |f| with grad E by central differences.
  double gradientMismatch(RotationMethod m, const Vectors& x) const {
    const Vectors gradient =
        test::finiteDifferenceGradient<N>([&](const Vectors& y) { return energy(m, y); }, x, 1e-6);
    const Vectors f = force(m, x);
    return (f + gradient).norm() / f.norm();
  }

  Matrix6d C = test::testElasticity(1000, 0.3);
  Element element;
  std::mt19937 rng{2024};
};

using ElementCases = ::testing::Types<TetrahedronCase, HexahedronCase>;
TYPED_TEST_SUITE(CorotationalElementTest, ElementCases);

TYPED_TEST(CorotationalElementTest, StiffnessIsSymmetricPositiveWithSixRigidModes) {
  const auto& Ke = this->element.stiffness;
  EXPECT_EQ(Ke, Ke.transpose());
  using Solver = Eigen::SelfAdjointEigenSolver<std::decay_t<decltype(Ke)>>;
  const auto eigenvalues = Solver(Ke).eigenvalues();  // increasing
  const double largest = eigenvalues.maxCoeff();
  for (int k = 0; k < 6; ++k) EXPECT_LT(std::abs(eigenvalues[k]), 1e-12 * largest) << k;
  EXPECT_GT(eigenvalues[6], 1e-3 * largest);
  // The zero modes are the translations and infinitesimal rotations of the rest shape.
  for (int a = 0; a < 3; ++a) {
    const Eigen::Vector3d axis = Eigen::Vector3d::Unit(a);
    typename TestFixture::Vectors translation, rotation;
    translation.colwise() = axis;
    for (int i = 0; i < TestFixture::N; ++i)
      rotation.col(i) = axis.cross(Eigen::Vector3d(this->element.restPositions.col(i)));
    EXPECT_LT((Ke * asElementVector<TestFixture::N>(translation)).norm(), 1e-10 * largest);
    EXPECT_LT((Ke * asElementVector<TestFixture::N>(rotation)).norm(), 1e-10 * largest);
  }
}

TYPED_TEST(CorotationalElementTest, RigidMotionGivesNoForceAndNoEnergy) {
  for (RotationMethod m : kRotatingMethods) {
    const Eigen::Matrix3d Q = test::randomRotation(this->rng);
    const typename TestFixture::Vectors x =
        (Q * this->element.restPositions).colwise() + Eigen::Vector3d(3, -1, 2);
    EXPECT_TRUE(computeRotation(m, this->element, x).isApprox(Q, 1e-12)) << rotationMethodName(m);
    EXPECT_LT(this->force(m, x).norm(), 1e-10) << rotationMethodName(m);
    EXPECT_LT(std::abs(this->energy(m, x)), 1e-20) << rotationMethodName(m);
  }
  const typename TestFixture::Vectors translated =
      this->element.restPositions.colwise() + Eigen::Vector3d(3, -1, 2);
  EXPECT_LT(this->force(RotationMethod::small, translated).norm(), 1e-9);
}

TYPED_TEST(CorotationalElementTest, RotatingDeformedElementRotatesForceKeepsEnergy) {
  for (RotationMethod m : kRotatingMethods) {
    for (int trial = 0; trial < 5; ++trial) {
      const auto x = test::randomDeformedState<TestFixture::N>(
          this->rng, this->element.restPositions, 0.2, 0.1);
      const Eigen::Matrix3d Q = test::randomRotation(this->rng);
      const typename TestFixture::Vectors moved = (Q * x).colwise() + Eigen::Vector3d(1, 2, 3);
      const auto f = this->force(m, x);
      EXPECT_TRUE(this->force(m, moved).isApprox(Q * f, 1e-10)) << rotationMethodName(m);
      EXPECT_NEAR(this->energy(m, moved), this->energy(m, x), 1e-10 * this->energy(m, x))
          << rotationMethodName(m);
    }
  }
}

TYPED_TEST(CorotationalElementTest, ForceIsMinusEnergyGradient) {
  for (RotationMethod m : kAllMethods) {
    if (!TypeParam::isConservative(m)) continue;
    for (int trial = 0; trial < 5; ++trial) {
      const auto x = test::randomDeformedState<TestFixture::N>(
          this->rng, this->element.restPositions, 0.3, 0.1);
      // For small the identity holds for any state, rotated or not.
      EXPECT_LT(this->gradientMismatch(m, x), 1e-6) << rotationMethodName(m);
    }
  }
}

TYPED_TEST(CorotationalElementTest, NonConservativeForceIsGradientToFirstOrder) {
  // Where f != -grad E, the difference is the neglected dR/dx term, quadratic in the strain:
  // the relative mismatch shrinks linearly with the deformation.
  for (RotationMethod m : kRotatingMethods) {
    if (TypeParam::isConservative(m)) continue;
    double mismatch[2] = {0, 0};
    const double sizes[2] = {1e-2, 1e-3};
    for (int trial = 0; trial < 5; ++trial) {
      const std::mt19937 start = this->rng;
      for (int k = 0; k < 2; ++k) {
        this->rng = start;  // the same random shape, scaled
        const auto x = test::randomDeformedState<TestFixture::N>(
            this->rng, this->element.restPositions, sizes[k], sizes[k]);
        mismatch[k] += this->gradientMismatch(m, x) / 5;
      }
    }
    EXPECT_LT(mismatch[1], 1e-2) << rotationMethodName(m);
    EXPECT_GT(mismatch[0] / mismatch[1], 4) << rotationMethodName(m);
    EXPECT_LT(mismatch[0] / mismatch[1], 25) << rotationMethodName(m);
  }
}

TYPED_TEST(CorotationalElementTest, StiffnessIsForceJacobianAtRigidlyMovedRest) {
  constexpr int N = TestFixture::N;
  for (RotationMethod m : kAllMethods) {
    const Eigen::Matrix3d Q =
        m == RotationMethod::small ? Eigen::Matrix3d::Identity() : test::randomRotation(this->rng);
    const NodalVectors<N> x = (Q * this->element.restPositions).colwise() + Eigen::Vector3d::Ones();
    const Eigen::Matrix3d R = computeRotation(m, this->element, x);
    const ElementMatrix<N> K = computeStiffness(this->element, R);
    const ElementMatrix<N> jacobian = test::finiteDifferenceJacobian<N>(
        [&](const NodalVectors<N>& y) { return this->force(m, y); }, x, 1e-6);
    EXPECT_LT((jacobian + K).norm(), 1e-6 * K.norm()) << rotationMethodName(m);
    EXPECT_TRUE(K.isApprox(K.transpose(), 1e-14));
    // computeDForce is the product with -K.
    const NodalVectors<N> dx = test::randomVectors<N>(this->rng, 1.0);
    const NodalVectors<N> df = computeDForce(this->element, R, dx);
    EXPECT_TRUE(asElementVector<N>(df).isApprox(-K * asElementVector<N>(dx), 1e-12));
  }
}

TYPED_TEST(CorotationalElementTest, InvertedElementGetsRotationAndRestoringForce) {
  constexpr int N = TestFixture::N;
  // Squash the element through itself along z: every Jacobian is negative.
  const NodalVectors<N> inverted =
      Eigen::Vector3d(1, 1, -0.3).asDiagonal() * this->element.restPositions;
  ASSERT_LT(TypeParam::volume(inverted), 0);
  const double restVolume = TypeParam::volume(this->element.restPositions);
  const double largest = Eigen::SelfAdjointEigenSolver<ElementMatrix<N>>(this->element.stiffness)
                             .eigenvalues()
                             .maxCoeff();
  for (RotationMethod m : {RotationMethod::polar, RotationMethod::svd}) {
    const Eigen::Matrix3d R = computeRotation(m, this->element, inverted);
    EXPECT_TRUE((R.transpose() * R).isIdentity(1e-12)) << rotationMethodName(m);
    EXPECT_NEAR(R.determinant(), 1, 1e-12) << rotationMethodName(m);
    // A small step along the force increases the signed volume.
    const NodalVectors<N> f = this->force(m, inverted);
    EXPECT_GT(TypeParam::volume(inverted + (0.01 / largest) * f), TypeParam::volume(inverted))
        << rotationMethodName(m);
    // Following the force (gradient flow, explicit steps) restores the rest volume.
    NodalVectors<N> x = inverted;
    for (int step = 0; step < 3000; ++step) x += (0.5 / largest) * this->force(m, x);
    EXPECT_NEAR(TypeParam::volume(x), restVolume, 1e-3 * restVolume) << rotationMethodName(m);
  }
}

// The factored form used by the matrix-free products (multiplyFactoredStiffness) is Ke.
TEST(CorotationalTetrahedron, FactoredStiffnessIsTheElementStiffness) {
  const double E = 3e4, nu = 0.45;
  const Matrix6d C = computeElasticityMatrix(computeLameParameters(E, nu));
  const Matrix6d unitC = computeElasticityMatrix(computeLameParameters(1.0, nu));
  CorotationalTetrahedron element;
  ASSERT_EQ(computeCorotationalTetrahedron(test::irregularTetrahedron(), C, element),
            ElementStatus::ok);
  const TetrahedronRows G = computeStiffnessFactor(element, E);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> uniform(-1, 1);
  for (int trial = 0; trial < 10; ++trial) {
    const TetrahedronVectors v = TetrahedronVectors::NullaryExpr([&] { return uniform(random); });
    TetrahedronVectors expected;
    Eigen::Map<ElementVector<4>>(expected.data()) = element.stiffness * asElementVector<4>(v);
    const TetrahedronVectors product = fromRows(multiplyFactoredStiffness(G, unitC, toRows(v)));
    EXPECT_LT((product - expected).norm(), 1e-14 * element.stiffness.norm() * v.norm());
  }
  // An element without stiffness (scale 0) has a zero factor.
  EXPECT_EQ(fromRows(computeStiffnessFactor(element, 0.0)), TetrahedronVectors::Zero());
}

}  // namespace
}  // namespace stroma::fem
