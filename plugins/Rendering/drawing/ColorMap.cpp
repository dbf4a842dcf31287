// SPDX-License-Identifier: MIT
#include "stroma/rendering/ColorMap.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>

#include "SceneReading.h"
#include "core/Node.h"
#include "core/StateTypes.h"
#include "simulation/MechanicalState.h"
#include "simulation/StressField.h"

namespace stroma::rendering {

bool parseColorMapKind(std::string_view name, ColorMapKind& kind, std::string& error) {
  std::string lower;
  for (char c : name)
    if (c != '-' && c != '_')
      lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (lower == "displacement") {
    kind = ColorMapKind::displacement;
    return true;
  }
  if (lower == "vonmises") {
    kind = ColorMapKind::vonMises;
    return true;
  }
  error = "unknown color map '" + std::string(name) + "' (known: displacement, vonmises)";
  return false;
}

const char* colorMapName(ColorMapKind kind) {
  switch (kind) {
    case ColorMapKind::displacement:
      return "displacement";
    case ColorMapKind::vonMises:
      return "von Mises stress";
    case ColorMapKind::none:
      break;
  }
  return "none";
}

const char* colorMapUnit(ColorMapKind kind) {
  return kind == ColorMapKind::vonMises ? "Pa" : kind == ColorMapKind::displacement ? "m" : "";
}

bool computePointFields(const Node& root, ColorMapKind kind, std::vector<PointField>& fields,
                        std::string& error) {
  fields.clear();
  if (kind == ColorMapKind::displacement) {
    forEachObject(root, [&](Base& object) {
      const auto* state = dynamic_cast<const MechanicalState<Vec3Types>*>(&object);
      if (!state) return;
      const auto& x = state->readCoord(VecId::position());
      const auto& rest = state->readCoord(VecId::restPosition());
      if (x.empty() || rest.size() != x.size()) return;
      PointField field{state, std::vector<double>(x.size())};
      for (std::size_t i = 0; i < x.size(); ++i) field.values[i] = (x[i] - rest[i]).norm();
      fields.push_back(std::move(field));
    });
    if (fields.empty())
      error = "no 3D mechanical state with rest positions to measure a displacement from";
  } else if (kind == ColorMapKind::vonMises) {
    bool anyStressField = false;
    forEachObject(root, [&](Base& object) {
      const auto* stress = dynamic_cast<const StressField*>(&object);
      if (!stress) return;
      anyStressField = true;
      PointField field{stress->stressState(), {}};
      if (field.state && stress->vonMisesPerPoint(field.values) && !field.values.empty())
        fields.push_back(std::move(field));
    });
    if (fields.empty())
      error = anyStressField ? "the force fields that provide stress could not compute it now"
                             : "no force field of the scene provides stress (StressField): von "
                               "Mises colors need an FEM force field that computes it";
  } else {
    error = "no color map asked for";
  }
  return !fields.empty();
}

void fieldRange(const std::vector<PointField>& fields, double& min, double& max) {
  bool any = false;
  min = max = 0;
  for (const PointField& f : fields)
    for (double v : f.values) {
      if (!std::isfinite(v)) continue;
      min = any ? std::min(min, v) : v;
      max = any ? std::max(max, v) : v;
      any = true;
    }
}

Vec3d rampColor(double t) {
  if (!std::isfinite(t)) t = 0;
  t = std::clamp(t, 0.0, 1.0);
  // Stops of the ramp, evenly spaced.
  static const Vec3d kStops[] = {{0.10, 0.05, 0.45}, {0.10, 0.35, 0.95}, {0.10, 0.80, 0.90},
                                 {0.30, 0.85, 0.30}, {0.98, 0.90, 0.15}, {0.85, 0.10, 0.10}};
  constexpr int kSegments = static_cast<int>(std::size(kStops)) - 1;
  const double s = t * kSegments;
  const int i = std::min(static_cast<int>(s), kSegments - 1);
  const double u = s - i;
  return (1 - u) * kStops[i] + u * kStops[i + 1];
}

std::string legendNumber(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", value);
  return text;
}

}  // namespace stroma::rendering
