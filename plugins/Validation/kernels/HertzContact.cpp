// SPDX-License-Identifier: MIT
#include "HertzContact.h"

#include <cmath>
#include <limits>

namespace stroma::reference {

bool HertzContact::isValid() const {
  return std::isfinite(youngModulus) && youngModulus > 0 && std::isfinite(poissonRatio) &&
         poissonRatio > -1 && poissonRatio < 0.5 && std::isfinite(radius) && radius > 0;
}

double HertzContact::effectiveModulus() const {
  return youngModulus / (1 - poissonRatio * poissonRatio);
}

double HertzContact::force(double indentation) const {
  if (!(indentation > 0)) return 0;
  return 4.0 / 3.0 * effectiveModulus() * std::sqrt(radius) * std::pow(indentation, 1.5);
}

double HertzContact::axisLag(double indentation, double depth) const {
  if (!(indentation > 0)) return 0;
  const double nu = poissonRatio;
  const double zeta = depth / std::sqrt(radius * indentation);
  if (!(zeta > 0)) return indentation;
  const double inverse = std::atan(1 / zeta);
  // (1 + zeta^2) atan(1/zeta) - zeta loses digits to cancellation far away: its series there.
  const double z2 = zeta * zeta;
  const double excess =
      zeta > 100 ? (2.0 / 3 - (2.0 / 15 - 2.0 / (35 * z2)) / z2) / zeta : (1 + z2) * inverse - zeta;
  return indentation * 2 / (M_PI * (1 - nu)) * (inverse - nu * excess);
}

double HertzContact::indentationForApproachAt(double approach, double depth) const {
  if (!(approach > 0)) return 0;
  // d = delta + u(z; d): u grows like sqrt(d), so the iteration contracts while u < d / 2.
  double d = approach;
  for (int k = 0; k < 200; ++k) {
    const double next = approach + axisLag(d, depth);
    if (!std::isfinite(next) || axisLag(next, depth) >= next / 2) break;
    if (std::abs(next - d) <= 1e-15 * next) return next;
    d = next;
  }
  return std::numeric_limits<double>::quiet_NaN();
}

}  // namespace stroma::reference
