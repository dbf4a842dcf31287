// SPDX-License-Identifier: MIT
// The mass of a rigid frame, as SOFA writes it in a scene: "mass volume inertia", where inertia
// is the 3x3 inertia matrix per unit mass in the body frame (9 numbers, row by row; SOFA also
// prints it as "[a b c,d e f,g h i]", which is read too). "mass" alone, or "mass volume", keep
// the identity inertia. The inertia of the body is mass * inertia.
#pragma once

#include <string>

#include "core/DataTraits.h"
#include "core/Types.h"

namespace stroma {

struct RigidMass3 {
  double mass = 1.0;
  double volume = 1.0;
  Mat3d inertia = Mat3d::Identity();  ///< per unit mass, body frame (m^2)

  bool operator==(const RigidMass3& o) const {
    return mass == o.mass && volume == o.volume && inertia == o.inertia;
  }
  /// mass * inertia, in the body frame (kg m^2).
  Mat3d bodyInertia() const { return mass * inertia; }
};

template <>
struct DataTraits<RigidMass3> {
  static std::string typeName() { return "rigid mass (mass volume inertia[9])"; }
  static bool parse(std::string_view text, RigidMass3& m, std::string& error) {
    // SOFA's matrix printing puts brackets and commas around the rows: read them as spaces.
    std::string cleaned(text);
    for (char& c : cleaned)
      if (c == '[' || c == ']' || c == ',') c = ' ';
    TokenReader in(cleaned);
    const std::size_t count = in.remaining();
    if (count != 1 && count != 2 && count != 11) {
      error =
          "expected 1 (mass), 2 (mass volume) or 11 (mass volume and a 3x3 inertia matrix "
          "per unit mass) numbers, got " +
          std::to_string(count);
      return false;
    }
    RigidMass3 parsed;
    if (!ElementTraits<double>::parseTokens(in, parsed.mass, error)) return false;
    if (count >= 2 && !ElementTraits<double>::parseTokens(in, parsed.volume, error)) return false;
    if (count == 11)
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
          if (!ElementTraits<double>::parseTokens(in, parsed.inertia(r, c), error)) return false;
    if (!std::isfinite(parsed.mass) || parsed.mass < 0 || !std::isfinite(parsed.volume) ||
        !parsed.inertia.allFinite()) {
      error = "expected a finite non-negative mass and finite volume and inertia";
      return false;
    }
    if ((parsed.inertia - parsed.inertia.transpose()).norm() > 1e-9 * parsed.inertia.norm()) {
      error = "the inertia matrix must be symmetric";
      return false;
    }
    m = parsed;
    return true;
  }
  static void print(std::string& out, const RigidMass3& m) {
    ElementTraits<double>::print(out, m.mass);
    out += ' ';
    ElementTraits<double>::print(out, m.volume);
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) {
        out += ' ';
        ElementTraits<double>::print(out, m.inertia(r, c));
      }
  }
};

}  // namespace stroma
