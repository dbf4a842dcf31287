// SPDX-License-Identifier: MIT
#include "OBBCollisionModel.h"

#include "core/Message.h"

namespace stroma {

void OBBCollisionModel::init() {
  m_geometry.kind = PrimitiveKind::box;
  m_state = nullptr;
  // The nearest state from the node up must hold frames: a box needs an orientation.
  BaseMechanicalState* nearest = node() ? node()->getUp<BaseMechanicalState>() : nullptr;
  if (nearest && !dynamic_cast<MechanicalState<Rigid3Types>*>(nearest)) {
    msgError("is for rigid frames (template Rigid3d): the state " + nearest->path() +
             " beside it is " + std::string(nearest->templateName()) +
             "; put it beside a Rigid3d MechanicalObject (mapped boxes of a deformable body are "
             "not provided)");
    return;
  }
  m_state = collision::findModelState<Rigid3Types>(*this);
  if (!m_state) return;
  m_halfExtents.clear();  // read again from extents
  const std::vector<Vec3d>& extents = d_extents.value();
  if (!extents.empty() && extents.size() != m_state->size())
    msgWarning("has " + std::to_string(extents.size()) + " extents for the " +
                   std::to_string(m_state->size()) + " frames of " + m_state->path() +
                   (extents.size() < m_state->size()
                        ? ": the others take defaultExtent " +
                              formatNumber(d_defaultExtent.value()) + " (as in SOFA)"
                        : ": the extra extents are unused") +
                   "; give one per frame",
               "extents");
  updateGeometry();
}

void OBBCollisionModel::updateGeometry() {
  if (!m_state || !isValid()) return;
  const auto& x = m_state->readCoord(VecId::position());
  if (m_halfExtents.size() != x.size()) {
    const std::vector<Vec3d>& extents = d_extents.value();
    m_halfExtents.assign(extents.begin(), extents.begin() + std::min(extents.size(), x.size()));
    m_halfExtents.resize(x.size(), Vec3d::Constant(d_defaultExtent.value()));
    m_centers.resize(x.size());
    m_boxes.resize(x.size());
  }
  for (std::size_t i = 0; i < x.size(); ++i) {
    m_centers[i] = x[i].center;
    m_boxes[i] = {x[i].center, x[i].orientation.normalized().toRotationMatrix(), m_halfExtents[i]};
  }
  m_geometry.points = m_centers;
  m_geometry.boxes = m_boxes;
}

}  // namespace stroma
