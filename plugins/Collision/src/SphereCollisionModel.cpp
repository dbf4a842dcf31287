// SPDX-License-Identifier: MIT
#include "SphereCollisionModel.h"

#include "core/Message.h"

namespace stroma {

template <class DataTypes>
void SphereCollisionModel<DataTypes>::init() {
  m_geometry.kind = PrimitiveKind::sphere;
  m_state = collision::findModelState<DataTypes>(*this);
  if (!m_state) return;
  const std::vector<double>& radii = d_listRadius.value();
  if (radii.empty()) {
    m_geometry.radii = std::span<const double>(&d_radius.value(), 1);
  } else {
    // As SOFA does: spheres without a radius in the list take `radius`; extra radii are unused.
    m_radii.assign(radii.begin(), radii.end());
    if (m_radii.size() != m_state->size())
      msgWarning("has " + std::to_string(radii.size()) + " radii for the " +
                     std::to_string(m_state->size()) + " points of " + m_state->path() +
                     (radii.size() < m_state->size()
                          ? ": the others take radius " + formatNumber(d_radius.value())
                          : ": the extra radii are unused") +
                     " (as in SOFA); give one per sphere",
                 "listRadius");
    m_radii.resize(m_state->size(), d_radius.value());
    m_geometry.radii = m_radii;
  }
  updateGeometry();
}

template <class DataTypes>
void SphereCollisionModel<DataTypes>::updateGeometry() {
  if (!m_state || !isValid()) return;
  const auto& x = m_state->readCoord(VecId::position());
  if constexpr (kRigid) {
    m_centers.resize(x.size());
    for (std::size_t i = 0; i < x.size(); ++i) m_centers[i] = x[i].center;
    m_geometry.points = m_centers;
  } else {
    m_geometry.points = x;
  }
}

template class SphereCollisionModel<Vec3Types>;
template class SphereCollisionModel<Rigid3Types>;

}  // namespace stroma
