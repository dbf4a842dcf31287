// SPDX-License-Identifier: MIT
#include "IdentityMapping.h"

namespace stroma {

template <class DataTypes>
void IdentityMapping<DataTypes>::init() {
  if (!this->findStates()) return;
  m_options.warnUnsupported(*this, this->output() != nullptr);
  if (!this->output()) return;
  const bool resized = resizeOutput(*this->output(), this->input()->size());
  applyAtInit(*this, resized || m_options.applyRestPosition.value());
}

template <class DataTypes>
void IdentityMapping<DataTypes>::apply(OutVecCoord& out, const InVecCoord& in) {
  out.resize(in.size());
  std::copy(in.begin(), in.end(), out.begin());
}

template <class DataTypes>
void IdentityMapping<DataTypes>::applyJ(OutVecDeriv& out, const InVecDeriv& in) {
  out.resize(in.size());
  std::copy(in.begin(), in.end(), out.begin());
}

template <class DataTypes>
void IdentityMapping<DataTypes>::applyJT(InVecDeriv& in, const OutVecDeriv& out) {
  const std::size_t n = std::min(in.size(), out.size());
  for (std::size_t i = 0; i < n; ++i) {
    if constexpr (std::is_same_v<DataTypes, Rigid3Types>) {
      in[i].linear += out[i].linear;
      in[i].angular += out[i].angular;
    } else {
      in[i] += out[i];
    }
  }
}

template <class DataTypes>
const Eigen::SparseMatrix<double>& IdentityMapping<DataTypes>::jacobian() {
  const auto n = static_cast<Eigen::Index>(this->input()->matrixSize());
  if (m_J.rows() != n) {
    m_J.resize(n, n);
    m_J.setIdentity();
  }
  return m_J;
}

template class IdentityMapping<Vec3Types>;
template class IdentityMapping<Rigid3Types>;

}  // namespace stroma
