// SPDX-License-Identifier: MIT
// Force fields made for the solver tests, registered into a test's Runtime (they are not
// components of Stroma): an anchor spring per point (harmonic oscillators with a closed-form
// motion, optionally hardening) and springs between pairs of points (chains and lattices).
// Both give forces, products by K and assembled K consistent with each other and with their
// energy, so that the solvers are tested alone.
#pragma once

#include <cmath>
#include <vector>

#include "core/ObjectFactory.h"
#include "core/StateTypes.h"
#include "simulation/ForceField.h"
#include "simulation/Mass.h"

namespace stroma::test {

/// Pulls each point to its rest position: f = -k o d - c |d|^2 d, d = x - x_rest, k per axis.
/// Energy 1/2 d^T diag(k) d + 1/4 c |d|^4; K = -diag(k) - c (|d|^2 I + 2 d d^T).
class TestAnchorForceField final : public ForceField<Vec3Types> {
 public:
  Data<Vec3d> d_stiffness{
      this, "stiffness", Vec3d(1, 1, 1), "Stiffness per axis.", {.unit = "N/m"}};
  Data<double> d_cubicStiffness{
      this, "cubicStiffness", 0.0, "Hardening coefficient c.", {.unit = "N/m^3"}};
  Data<double> d_tangentScale{this, "tangentScale", 1.0,
                              "Scales K only (not the force): a wrong derivative, to test how "
                              "solvers cope with one."};

  void init() override {
    ForceField<Vec3Types>::init();
    if (mstate()) m_rest = mstate()->readCoord(VecId::restPosition());
  }
  void addForce(const MechanicalParams&, VecDeriv& f, const VecCoord& x, const VecDeriv&) override {
    const Vec3d k = d_stiffness.value();
    const double c = d_cubicStiffness.value();
    for (std::size_t i = 0; i < x.size(); ++i) {
      const Vec3d d = x[i] - m_rest[i];
      f[i] -= k.cwiseProduct(d) + c * d.squaredNorm() * d;
    }
  }
  void addDForce(const MechanicalParams& mp, VecDeriv& df, const VecDeriv& dx) override {
    const VecCoord& x = mstate()->readCoord(mp.x);
    for (std::size_t i = 0; i < dx.size(); ++i) df[i] += mp.kFactor * (stiffness(x, i) * dx[i]);
  }
  void addKToMatrix(const MechanicalParams& mp, MatrixAccumulator& matrix,
                    std::size_t offset) override {
    const VecCoord& x = mstate()->readCoord(mp.x);
    for (std::size_t i = 0; i < x.size(); ++i)
      matrix.addBlock(offset + 3 * i, offset + 3 * i, mp.kFactor * stiffness(x, i));
  }
  double potentialEnergy(const MechanicalParams&, const VecCoord& x) const override {
    const Vec3d k = d_stiffness.value();
    double e = 0;
    for (std::size_t i = 0; i < x.size(); ++i) {
      const Vec3d d = x[i] - m_rest[i];
      e += 0.5 * d.dot(k.cwiseProduct(d)) +
           0.25 * d_cubicStiffness.value() * d.squaredNorm() * d.squaredNorm();
    }
    return e;
  }

 private:
  Eigen::Matrix3d stiffness(const VecCoord& x, std::size_t i) const {
    const Vec3d d = x[i] - m_rest[i];
    const double c = d_cubicStiffness.value();
    Eigen::Matrix3d K = -Eigen::Matrix3d(d_stiffness.value().asDiagonal());
    K -= c * (d.squaredNorm() * Eigen::Matrix3d::Identity() + 2 * d * d.transpose());
    return d_tangentScale.value() * K;
  }
  VecCoord m_rest;
};

/// Springs between pairs of points, tension T = k e + c e^3 for the elongation e = L - L_rest
/// (L_rest from the rest positions). With u = x_j - x_i, n = u / L and
/// G = (k + 3 c e^2) n n^T + T / L (I - n n^T): f_i = T n = -f_j, K_ii = K_jj = -G,
/// K_ij = K_ji = G. Energy 1/2 k e^2 + 1/4 c e^4.
class TestSpringForceField final : public ForceField<Vec3Types> {
 public:
  Data<std::vector<unsigned>> d_springs{this, "springs", {}, "Pairs of point indices."};
  Data<double> d_stiffness{this, "stiffness", 1.0, "Linear stiffness k.", {.unit = "N/m"}};
  Data<double> d_cubicStiffness{
      this, "cubicStiffness", 0.0, "Hardening coefficient c.", {.unit = "N/m^3"}};

  void init() override {
    ForceField<Vec3Types>::init();
    if (!mstate()) return;
    const VecCoord& rest = mstate()->readCoord(VecId::restPosition());
    const auto& s = d_springs.value();
    m_restLength.clear();
    for (std::size_t p = 0; p + 1 < s.size(); p += 2)
      m_restLength.push_back((rest[s[p + 1]] - rest[s[p]]).norm());
  }
  void addForce(const MechanicalParams&, VecDeriv& f, const VecCoord& x, const VecDeriv&) override {
    forEachSpring(
        x, [&](unsigned i, unsigned j, const Vec3d& n, double, double T, const Eigen::Matrix3d&) {
          f[i] += T * n;
          f[j] -= T * n;
        });
  }
  void addDForce(const MechanicalParams& mp, VecDeriv& df, const VecDeriv& dx) override {
    forEachSpring(mstate()->readCoord(mp.x), [&](unsigned i, unsigned j, const Vec3d&, double,
                                                 double, const Eigen::Matrix3d& G) {
      const Vec3d d = mp.kFactor * (G * (dx[j] - dx[i]));
      df[i] += d;
      df[j] -= d;
    });
  }
  void addKToMatrix(const MechanicalParams& mp, MatrixAccumulator& matrix,
                    std::size_t offset) override {
    forEachSpring(mstate()->readCoord(mp.x), [&](unsigned i, unsigned j, const Vec3d&, double,
                                                 double, const Eigen::Matrix3d& G) {
      const Eigen::Matrix3d kG = mp.kFactor * G;
      matrix.addBlock(offset + 3 * i, offset + 3 * i, -kG);
      matrix.addBlock(offset + 3 * i, offset + 3 * j, kG);
      matrix.addBlock(offset + 3 * j, offset + 3 * i, kG);
      matrix.addBlock(offset + 3 * j, offset + 3 * j, -kG);
    });
  }
  double potentialEnergy(const MechanicalParams&, const VecCoord& x) const override {
    double energy = 0;
    const double k = d_stiffness.value(), c = d_cubicStiffness.value();
    forEachSpring(x,
                  [&](unsigned, unsigned, const Vec3d&, double e, double, const Eigen::Matrix3d&) {
                    energy += 0.5 * k * e * e + 0.25 * c * e * e * e * e;
                  });
    return energy;
  }

 private:
  template <class F>
  void forEachSpring(const VecCoord& x, F&& f) const {
    const auto& s = d_springs.value();
    const double k = d_stiffness.value(), c = d_cubicStiffness.value();
    for (std::size_t p = 0; p < m_restLength.size(); ++p) {
      const unsigned i = s[2 * p], j = s[2 * p + 1];
      const Vec3d u = x[j] - x[i];
      const double L = u.norm();
      const Vec3d n = u / L;
      const double e = L - m_restLength[p];
      const double T = k * e + c * e * e * e;
      const Eigen::Matrix3d nn = n * n.transpose();
      const Eigen::Matrix3d G =
          (k + 3 * c * e * e) * nn + (T / L) * (Eigen::Matrix3d::Identity() - nn);
      f(i, j, n, e, T, G);
    }
  }
  std::vector<double> m_restLength;
};

/// A consistent (non-diagonal) mass: points (2k, 2k+1) form bars of mass 2 m with the
/// linear-element mass matrix m/3 [[2, 1], [1, 2]] per axis (a lone last point has mass m).
/// Explicit solvers must invert it through a linear solver. No gravity.
class TestBarMass final : public Mass<Vec3Types> {
 public:
  Data<double> d_mass{this, "pointMass", 1.0, "m: half the mass of a bar.", {.unit = "kg"}};

  void addForce(const MechanicalParams&, VecDeriv&, const VecCoord&, const VecDeriv&) override {}
  void addDForce(const MechanicalParams&, VecDeriv&, const VecDeriv&) override {}
  void addKToMatrix(const MechanicalParams&, MatrixAccumulator&, std::size_t) override {}
  void addMDx(VecDeriv& f, const VecDeriv& dx, double factor) override {
    const double m = factor * d_mass.value();
    for (std::size_t i = 0; i + 1 < dx.size(); i += 2) {
      f[i] += m / 3 * (2 * dx[i] + dx[i + 1]);
      f[i + 1] += m / 3 * (dx[i] + 2 * dx[i + 1]);
    }
    if (dx.size() % 2) f.back() += m * dx.back();
  }
  void accFromF(VecDeriv&, const VecDeriv&) override {
    this->msgError("accFromF called on a non-diagonal mass");
  }
  void addMToMatrix(MatrixAccumulator& matrix, std::size_t offset, double factor) override {
    const double m = factor * d_mass.value();
    const std::size_t n = mstate()->size();
    const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
    for (std::size_t i = 0; i + 1 < n; i += 2) {
      const std::size_t a = offset + 3 * i, b = offset + 3 * (i + 1);
      matrix.addBlock(a, a, 2 * m / 3 * I);
      matrix.addBlock(a, b, m / 3 * I);
      matrix.addBlock(b, a, m / 3 * I);
      matrix.addBlock(b, b, 2 * m / 3 * I);
    }
    if (n % 2) matrix.addBlock(offset + 3 * (n - 1), offset + 3 * (n - 1), m * I);
  }
  double kineticEnergy(const VecDeriv& v) const override {
    VecDeriv mv(v.size(), Vec3d::Zero());
    const_cast<TestBarMass*>(this)->addMDx(mv, v, 1.0);
    double e = 0;
    for (std::size_t i = 0; i < v.size(); ++i) e += 0.5 * v[i].dot(mv[i]);
    return e;
  }
  bool isDiagonal() const override { return false; }
};

/// Registers the test force fields in a Runtime's factory.
inline void registerTestSprings(ObjectFactory& factory) {
  factory.add("TestAnchorForceField", "Test: anchor springs").with<TestAnchorForceField>("Vec3d");
  factory.add("TestSpringForceField", "Test: springs between points")
      .with<TestSpringForceField>("Vec3d");
  factory.add("TestBarMass", "Test: consistent bar masses").with<TestBarMass>("Vec3d");
}

}  // namespace stroma::test
