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

template <class Vector>
Vec3d weightedPoint(const PenaltyContact& c, int side, const Vector& values) {
  Vec3d p = Vec3d::Zero();
  for (int k = 0; k < c.vertexCount[side]; ++k)
    p += c.weights[side][k] * pointOf(values[c.vertices[side][k]]);
  return p;
}

template <class Vector>
void spread(const PenaltyContact& c, int side, const Vec3d& force, Vector& out) {
  for (int k = 0; k < c.vertexCount[side]; ++k)
    pointOf(out[c.vertices[side][k]]) += c.weights[side][k] * force;
}

// Adds scale * w_a w_b n n^T for each pair of vertices of the two sides, at their rows.
void addBlocks(MatrixAccumulator& matrix, const PenaltyContact& c, int sideA, std::size_t offsetA,
               int dimA, int sideB, std::size_t offsetB, int dimB, double scale) {
  const Mat3d nn = c.normal * c.normal.transpose();
  for (int a = 0; a < c.vertexCount[sideA]; ++a)
    for (int b = 0; b < c.vertexCount[sideB]; ++b) {
      const double w = scale * c.weights[sideA][a] * c.weights[sideB][b];
      if (w == 0) continue;
      const std::size_t row = offsetA + c.vertices[sideA][a] * static_cast<std::size_t>(dimA);
      const std::size_t col = offsetB + c.vertices[sideB][b] * static_cast<std::size_t>(dimB);
      matrix.addBlock(row, col, w * nn);
    }
}

}  // namespace

template <class D1, class D2>
double PenalityContactForceField<D1, D2>::penetration(
    const PenaltyContact& c, const std::vector<typename D1::Coord>& x1,
    const std::vector<typename D2::Coord>& x2) const {
  return c.restDistance - c.normal.dot(weightedPoint(c, 1, x2) - weightedPoint(c, 0, x1));
}

template <class D1, class D2>
void PenalityContactForceField<D1, D2>::accumulateForce(const MechanicalParams& mp, VecId f) {
  m_lastForce.setZero();
  m_active = 0;
  if (m_contacts.empty()) return;
  const auto& x1 = m_state1->readCoord(mp.x);
  const auto& x2 = m_state2->readCoord(mp.x);
  auto& f1 = m_state1->writeDeriv(f);
  auto& f2 = m_state2->writeDeriv(f);
  for (const PenaltyContact& c : m_contacts) {
    const double p = penetration(c, x1, x2);
    if (!(p > 0)) continue;
    const Vec3d force = c.stiffness * p * c.normal;  // on side 2; minus it on side 1
    spread(c, 0, -force, f1);
    spread(c, 1, force, f2);
    m_lastForce += force;
    ++m_active;
  }
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
    if (!(penetration(c, x1, x2) > 0)) continue;
    // dp = -n.(dx_2 - dx_1); the force on side 2 changes by k dp n.
    const double dp = -c.normal.dot(weightedPoint(c, 1, dx2) - weightedPoint(c, 0, dx1));
    const Vec3d dforce = mp.kFactor * c.stiffness * dp * c.normal;
    spread(c, 0, -dforce, df1);
    spread(c, 1, dforce, df2);
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
    if (!(penetration(c, x1, x2) > 0)) continue;
    const double k = mp.kFactor * c.stiffness;
    if (has1) addBlocks(matrix, c, 0, o1, d1, 0, o1, d1, -k);
    if (has2) addBlocks(matrix, c, 1, o2, d2, 1, o2, d2, -k);
    if (has1 && has2) {
      addBlocks(matrix, c, 0, o1, d1, 1, o2, d2, k);
      addBlocks(matrix, c, 1, o2, d2, 0, o1, d1, k);
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
