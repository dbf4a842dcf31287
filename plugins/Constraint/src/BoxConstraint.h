// SPDX-License-Identifier: MIT
#pragma once

#include <vector>

#include "core/StateTypes.h"
#include "simulation/ProjectiveConstraint.h"

namespace stroma {

/// Fixes every point that lies inside one of the axis-aligned boxes `box` (SOFA's
/// BoxConstraint): a FixedProjectiveConstraint whose indices are selected by the boxes.
///
/// The selection is made on the state's rest positions (as SOFA: the points where the body
/// starts), at init and again whenever `box` changes (checked at the start of each step); a
/// point on a face of a box is inside. The fixed points' forces, increments and velocities are
/// zeroed, and their rows and columns of an assembled matrix become the identity. A box with a
/// minimum above its maximum is an error naming the field and the box; it selects nothing.
class BoxConstraint final : public ProjectiveConstraint<Vec3Types> {
 public:
  Data<std::vector<Vec6d>> d_box{
      this, "box", {}, "Boxes 'xmin ymin zmin xmax ymax zmax' (nbBoxes x 6).", {.unit = "m"}};
  Data<std::vector<unsigned>> d_indices{
      this, "indices", {}, "Indices of the points inside the boxes, fixed.", {.output = true}};
  Data<bool> d_drawBoxes{this, "drawBoxes", false, "Viewers only."};
  Data<double> d_drawSize{this, "drawSize", 0.0, "Viewers only."};

  void init() override;
  void reinit() override { init(); }

  void projectResponse(VecDeriv& dx) override;
  void projectVelocity(VecDeriv& v, double time) override;
  void projectPosition(VecCoord&, double) override {}
  void fixedRows(std::vector<std::size_t>& rows) const override;

 private:
  /// Selects the points inside the boxes when `box` has changed since the last selection.
  void updateSelection();
  /// Reports each box with min > max (an error on `box` naming the box); false if there is one.
  bool checkBoxes();
  std::uint64_t m_selectedBoxes = 0;
};

}  // namespace stroma
