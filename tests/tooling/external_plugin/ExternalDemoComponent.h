// SPDX-License-Identifier: MIT
#pragma once

#include "core/Base.h"

namespace externaldemo {

/// A component of a plugin built outside the Stroma tree: one Data with a unit and a range, and
/// an init() that reports its value, so that the install test sees the component created,
/// filled from the scene and initialized.
class ExternalDemoComponent final : public stroma::Base {
 public:
  stroma::Data<double> d_stiffness{this,
                                   "stiffness",
                                   1.0,
                                   "Stiffness the component reports at init.",
                                   {.unit = "N/m", .min = 0}};

  void init() override;
};

}  // namespace externaldemo
