// SPDX-License-Identifier: MIT
#pragma once

#include <vector>

namespace stroma {

class BaseMechanicalState;

/// A force field that can tell the stress in its body, for pictures and exports (color maps,
/// VTU fields). Nothing asks for it during a run: it is computed on demand from the current
/// positions. Force fields implement it beside their force-field base (found by dynamic_cast).
class StressField {
 public:
  virtual ~StressField() = default;
  /// The state whose points the stresses below refer to.
  virtual const BaseMechanicalState* stressState() const = 0;
  /// Von Mises stress of each element at the current positions, in the order of the elements
  /// of the field's topology (tetrahedra or hexahedra), in the units of the Young modulus.
  /// Returns false when it cannot be computed now.
  virtual bool vonMisesPerElement(std::vector<double>& stress) const = 0;
  /// Von Mises stress at each point of stressState(): the mean of the elements around it
  /// (points in no element get 0).
  virtual bool vonMisesPerPoint(std::vector<double>& stress) const = 0;
};

}  // namespace stroma
