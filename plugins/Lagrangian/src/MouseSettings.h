// SPDX-License-Identifier: MIT
// SOFA's mouse settings of its GUI: how a viewer's mouse drags the bodies it picks. Stroma's
// batch runs have no mouse: the settings are kept for the viewer (they are what it will read),
// and SOFA's scenes that carry them load unmodified.
#pragma once

#include <string>

#include "core/Base.h"
#include "core/Data.h"
#include "core/DataTraits.h"

namespace stroma {

/// SOFA's AttachBodyButtonSetting: a picked body is dragged by a spring of this stiffness.
class AttachBodyButtonSetting final : public Base {
 public:
  Data<double> d_stiffness{this, "stiffness", 1000.0, "Stiffness of the dragging spring.",
                           {.unit = "N/m", .min = 0.0}};
  Data<double> d_arrowSize{this, "arrowSize", 0.0, "Drawn size of the spring (0: a line).",
                           {.min = 0.0}};
  Data<double> d_showFactorSize{this, "showFactorSize", 1.0, "Drawn size of the picked point.",
                                {.min = 0.0}};
  Data<std::string> d_button{this, "button", "Left", "Mouse button: Left, Middle or Right."};

  void init() override { checkButton(*this, d_button.value()); }
  static void checkButton(Base& self, const std::string& button);
};

/// SOFA's ConstraintAttachButtonSetting: a picked body is dragged by a bilateral Lagrangian
/// constraint instead of a spring (under FreeMotionAnimationLoop).
class ConstraintAttachButtonSetting final : public Base {
 public:
  Data<std::string> d_button{this, "button", "Left", "Mouse button: Left, Middle or Right."};

  void init() override { AttachBodyButtonSetting::checkButton(*this, d_button.value()); }
};

inline void AttachBodyButtonSetting::checkButton(Base& self, const std::string& button) {
  if (button != "Left" && button != "Middle" && button != "Right")
    self.msgError("expected Left, Middle or Right, got '" + button + "'", "button");
}

}  // namespace stroma
