// SPDX-License-Identifier: MIT
#include "BoxConstraint.h"

#include <string>

namespace stroma {

namespace {

/// True when p is inside the box b = (min, max), faces included.
bool inside(const Vec6d& b, const Vec3d& p) {
  for (int k = 0; k < 3; ++k)
    if (p[k] < b[k] || p[k] > b[k + 3]) return false;
  return true;
}

bool isOrdered(const Vec6d& b) { return b[0] <= b[3] && b[1] <= b[4] && b[2] <= b[5]; }

}  // namespace

void BoxConstraint::init() {
  ProjectiveConstraint<Vec3Types>::init();
  if (!mstate()) return;
  if (d_box.value().empty()) msgWarning("no box given: nothing is fixed", "box");
  m_selectedBoxes = 0;
  updateSelection();
}

bool BoxConstraint::checkBoxes() {
  bool ok = true;
  const auto& boxes = d_box.value();
  for (std::size_t b = 0; b < boxes.size(); ++b)
    for (int k = 0; k < 3; ++k)
      if (boxes[b][k] > boxes[b][k + 3]) {
        msgError("box " + std::to_string(b) + " has min > max along " + "xyz"[k] + " (" +
                     std::to_string(boxes[b][k]) + " > " + std::to_string(boxes[b][k + 3]) +
                     "): give 'xmin ymin zmin xmax ymax zmax'; this box selects nothing",
                 "box");
        ok = false;
        break;
      }
  return ok;
}

void BoxConstraint::updateSelection() {
  if (!mstate() || d_box.version() == m_selectedBoxes) return;
  m_selectedBoxes = d_box.version();
  checkBoxes();
  // The rest positions: where the body starts, whatever it has moved since (SOFA).
  const VecCoord& x0 = mstate()->readCoord(VecId::restPosition());
  std::vector<unsigned> selected;
  for (std::size_t i = 0; i < x0.size(); ++i)
    for (const Vec6d& b : d_box.value())
      if (isOrdered(b) && inside(b, x0[i])) {
        selected.push_back(static_cast<unsigned>(i));
        break;
      }
  d_indices.setValue(std::move(selected));
}

void BoxConstraint::projectResponse(VecDeriv& dx) {
  for (unsigned i : d_indices.value())
    if (i < dx.size()) dx[i] = Vec3Types::zeroDeriv();
}

void BoxConstraint::projectVelocity(VecDeriv& v, double) {
  updateSelection();  // every step starts with this projection
  for (unsigned i : d_indices.value())
    if (i < v.size()) v[i] = Vec3Types::zeroDeriv();
}

void BoxConstraint::fixedRows(std::vector<std::size_t>& rows) const {
  for (unsigned i : d_indices.value())
    for (std::size_t k = 0; k < 3; ++k) rows.push_back(3 * std::size_t{i} + k);
}

}  // namespace stroma
