// SPDX-License-Identifier: MIT
#include "PenalityContactForceField.h"

#include "core/Message.h"
#include "core/Node.h"

namespace stroma {

namespace {

// The point of a position or a displacement: Vec3d itself, a frame's origin (linear part).
inline const Vec3d& pointOf(const Vec3d& v) { return v; }
inline const Vec3d& pointOf(const RigidCoord3& x) { return x.center; }
inline const Vec3d& pointOf(const RigidDeriv3& d) { return d.linear; }
inline Vec3d& pointOf(Vec3d& v) { return v; }
inline Vec3d& pointOf(RigidDeriv3& d) { return d.linear; }

// A frame's arm in world axes at its position x (nothing on a point).
inline Vec3d worldArm(const Vec3d&, const Vec3d&) { return Vec3d::Zero(); }
inline Vec3d worldArm(const RigidCoord3& x, const Vec3d& arm) { return x.orientation * arm; }
// A frame's rotation in a displacement (nothing on a point), and a moment added to a force.
inline Vec3d rotationOf(const Vec3d&) { return Vec3d::Zero(); }
inline const Vec3d& rotationOf(const RigidDeriv3& d) { return d.angular; }
inline void addMoment(Vec3d&, const Vec3d&) {}
inline void addMoment(RigidDeriv3& d, const Vec3d& moment) { d.angular += moment; }

// Side s's arm in world axes at positions x: r_s = R_s arm_s (zero on points).
template <class Coords>
Vec3d armOf(const PenaltyContact& c, int side, const Coords& x) {
  return worldArm(x[c.vertices[side][0]], c.arm[side]);
}

// The contact point of side s: sum_k w_k x_k (+ r_s on a frame).
template <class Coords>
Vec3d contactPoint(const PenaltyContact& c, int side, const Coords& x, const Vec3d& arm) {
  Vec3d p = arm;
  for (int k = 0; k < c.vertexCount[side]; ++k)
    p += c.weights[side][k] * pointOf(x[c.vertices[side][k]]);
  return p;
}

// Its displacement for dx: sum_k w_k dx_k (+ dtheta x r_s on a frame).
template <class Derivs>
Vec3d pointDisplacement(const PenaltyContact& c, int side, const Derivs& dx, const Vec3d& arm) {
  Vec3d d = rotationOf(dx[c.vertices[side][0]]).cross(arm);
  for (int k = 0; k < c.vertexCount[side]; ++k)
    d += c.weights[side][k] * pointOf(dx[c.vertices[side][k]]);
  return d;
}

// A force applied at the contact point of side s: spread on its vertices by their weights (and
// its moment r_s x f on a frame).
template <class Derivs>
void spread(const PenaltyContact& c, int side, const Vec3d& force, const Vec3d& arm, Derivs& out) {
  for (int k = 0; k < c.vertexCount[side]; ++k)
    pointOf(out[c.vertices[side][k]]) += c.weights[side][k] * force;
  addMoment(out[c.vertices[side][0]], arm.cross(force));
}

using Direction = Eigen::Matrix<double, 6, 1>;

// J^T n for vertex k of side s: w_k n on a point, [w_k n; r_s x n] on a frame (dim 6).
Direction generalizedNormal(const PenaltyContact& c, int side, int k, const Vec3d& arm, int dim) {
  Direction g = Direction::Zero();
  g.head<3>() = c.weights[side][k] * c.normal;
  if (dim == 6 && k == 0) g.tail<3>() = arm.cross(c.normal);
  return g;
}

// Adds scale * (J_a^T n)(J_b^T n)^T for each pair of vertices of the two sides, at their rows,
// in 3 x 3 blocks (a frame's row block is 6 wide: linear, then angular).
void addBlocks(MatrixAccumulator& matrix, const PenaltyContact& c, int sideA, std::size_t offsetA,
               int dimA, const Vec3d& armA, int sideB, std::size_t offsetB, int dimB,
               const Vec3d& armB, double scale) {
  for (int a = 0; a < c.vertexCount[sideA]; ++a) {
    const Direction ga = generalizedNormal(c, sideA, a, armA, dimA);
    for (int b = 0; b < c.vertexCount[sideB]; ++b) {
      const Direction gb = generalizedNormal(c, sideB, b, armB, dimB);
      const Eigen::Matrix<double, 6, 6> block = scale * ga * gb.transpose();
      const std::size_t row = offsetA + c.vertices[sideA][a] * static_cast<std::size_t>(dimA);
      const std::size_t col = offsetB + c.vertices[sideB][b] * static_cast<std::size_t>(dimB);
      for (int i = 0; i < dimA; i += 3)
        for (int j = 0; j < dimB; j += 3) {
          const Mat3d sub = block.block<3, 3>(i, j);
          if (!sub.isZero(0)) matrix.addBlock(row + i, col + j, sub);
        }
    }
  }
}

Mat3d cross(const Vec3d& v) {
  Mat3d m;
  m << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return m;
}

}  // namespace

template <class D1, class D2>
double PenalityContactForceField<D1, D2>::penetration(
    const PenaltyContact& c, const std::vector<typename D1::Coord>& x1,
    const std::vector<typename D2::Coord>& x2) const {
  return c.restDistance - c.normal.dot(contactPoint(c, 1, x2, armOf(c, 1, x2)) -
                                       contactPoint(c, 0, x1, armOf(c, 0, x1)));
}

template <class D1, class D2>
void PenalityContactForceField<D1, D2>::accumulateForce(const MechanicalParams& mp, VecId f) {
  m_lastForce.setZero();
  m_active = 0;
  if (m_contacts.empty()) {
    d_force.setValue(m_lastForce);
    return;
  }
  const auto& x1 = m_state1->readCoord(mp.x);
  const auto& x2 = m_state2->readCoord(mp.x);
  auto& f1 = m_state1->writeDeriv(f);
  auto& f2 = m_state2->writeDeriv(f);
  for (const PenaltyContact& c : m_contacts) {
    const double p = penetration(c, x1, x2);
    if (!(p > 0)) continue;
    const Vec3d force = c.stiffness * p * c.normal;  // on side 2; minus it on side 1
    spread(c, 0, -force, armOf(c, 0, x1), f1);
    spread(c, 1, force, armOf(c, 1, x2), f2);
    m_lastForce += force;
    ++m_active;
  }
  d_force.setValue(m_lastForce);
  if (m_lastForce.norm() > m_largestForce) {
    m_largestForce = m_lastForce.norm();
    m_largestForceTime = node() ? node()->time() : 0.0;
  }
}

template <class D1, class D2>
std::vector<std::string> PenalityContactForceField<D1, D2>::runSummaryLines() const {
  return {std::to_string(m_active) + " contacts pushing at the end; force on " + m_state2->path() +
              ": " + formatNumber(m_lastForce.x()) + " " + formatNumber(m_lastForce.y()) + " " +
              formatNumber(m_lastForce.z()) + " N (on " + m_state1->path() + ": the opposite)",
          "largest contact force " + formatNumber(m_largestForce) + " N, at time " +
              formatNumber(m_largestForceTime) + " s"};
}

template <class D1, class D2>
void PenalityContactForceField<D1, D2>::accumulateDForce(const MechanicalParams& mp, VecId df,
                                                         VecId dx) {
  if (m_contacts.empty() || mp.kFactor == 0) return;
  const auto& x1 = m_state1->readCoord(mp.x);
  const auto& x2 = m_state2->readCoord(mp.x);
  const auto& dx1 = m_state1->readDeriv(dx);
  const auto& dx2 = m_state2->readDeriv(dx);
  auto& df1 = m_state1->writeDeriv(df);
  auto& df2 = m_state2->writeDeriv(df);
  for (const PenaltyContact& c : m_contacts) {
    const double p = penetration(c, x1, x2);
    if (!(p > 0)) continue;
    const Vec3d r1 = armOf(c, 0, x1), r2 = armOf(c, 1, x2);
    // dp = -n.(dx_2 - dx_1) at the contact points; the force on side 2 changes by k dp n.
    const double dp =
        -c.normal.dot(pointDisplacement(c, 1, dx2, r2) - pointDisplacement(c, 0, dx1, r1));
    const Vec3d dforce = mp.kFactor * c.stiffness * dp * c.normal;
    spread(c, 0, -dforce, r1, df1);
    spread(c, 1, dforce, r2, df2);
    if (d_geometricStiffness.value()) {
      // The arms turn with the frames: d(r x f) = (dtheta x r) x f = f x (r x dtheta).
      const Vec3d f2 = mp.kFactor * c.stiffness * p * c.normal;
      addMoment(df1[c.vertices[0][0]], -f2.cross(r1.cross(rotationOf(dx1[c.vertices[0][0]]))));
      addMoment(df2[c.vertices[1][0]], f2.cross(r2.cross(rotationOf(dx2[c.vertices[1][0]]))));
    }
  }
}

template <class D1, class D2>
void PenalityContactForceField<D1, D2>::accumulateKMatrix(const MechanicalParams& mp,
                                                          MatrixAccumulator& matrix,
                                                          const StateOffsets& offsets) {
  if (m_contacts.empty() || mp.kFactor == 0) return;
  std::size_t o1 = 0, o2 = 0;
  const bool has1 = offsets.find(m_state1, o1), has2 = offsets.find(m_state2, o2);
  if (!has1 && !has2) return;
  const auto& x1 = m_state1->readCoord(mp.x);
  const auto& x2 = m_state2->readCoord(mp.x);
  constexpr int d1 = D1::derivSize, d2 = D2::derivSize;
  for (const PenaltyContact& c : m_contacts) {
    const double p = penetration(c, x1, x2);
    if (!(p > 0)) continue;
    const double k = mp.kFactor * c.stiffness;
    const Vec3d r1 = armOf(c, 0, x1), r2 = armOf(c, 1, x2);
    if (has1) addBlocks(matrix, c, 0, o1, d1, r1, 0, o1, d1, r1, -k);
    if (has2) addBlocks(matrix, c, 1, o2, d2, r2, 1, o2, d2, r2, -k);
    if (has1 && has2) {
      addBlocks(matrix, c, 0, o1, d1, r1, 1, o2, d2, r2, k);
      addBlocks(matrix, c, 1, o2, d2, r2, 0, o1, d1, r1, k);
    }
    if (d_geometricStiffness.value()) {
      // [f_s]x [r_s]x on the rotation block of each frame (f_2 = k p n, f_1 = -f_2).
      const Vec3d f2 = k * p * c.normal;
      if (has1 && d1 == 6)
        matrix.addBlock(o1 + c.vertices[0][0] * std::size_t{6} + 3,
                        o1 + c.vertices[0][0] * std::size_t{6} + 3, -cross(f2) * cross(r1));
      if (has2 && d2 == 6)
        matrix.addBlock(o2 + c.vertices[1][0] * std::size_t{6} + 3,
                        o2 + c.vertices[1][0] * std::size_t{6} + 3, cross(f2) * cross(r2));
    }
  }
}

template <class D1, class D2>
double PenalityContactForceField<D1, D2>::energy(const MechanicalParams& mp) const {
  const auto& x1 = m_state1->readCoord(mp.x);
  const auto& x2 = m_state2->readCoord(mp.x);
  double e = 0;
  for (const PenaltyContact& c : m_contacts) {
    const double p = penetration(c, x1, x2);
    if (p > 0) e += 0.5 * c.stiffness * p * p;
  }
  return e;
}

template class PenalityContactForceField<Vec3Types, Vec3Types>;
template class PenalityContactForceField<Vec3Types, Rigid3Types>;
template class PenalityContactForceField<Rigid3Types, Vec3Types>;
template class PenalityContactForceField<Rigid3Types, Rigid3Types>;

}  // namespace stroma
