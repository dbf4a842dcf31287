// SPDX-License-Identifier: MIT
#include "Validation/kernels/CylinderTorsion.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>

namespace stroma::reference {

bool CylinderTorsion::isValid() const {
  for (double v : {radius, length, torque, youngModulus, poissonRatio})
    if (!std::isfinite(v)) return false;
  return radius > 0 && length > 0 && youngModulus > 0 && poissonRatio > -1 && poissonRatio < 0.5;
}

double CylinderTorsion::polarMomentOfArea() const {
  return std::numbers::pi * std::pow(radius, 4) / 2;
}

double CylinderTorsion::twistAngle(double s) const {
  const double G = youngModulus / (2 * (1 + poissonRatio));
  return torque * std::clamp(s, 0.0, length) / (G * polarMomentOfArea());
}

Eigen::Vector3d CylinderTorsion::displacement(const Eigen::Vector3d& X,
                                              const Eigen::Vector3d& origin,
                                              const Eigen::Vector3d& axis) const {
  const Eigen::Vector3d d = X - origin;
  const double s = d.dot(axis);
  return twistAngle(s) * axis.cross(d - s * axis);
}

}  // namespace stroma::reference
