// SPDX-License-Identifier: MIT
#pragma once

#include "core/Base.h"

namespace stroma {

/// Something that only draws (a rendered mesh, a light, a style). Batch runs never call it:
/// a scene's visual components are loaded and checked, and cost nothing per step.
class VisualModel : public Base {
 public:
  /// Brings what is drawn up to date; called by a renderer before drawing, never in batch.
  virtual void updateVisual() {}
};

}  // namespace stroma
