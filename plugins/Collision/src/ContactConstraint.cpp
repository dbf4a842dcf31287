// SPDX-License-Identifier: MIT
#include "ContactConstraint.h"

namespace stroma {

namespace {

inline const Vec3d& pointOf(const Vec3d& v) { return v; }
inline const Vec3d& pointOf(const RigidCoord3& x) { return x.center; }
inline const Vec3d& pointOf(const RigidDeriv3& d) { return d.linear; }

// A frame's arm in world axes (nothing on a point) and a frame's angular velocity.
inline Vec3d worldArm(const Vec3d&, const Vec3d&) { return Vec3d::Zero(); }
inline Vec3d worldArm(const RigidCoord3& x, const Vec3d& arm) { return x.orientation * arm; }
inline Vec3d angularOf(const Vec3d&) { return Vec3d::Zero(); }
inline const Vec3d& angularOf(const RigidDeriv3& d) { return d.angular; }

template <class Vector>
Vec3d weighted(const PenaltyContact& c, int side, const Vector& values) {
  Vec3d p = Vec3d::Zero();
  for (int k = 0; k < c.vertexCount[side]; ++k)
    p += c.weights[side][k] * pointOf(values[c.vertices[side][k]]);
  return p;
}

// The entries of one row on one side: the direction on the weighted vertices, and on a frame
// (derivSize 6) the moment arm x direction on its rotation.
template <class DataTypes>
void addSide(ConstraintRows& rows, std::size_t row, const MechanicalState<DataTypes>* state,
             const PenaltyContact& c, int side, double sign, const Vec3d& direction,
             const Vec3d& arm) {
  constexpr std::size_t dim = DataTypes::derivSize;
  for (int k = 0; k < c.vertexCount[side]; ++k)
    for (int a = 0; a < 3; ++a)
      rows.add(row, state, c.vertices[side][k] * dim + a, sign * c.weights[side][k] * direction[a]);
  if constexpr (dim == 6) {
    const Vec3d moment = arm.cross(direction);
    for (int a = 0; a < 3; ++a) rows.add(row, state, c.vertices[side][0] * dim + 3 + a, sign * moment[a]);
  }
}

}  // namespace

void ContactConstraintBase::storeMultipliers(std::span<const double> lambda) {
  const std::size_t perContact = static_cast<std::size_t>(rowsPerContact());
  std::vector<Vec3d>& forces = d_contactForces.edit();
  forces.resize(m_frames.size());
  Vec3d total = Vec3d::Zero();
  for (std::size_t i = 0; i < m_frames.size(); ++i) {
    Vec3d f = Vec3d::Zero();
    for (std::size_t r = 0; r < perContact && perContact * i + r < lambda.size(); ++r)
      f += lambda[perContact * i + r] * m_frames[i][r];
    forces[i] = f;
    total += f;
  }
  d_force.setValue(total);
}

template <class D1, class D2>
void ContactConstraint<D1, D2>::buildConstraintRows(ConstraintRows& rows, double dt) {
  m_frames.resize(m_contacts.size());
  m_surfaceOffsets.resize(m_contacts.size(), {Vec3d::Zero(), Vec3d::Zero()});
  if (m_contacts.empty()) return;
  const auto& x1 = m_state1->readCoord(VecId::position());
  const auto& x2 = m_state2->readCoord(VecId::position());
  const auto& v1 = m_state1->readDeriv(VecId::velocity());
  const auto& v2 = m_state2->readDeriv(VecId::velocity());
  for (std::size_t i = 0; i < m_contacts.size(); ++i) {
    const PenaltyContact& c = m_contacts[i];
    auto& frame = m_frames[i];
    frame = contactFrame(c.normal);
    // The normal row acts at the point the penalty response uses (a sphere's centre: its force
    // goes through it); friction at the surface point (a sphere's centre plus its offset).
    const Vec3d arm1 = worldArm(x1[c.vertices[0][0]], c.arm[0]);
    const Vec3d arm2 = worldArm(x2[c.vertices[1][0]], c.arm[1]);
    const Vec3d surface1 = arm1 + m_surfaceOffsets[i][0];
    const Vec3d surface2 = arm2 + m_surfaceOffsets[i][1];
    const Vec3d gap = weighted(c, 1, x2) + arm2 - weighted(c, 0, x1) - arm1;
    const Vec3d velocity1 = weighted(c, 0, v1) + angularOf(v1[c.vertices[0][0]]).cross(surface1);
    const Vec3d velocity2 = weighted(c, 1, v2) + angularOf(v2[c.vertices[1][0]]).cross(surface2);
    const Vec3d slip = dt * (velocity2 - velocity1);
    const double normalGap = c.normal.dot(gap) - c.restDistance;
    std::size_t first = 0;
    int count = 3;
    if (m_law == Law::stick) {
      const std::array<double, 3> violations{normalGap, frame[1].dot(slip), frame[2].dot(slip)};
      for (int r = 0; r < 3; ++r) {
        const std::size_t row =
            rows.addGroup(ConstraintKind::bilateral, std::span<const double>(&violations[r], 1));
        if (r == 0) first = row;
      }
    } else {
      first = addContactGroup(rows, frame, normalGap, slip, m_mu, count);
    }
    for (int r = 0; r < count; ++r) {
      const Vec3d& direction = frame[static_cast<std::size_t>(r)];
      addSide(rows, first + r, m_state2, c, 1, 1.0, direction, r == 0 ? arm2 : surface2);
      addSide(rows, first + r, m_state1, c, 0, -1.0, direction, r == 0 ? arm1 : surface1);
    }
  }
}

template class ContactConstraint<Vec3Types, Vec3Types>;
template class ContactConstraint<Vec3Types, Rigid3Types>;
template class ContactConstraint<Rigid3Types, Vec3Types>;
template class ContactConstraint<Rigid3Types, Rigid3Types>;

}  // namespace stroma
