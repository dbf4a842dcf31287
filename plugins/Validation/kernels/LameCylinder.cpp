// SPDX-License-Identifier: MIT
#include "Validation/kernels/LameCylinder.h"

#include <cmath>

namespace stroma::reference {

bool LameCylinder::isValid() const {
  return std::isfinite(innerRadius) && std::isfinite(outerRadius) && std::isfinite(pressure) &&
         std::isfinite(youngModulus) && std::isfinite(poissonRatio) && innerRadius > 0 &&
         outerRadius > innerRadius && youngModulus > 0 && poissonRatio > -1 && poissonRatio <= 0.5;
}

double LameCylinder::radialDisplacement(double r) const {
  const double a2 = innerRadius * innerRadius, b2 = outerRadius * outerRadius;
  const double nu = poissonRatio;
  return (1 + nu) / youngModulus * pressure * a2 / (b2 - a2) * ((1 - 2 * nu) * r + b2 / r);
}

double LameCylinder::radialStress(double r) const {
  const double a2 = innerRadius * innerRadius, b2 = outerRadius * outerRadius;
  return pressure * a2 / (b2 - a2) * (1 - b2 / (r * r));
}

double LameCylinder::hoopStress(double r) const {
  const double a2 = innerRadius * innerRadius, b2 = outerRadius * outerRadius;
  return pressure * a2 / (b2 - a2) * (1 + b2 / (r * r));
}

Eigen::Vector3d LameCylinder::displacement(const Eigen::Vector3d& x) const {
  const double r = std::hypot(x.x(), x.y());
  if (r == 0) return Eigen::Vector3d::Zero();
  const double ur = radialDisplacement(r);
  return {ur * x.x() / r, ur * x.y() / r, 0};
}

}  // namespace stroma::reference
