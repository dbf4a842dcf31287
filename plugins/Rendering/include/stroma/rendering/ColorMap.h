// SPDX-License-Identifier: MIT
// Scalar fields on the points of a body, and the colors they are drawn with.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "core/Types.h"

namespace stroma {
class Node;
class BaseMechanicalState;
}  // namespace stroma

namespace stroma::rendering {

enum class ColorMapKind { none, displacement, vonMises };

/// "displacement" or "vonmises" (case-insensitive; "von-mises" too). Returns false on other
/// names; `error` then lists the known ones.
bool parseColorMapKind(std::string_view name, ColorMapKind& kind, std::string& error);
const char* colorMapName(ColorMapKind kind);
/// The unit of the field's numbers: "m" or "Pa".
const char* colorMapUnit(ColorMapKind kind);

/// One scalar per point of a state.
struct PointField {
  const BaseMechanicalState* state = nullptr;
  std::vector<double> values;
};

/// The fields of a kind on the scene under `root`: the displacement magnitude
/// |x - x_rest| of every Vec3d mechanical state that has rest positions, or the von Mises
/// stress per point of every force field that is a StressField. Returns false with `error`
/// when the scene has nothing to color (no such state; no force field provides stress).
bool computePointFields(const Node& root, ColorMapKind kind, std::vector<PointField>& fields,
                        std::string& error);

/// Smallest and largest value over every field (0 0 when all are empty).
void fieldRange(const std::vector<PointField>& fields, double& min, double& max);

/// The color of `t` in [0, 1] (clamped): dark blue, blue, cyan, green, yellow, red, a ramp
/// whose lightness grows with t up to yellow so that it still reads in grey.
Vec3d rampColor(double t);

/// How a legend writes a number: 3 significant digits, %g style ("0.0123", "1.5e+04").
std::string legendNumber(double value);

}  // namespace stroma::rendering
