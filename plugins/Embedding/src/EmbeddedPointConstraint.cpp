// SPDX-License-Identifier: MIT
#include "EmbeddedPointConstraint.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <type_traits>

#include "core/Node.h"
#include "simulation/Mapping.h"

namespace stroma {

namespace {

using RowMatrix = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;

// A state vector of 3D values as an (n x 3) matrix (read-only for a const vector).
template <class Vector>
auto asMatrix(Vector& values) {
  using Matrix = std::conditional_t<std::is_const_v<Vector>, const RowMatrix, RowMatrix>;
  return Eigen::Map<Matrix>(values.empty() ? nullptr : values[0].data(),
                            static_cast<Eigen::Index>(values.size()), 3);
}

// First mechanical mapping from `state` in the subtree below `node`.
BaseMapping* mappingFrom(const Node& node, const BaseMechanicalState* state) {
  for (const auto& child : node.children()) {
    for (const auto& object : child->objects())
      if (auto* m = dynamic_cast<BaseMapping*>(object.get()); m && m->fromState() == state)
        return m;
    if (BaseMapping* m = mappingFrom(*child, state)) return m;
  }
  return nullptr;
}

}  // namespace

void EmbeddedPointConstraint::init() {
  ProjectiveConstraint<Vec3Types>::init();
  m_ready = false;
  const auto& times = d_keyTimes.value();
  if (d_movements.value().size() != times.size())
    msgError("has " + std::to_string(d_movements.value().size()) + " movements for " +
                 std::to_string(times.size()) + " key times: give one movement per key time",
             "movements");
  for (std::size_t k = 1; k < times.size(); ++k)
    if (times[k] < times[k - 1]) {
      msgError("key times must be in increasing order (keyTimes[" + std::to_string(k) + "])",
               "keyTimes");
      break;
    }
  if (d_indices.value().empty()) msgWarning("no index given: nothing is constrained", "indices");
}

BaseMapping* EmbeddedPointConstraint::findMapping() const {
  if (l_mapping) return dynamic_cast<BaseMapping*>(l_mapping.get());
  return node() ? mappingFrom(*node(), mstate()) : nullptr;
}

void EmbeddedPointConstraint::bwdInit() {
  m_ready = false;
  if (!mstate() || d_indices.value().empty()) return;
  BaseMapping* mapping = findMapping();
  if (!mapping) {
    msgError(l_mapping ? "the linked component is not a mapping"
                       : "no mapping from " + mstate()->path() +
                             " in the child nodes: link the embedding with mapping=\"@...\"",
             "mapping");
    return;
  }
  if (mapping->fromState() != mstate()) {
    msgError(mapping->path() + " does not map from " + mstate()->path(), "mapping");
    return;
  }
  if (!mapping->toState()) {
    msgError(mapping->path() + " maps to a visual model: its points cannot be constrained",
             "mapping");
    return;
  }
  const Eigen::SparseMatrix<double> J = mapping->jacobian();
  const std::size_t n = mstate()->size(), outputs = mapping->toState()->size();
  if (J.cols() != Eigen::Index(3 * n) || J.rows() != Eigen::Index(3 * outputs)) {
    msgError(mapping->path() + " is not a mapping between 3D points (J is " +
                 std::to_string(J.rows()) + " x " + std::to_string(J.cols()) + ")",
             "mapping");
    return;
  }
  const auto& indices = d_indices.value();
  for (unsigned i : indices)
    if (i >= outputs) {
      msgError("index " + std::to_string(i) + " is out of range of the " + std::to_string(outputs) +
                   " points of " + mapping->toState()->path(),
               "indices");
      return;
    }

  // H: the x rows of J for the constrained points; J must hold the same weight on x, y and z.
  const Eigen::SparseMatrix<double, Eigen::RowMajor> Jr = J;
  std::vector<Eigen::Triplet<double>> entries;
  for (std::size_t r = 0; r < indices.size(); ++r)
    for (int d = 0; d < 3; ++d)
      for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator e(Jr, 3 * indices[r] + d); e;
           ++e) {
        const bool diagonal = e.col() % 3 == d;
        const double x = diagonal ? Jr.coeff(3 * indices[r], e.col() - d) : 0.0;
        if (!diagonal || std::abs(e.value() - x) > 1e-14 * (1 + std::abs(x))) {
          msgError(mapping->path() + " does not move x, y and z with the same weights (point " +
                       std::to_string(indices[r]) + "): use a BarycentricMapping",
                   "mapping");
          return;
        }
        if (d == 0) entries.emplace_back(Eigen::Index(r), e.col() / 3, e.value());
      }
  m_H.resize(Eigen::Index(indices.size()), Eigen::Index(n));
  m_H.setFromTriplets(entries.begin(), entries.end());

  // G^+ by the eigen decomposition of G = H H^T (symmetric, semi-definite).
  const Eigen::MatrixXd G = Eigen::MatrixXd(m_H * m_H.transpose());
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(G);
  const Eigen::VectorXd& lambda = eigen.eigenvalues();
  const double cutoff = 1e-10 * std::max(lambda.maxCoeff(), 1e-300);
  Eigen::VectorXd inverse(lambda.size());
  Eigen::Index dropped = 0;
  for (Eigen::Index k = 0; k < lambda.size(); ++k) {
    inverse[k] = lambda[k] > cutoff ? 1.0 / lambda[k] : 0.0;
    dropped += lambda[k] <= cutoff;
  }
  m_Gplus = eigen.eigenvectors() * inverse.asDiagonal() * eigen.eigenvectors().transpose();
  if (dropped > 0)
    msgWarning(std::to_string(dropped) + " of the " + std::to_string(indices.size()) +
                   " constrained points depend on the others (the same weights, or more points "
                   "than nodes in a cell): H H^T is singular and the points are imposed in the "
                   "least-squares sense (pseudo-inverse)",
               "indices");
  m_p0 = pointsOf(mstate()->readCoord(VecId::restPosition()));
  m_ready = true;
}

Eigen::MatrixXd EmbeddedPointConstraint::pointsOf(const VecCoord& x) const {
  return m_H * asMatrix(x);
}

Vec3d EmbeddedPointConstraint::movementAt(double t) const {
  const auto& times = d_keyTimes.value();
  const auto& moves = d_movements.value();
  if (times.empty() || moves.size() != times.size() || t <= times.front())
    return times.empty() || moves.size() != times.size() ? Vec3d::Zero() : moves.front();
  if (t >= times.back()) return moves.back();
  const std::size_t k =
      std::size_t(std::upper_bound(times.begin(), times.end(), t) - times.begin()) - 1;
  const double span = times[k + 1] - times[k];
  const double s = span > 0 ? (t - times[k]) / span : 1.0;
  return (1 - s) * moves[k] + s * moves[k + 1];
}

Eigen::MatrixXd EmbeddedPointConstraint::targetsAt(double t) const {
  const Vec3d shift = d_displacement.value() + movementAt(t);
  return m_p0.rowwise() + shift.transpose();
}

template <class Vector>
void EmbeddedPointConstraint::correct(Vector& values, const Eigen::MatrixXd* target) const {
  if (!m_ready || values.size() != std::size_t(m_H.cols())) return;
  auto u = asMatrix(values);
  Eigen::MatrixXd gap = -(m_H * u);  // target - H u
  if (target) gap += *target;
  const Eigen::MatrixXd lagrange = m_Gplus * gap;
  u += m_H.transpose() * lagrange;
}

void EmbeddedPointConstraint::projectResponse(VecDeriv& dx) { correct(dx, nullptr); }

void EmbeddedPointConstraint::projectPosition(VecCoord& x, double time) {
  if (!m_ready) return;
  const Eigen::MatrixXd target = targetsAt(time);
  correct(x, &target);
}

void EmbeddedPointConstraint::projectVelocity(VecDeriv& v, double time) {
  if (!m_ready) return;
  // The mean velocity over the step [start, time] (or [time, time + dt] when given its start).
  const double start = node() ? node()->time() : time;
  const double t0 = time > start ? start : time;
  const double t1 = time > start ? time : time + (node() ? node()->dt() : 0.0);
  Eigen::MatrixXd target = Eigen::MatrixXd::Zero(m_H.rows(), 3);
  // The constant displacement has no velocity: it is imposed on the positions alone.
  if (t1 > t0) target.rowwise() = ((movementAt(t1) - movementAt(t0)) / (t1 - t0)).transpose();
  correct(v, &target);
}

void EmbeddedPointConstraint::fixedRows(std::vector<std::size_t>&) const {
  if (!m_ready || m_reportedAssembled) return;
  m_reportedAssembled = true;
  msgWarning(
      "the solver assembles the matrix, which cannot hold the projection on the motions "
      "that leave the embedded points in place: the solve is unconstrained and only the "
      "end of each step puts them back; use CGLinearSolver with its default (matrix-free) "
      "template",
      "");
}

}  // namespace stroma
