// SPDX-License-Identifier: MIT
#pragma once

#include <vector>

#include "core/Base.h"
#include "core/StateTypes.h"

namespace stroma::test {

/// A component templated on the kind of degrees of freedom (Vec3d, Rigid3d), to test that the
/// template is deduced from the node's mechanical state when the scene gives none.
template <class DataTypes>
class TestTemplated final : public Base {
 public:
  using Coord = typename DataTypes::Coord;

  Data<std::vector<Coord>> d_values{this, "values", {}, "Coordinates of the template's kind."};
};

}  // namespace stroma::test
