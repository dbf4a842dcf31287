// SPDX-License-Identifier: MIT
#include "SpringKernel.h"

namespace stroma {

SpringResponse evaluateSpring(const LinearSpring& s, const Vec3d& p1, const Vec3d& p2,
                              const Vec3d& v1, const Vec3d& v2) {
  SpringResponse r;
  const Vec3d u = p2 - p1;
  const double l = u.norm();
  if (s.elongationOnly && l < s.restLength) return r;
  const double tiny = 1e-14 * (1 + s.restLength);
  if (s.restLength == 0) {
    // Linear spring: f1 = ks u, defined everywhere.
    r.force = s.ks * u;
    r.stiffness = s.ks * Mat3d::Identity();
    r.energy = 0.5 * s.ks * u.squaredNorm();
    if (l > tiny) {
      const Vec3d e = u / l;
      r.force += s.kd * (v2 - v1).dot(e) * e;
      r.damping = s.kd * e * e.transpose();
    }
    return r;
  }
  if (l <= tiny) return r;  // no direction: the ends coincide
  const Vec3d e = u / l;
  const Mat3d eeT = e * e.transpose();
  const double stretch = l - s.restLength;
  r.force = (s.ks * stretch + s.kd * (v2 - v1).dot(e)) * e;
  r.stiffness = s.ks * (eeT + (stretch / l) * (Mat3d::Identity() - eeT));
  r.damping = s.kd * eeT;
  r.energy = 0.5 * s.ks * stretch * stretch;
  return r;
}

namespace {
const Vec3d kZero = Vec3d::Zero();
}  // namespace

double addSpringForces(const std::vector<LinearSpring>& springs, const SpringStates& x,
                       const std::vector<Vec3d>& v1, const std::vector<Vec3d>& v2,
                       std::vector<Vec3d>& f1, std::vector<Vec3d>& f2) {
  double energy = 0;
  for (const LinearSpring& s : springs) {
    const SpringResponse r =
        evaluateSpring(s, x.x1[s.m1], x.x2[s.m2], s.m1 < v1.size() ? v1[s.m1] : kZero,
                       s.m2 < v2.size() ? v2[s.m2] : kZero);
    f1[s.m1] += r.force;
    f2[s.m2] -= r.force;
    energy += r.energy;
  }
  return energy;
}

void addSpringDForces(const std::vector<LinearSpring>& springs, const SpringStates& x,
                      const std::vector<Vec3d>& dx1, const std::vector<Vec3d>& dx2,
                      std::vector<Vec3d>& df1, std::vector<Vec3d>& df2, double kFactor,
                      double bFactor) {
  for (const LinearSpring& s : springs) {
    const SpringResponse r = evaluateSpring(s, x.x1[s.m1], x.x2[s.m2], kZero, kZero);
    const Vec3d d = dx2[s.m2] - dx1[s.m1];
    const Vec3d df = kFactor * (r.stiffness * d) + bFactor * (r.damping * d);
    df1[s.m1] += df;
    df2[s.m2] -= df;
  }
}

void addSpringMatrix(const std::vector<LinearSpring>& springs, const SpringStates& x,
                     MatrixAccumulator& matrix, std::size_t offset1, std::size_t offset2,
                     double kFactor, double bFactor) {
  for (const LinearSpring& s : springs) {
    const SpringResponse r = evaluateSpring(s, x.x1[s.m1], x.x2[s.m2], kZero, kZero);
    const Mat3d K = kFactor * r.stiffness + bFactor * r.damping;
    const std::size_t row1 = offset1 + 3 * std::size_t{s.m1};
    const std::size_t row2 = offset2 + 3 * std::size_t{s.m2};
    matrix.addBlock(row1, row1, -K);
    matrix.addBlock(row1, row2, K);
    matrix.addBlock(row2, row1, K);
    matrix.addBlock(row2, row2, -K);
  }
}

double springEnergy(const std::vector<LinearSpring>& springs, const SpringStates& x) {
  double energy = 0;
  for (const LinearSpring& s : springs)
    energy += evaluateSpring(s, x.x1[s.m1], x.x2[s.m2], kZero, kZero).energy;
  return energy;
}

}  // namespace stroma
