// SPDX-License-Identifier: MIT
#include "RigidMapping.h"

namespace stroma {

void RigidMapping::init() {
  if (!findStates()) return;
  m_options.warnUnsupported(*this, output() != nullptr);
  if (d_geometricStiffness.value() != 0)
    msgWarning("geometricStiffness=" + std::to_string(d_geometricStiffness.value()) +
                   " is not implemented: J^T f is linearized with J only",
               "geometricStiffness");
  if (!output()) return;  // a visual output is prepared when first drawn (prepareVisual)
  if (!computeLocalPoints(output()->readCoord(VecId::position()), VecId::position())) return;
  const bool resized = resizeOutput(*output(), m_local.size());
  applyAtInit(*this, resized || m_options.applyRestPosition.value());
}

// A visual output is prepared when first drawn, maybe after steps: world points are made local
// in the frames of the start (reset positions, those init() would have used).
bool RigidMapping::prepareVisual(const OutVecCoord& points) {
  const bool started = input()->readCoord(VecId::resetPosition()).size() == input()->size();
  return computeLocalPoints(points, started ? VecId::resetPosition() : VecId::position());
}

// The frame of each point and its local coordinates, the points of the output being
// `outputPoints` and the frames `frameId`; false after an error.
bool RigidMapping::computeLocalPoints(const std::vector<Vec3d>& outputPoints, VecId frameId) {
  const auto& frames = input()->readCoord(frameId);
  const std::size_t nbFrames = frames.size();
  const bool given = !d_points.value().empty() || !d_initialPoints.value().empty();
  const std::vector<Vec3d>& points = !d_points.value().empty() ? d_points.value()
                                     : given                   ? d_initialPoints.value()
                                             : outputPoints;
  const std::size_t n = points.size();
  if (n == 0) msgWarning("maps no point: give points or positions to the output", "points");

  // Frame of each point.
  const auto& perPoint = d_rigidIndexPerPoint.value();
  if (!perPoint.empty() && perPoint.size() != n) {
    msgError("has " + std::to_string(perPoint.size()) + " values for " + std::to_string(n) +
                 " mapped points",
             "rigidIndexPerPoint");
    return false;
  }
  if (perPoint.empty()) {
    if (d_index.value() >= nbFrames) {
      msgError("index " + std::to_string(d_index.value()) + " is out of range of the " +
                   std::to_string(nbFrames) + " input frames",
               "index");
      return false;
    }
    const unsigned k = d_indexFromEnd.value()
                           ? static_cast<unsigned>(nbFrames - 1 - d_index.value())
                           : d_index.value();
    m_frame.assign(n, k);
  } else {
    std::string bad;
    for (unsigned k : perPoint)
      if (k >= nbFrames) bad += (bad.empty() ? "" : " ") + std::to_string(k);
    if (!bad.empty()) {
      msgError("frames out of range of the " + std::to_string(nbFrames) + " input frames: " + bad,
               "rigidIndexPerPoint");
      return false;
    }
    m_frame = perPoint;
  }

  // Local coordinates: p = R^T (x - c) for world coordinates.
  m_local = points;
  if (!given && d_globalToLocalCoords.value())
    for (std::size_t i = 0; i < n; ++i) {
      const RigidCoord3& frame = frames[m_frame[i]];
      m_local[i] = frame.orientation.conjugate() * (points[i] - frame.center);
    }
  return true;
}

void RigidMapping::apply(OutVecCoord& out, const InVecCoord& in) {
  out.resize(m_local.size());
  for (std::size_t i = 0; i < m_local.size(); ++i) {
    const RigidCoord3& frame = in[m_frame[i]];
    out[i] = frame.center + frame.orientation * m_local[i];
  }
}

void RigidMapping::applyJ(OutVecDeriv& out, const InVecDeriv& in) {
  const auto& frames = input()->readCoord(VecId::position());
  out.resize(m_local.size());
  for (std::size_t i = 0; i < m_local.size(); ++i) {
    const RigidDeriv3& v = in[m_frame[i]];
    const Vec3d r = frames[m_frame[i]].orientation * m_local[i];
    out[i] = v.linear + v.angular.cross(r);
  }
}

void RigidMapping::applyJT(InVecDeriv& in, const OutVecDeriv& out) {
  const auto& frames = input()->readCoord(VecId::position());
  for (std::size_t i = 0; i < m_local.size() && i < out.size(); ++i) {
    RigidDeriv3& f = in[m_frame[i]];
    const Vec3d r = frames[m_frame[i]].orientation * m_local[i];
    f.linear += out[i];
    f.angular += r.cross(out[i]);
  }
}

const Eigen::SparseMatrix<double>& RigidMapping::jacobian() {
  const auto& frames = input()->readCoord(VecId::position());
  m_triplets.clear();
  m_triplets.reserve(12 * m_local.size());
  for (std::size_t i = 0; i < m_local.size(); ++i) {
    const int row = static_cast<int>(3 * i), col = static_cast<int>(6 * m_frame[i]);
    const Vec3d r = frames[m_frame[i]].orientation * m_local[i];
    // [ I  -[r]x ]: -[r]x w = w x r.
    for (int c = 0; c < 3; ++c) m_triplets.emplace_back(row + c, col + c, 1.0);
    m_triplets.emplace_back(row + 0, col + 4, r.z());
    m_triplets.emplace_back(row + 0, col + 5, -r.y());
    m_triplets.emplace_back(row + 1, col + 3, -r.z());
    m_triplets.emplace_back(row + 1, col + 5, r.x());
    m_triplets.emplace_back(row + 2, col + 3, r.y());
    m_triplets.emplace_back(row + 2, col + 4, -r.x());
  }
  m_J.resize(static_cast<Eigen::Index>(3 * m_local.size()),
             static_cast<Eigen::Index>(input()->matrixSize()));
  m_J.setFromTriplets(m_triplets.begin(), m_triplets.end());
  return m_J;
}

}  // namespace stroma
