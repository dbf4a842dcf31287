// SPDX-License-Identifier: MIT
#include "SubsetMapping.h"

#include <limits>

namespace stroma {

void SubsetMapping::init() {
  if (!findStates()) return;
  m_options.warnUnsupported(*this, output() != nullptr);
  if (!output()) return;  // a visual output is prepared when first drawn (prepareVisual)
  if (!computeIndices(output()->readCoord(VecId::position()), VecId::position())) return;
  const bool resized = resizeOutput(*output(), d_indices.value().size());
  applyAtInit(*this, resized || m_options.applyRestPosition.value());
}

// A visual output is matched, when first drawn, to the input's points of the start.
bool SubsetMapping::prepareVisual(const OutVecCoord& points) {
  const bool started = input()->readCoord(VecId::resetPosition()).size() == input()->size();
  return computeIndices(points, started ? VecId::resetPosition() : VecId::position());
}

// The indices as given, from first..last, or by matching the output's points `xout` to the
// input's `inputPoints`; false after an error.
bool SubsetMapping::computeIndices(const std::vector<Vec3d>& xout, VecId inputPoints) {
  const std::size_t n = input()->size();
  if (!d_indices.value().empty()) {
    std::string bad;
    for (unsigned i : d_indices.value())
      if (i >= n) bad += (bad.empty() ? "" : " ") + std::to_string(i);
    if (!bad.empty()) {
      msgError("indices out of range of the " + std::to_string(n) + " input points: " + bad,
               "indices");
      return false;
    }
    return true;
  }
  const int first = d_first.value(), last = d_last.value();
  if (first >= 0 || last >= 0) {
    const int from = std::max(first, 0);
    const int to = last >= 0 ? last : static_cast<int>(n) - 1;
    if (to >= static_cast<int>(n) || from > to) {
      msgError("range first=" + std::to_string(first) + " last=" + std::to_string(last) +
                   " is not within the " + std::to_string(n) + " input points",
               last >= static_cast<int>(n) ? "last" : "first");
      return false;
    }
    std::vector<unsigned> range;
    for (int i = from; i <= to; ++i) range.push_back(static_cast<unsigned>(i));
    d_indices.setValue(std::move(range));
    return true;
  }
  // Match each output point to the nearest input point (brute force, once, at init).
  const auto& xin = input()->readCoord(inputPoints);
  const double radius = d_radius.value();
  std::vector<unsigned> found;
  std::size_t missing = 0, firstMissing = 0;
  for (std::size_t k = 0; k < xout.size(); ++k) {
    double best = std::numeric_limits<double>::infinity();
    std::size_t nearest = 0;
    for (std::size_t i = 0; i < xin.size(); ++i) {
      const double d = (xin[i] - xout[k]).squaredNorm();
      if (d < best) best = d, nearest = i;
    }
    if (std::sqrt(best) <= radius) {
      found.push_back(static_cast<unsigned>(nearest));
    } else if (missing++ == 0) {
      firstMissing = k;
    }
  }
  if (missing && !d_ignoreNotFound.value()) {
    msgError(std::to_string(missing) + " of the " + std::to_string(xout.size()) +
                 " output points (the first is " + std::to_string(firstMissing) +
                 ") have no input point within radius=" + d_radius.valueText() +
                 "; give indices, first/last, a larger radius or ignoreNotFound=true",
             "indices");
    return false;
  }
  if (missing)
    msgWarning(std::to_string(missing) +
                   " output points have no input point within radius; "
                   "they are dropped",
               "ignoreNotFound");
  d_indices.setValue(std::move(found));
  return true;
}

void SubsetMapping::apply(OutVecCoord& out, const InVecCoord& in) {
  const auto& indices = d_indices.value();
  out.resize(indices.size());
  for (std::size_t k = 0; k < indices.size(); ++k) out[k] = in[indices[k]];
}

void SubsetMapping::applyJ(OutVecDeriv& out, const InVecDeriv& in) {
  const auto& indices = d_indices.value();
  out.resize(indices.size());
  for (std::size_t k = 0; k < indices.size(); ++k) out[k] = in[indices[k]];
}

void SubsetMapping::applyJT(InVecDeriv& in, const OutVecDeriv& out) {
  const auto& indices = d_indices.value();
  for (std::size_t k = 0; k < indices.size() && k < out.size(); ++k) in[indices[k]] += out[k];
}

const Eigen::SparseMatrix<double>& SubsetMapping::jacobian() {
  // Constant: rebuilt only when the indices or the input's size changed.
  const auto& indices = d_indices.value();
  const auto columns = static_cast<Eigen::Index>(input()->matrixSize());
  if (m_jacobianVersion == d_indices.version() && m_J.cols() == columns) return m_J;
  m_jacobianVersion = d_indices.version();
  std::vector<Eigen::Triplet<double>> ones;
  ones.reserve(3 * indices.size());
  for (std::size_t k = 0; k < indices.size(); ++k)
    for (int c = 0; c < 3; ++c)
      ones.emplace_back(static_cast<int>(3 * k) + c, static_cast<int>(3 * indices[k]) + c, 1.0);
  m_J.resize(static_cast<Eigen::Index>(3 * indices.size()), columns);
  m_J.setFromTriplets(ones.begin(), ones.end());
  return m_J;
}

}  // namespace stroma
