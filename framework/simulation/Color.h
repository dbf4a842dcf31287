// SPDX-License-Identifier: MIT
// Colors as SOFA scenes write them, for every component that draws.
#pragma once

#include <string>
#include <string_view>

#include "core/Types.h"

namespace stroma {

/// Reads a color: a name ("red", "lightgray", ...: SOFA's names), "#rrggbb" or "#rrggbbaa",
/// or three or four numbers in [0, 1] ("r g b" takes alpha 1). False with `error` otherwise.
bool parseColor(std::string_view text, Vec4d& rgba, std::string& error);

}  // namespace stroma
