// SPDX-License-Identifier: MIT
// A spring force field for the tests, written here (not in a plugin) so that the tests of the
// force-field test and of the mappings do not depend on the spring plugin. Register it with
//   scene.runtime().factory().add("TestSprings", "test").with<stroma::test::CorrectSprings>();
#pragma once

#include <string>
#include <vector>

#include "core/StateTypes.h"
#include "simulation/ForceField.h"

namespace stroma::test {

/// Springs between pairs of points, E = sum k/2 (l - l0)^2 with l0 the rest length.
/// f_i = k (l - l0) u and f_j = -f_i, with u = (x_j - x_i) / l; the block
/// df_i/dx_j = k [u u^T + (1 - l0 / l)(I - u u^T)] (the second term is the geometric one).
class TestSprings : public ForceField<Vec3Types> {
 public:
  Data<std::vector<Vec2i>> d_edges{this, "edges", {}, "Springs (nbSprings x 2 points)."};
  Data<double> d_stiffness{this, "stiffness", 100.0, "Stiffness.", {.unit = "N/m", .min = 0.0}};

  void init() override {
    ForceField<Vec3Types>::init();
    if (!mstate()) return;
    const auto& rest = mstate()->readCoord(VecId::restPosition());
    m_restLength.clear();
    for (const Vec2i& e : d_edges.value()) {
      if (e.minCoeff() < 0 || static_cast<std::size_t>(e.maxCoeff()) >= rest.size()) {
        this->msgError("spring " + std::to_string(e[0]) + " " + std::to_string(e[1]) +
                           " is out of range of the " + std::to_string(rest.size()) + " points",
                       "edges");
        return;
      }
      m_restLength.push_back((rest[e[1]] - rest[e[0]]).norm());
    }
  }

  void addForce(const MechanicalParams&, VecDeriv& f, const VecCoord& x, const VecDeriv&) override {
    forEachSpring(x, [&](int i, int j, const Vec3d& u, double l, double l0) {
      const Vec3d fi = d_stiffness.value() * (l - l0) * u;
      f[i] += fi;
      f[j] -= fi;
    });
  }
  void addDForce(const MechanicalParams& mp, VecDeriv& df, const VecDeriv& dx) override {
    forEachSpring(mstate()->readCoord(VecId::position()),
                  [&](int i, int j, const Vec3d& u, double l, double l0) {
                    const Vec3d d = mp.kFactor * block(u, l, l0) * (dx[j] - dx[i]);
                    df[i] += d;
                    df[j] -= d;
                  });
  }
  void addKToMatrix(const MechanicalParams& mp, MatrixAccumulator& matrix,
                    std::size_t offset) override {
    forEachSpring(mstate()->readCoord(VecId::position()),
                  [&](int i, int j, const Vec3d& u, double l, double l0) {
                    Mat3d b = mp.kFactor * block(u, l, l0);
                    if (m_bug == Bug::matrixSign) b = -b;
                    const std::size_t ri = offset + 3 * i, rj = offset + 3 * j;
                    matrix.addBlock(ri, ri, -b);
                    matrix.addBlock(rj, rj, -b);
                    matrix.addBlock(ri, rj, b);
                    matrix.addBlock(rj, ri, b);
                  });
  }
  double potentialEnergy(const MechanicalParams&, const VecCoord& x) const override {
    double e = 0;
    forEachSpring(x, [&](int, int, const Vec3d&, double l, double l0) {
      e += 0.5 * d_stiffness.value() * (l - l0) * (l - l0);
    });
    return m_bug == Bug::energyFactor ? 2 * e : e;
  }

 protected:
  enum class Bug { none, noGeometricStiffness, matrixSign, energyFactor };
  Bug m_bug = Bug::none;

 private:
  Mat3d block(const Vec3d& u, double l, double l0) const {
    const Mat3d uu = u * u.transpose();
    const double geometric = m_bug == Bug::noGeometricStiffness ? 0.0 : 1.0 - l0 / l;
    return d_stiffness.value() * (uu + geometric * (Mat3d::Identity() - uu));
  }
  template <class F>
  void forEachSpring(const VecCoord& x, F&& f) const {
    const auto& edges = d_edges.value();
    for (std::size_t s = 0; s < edges.size(); ++s) {
      const int i = edges[s][0], j = edges[s][1];
      const Vec3d d = x[j] - x[i];
      const double l = d.norm();
      f(i, j, Vec3d(d / l), l, m_restLength[s]);
    }
  }
  std::vector<double> m_restLength;
};

/// The correct springs, registrable (TestSprings is a base of deliberately wrong variants).
struct CorrectSprings final : TestSprings {};

}  // namespace stroma::test
