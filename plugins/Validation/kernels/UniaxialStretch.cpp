// SPDX-License-Identifier: MIT
#include "Validation/kernels/UniaxialStretch.h"

#include <cmath>
#include <limits>

namespace stroma::reference {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

struct Lame {
  double lambda, mu;
};

Lame lameOf(double E, double nu) {
  return {E * nu / ((1 + nu) * (1 - 2 * nu)), E / (2 * (1 + nu))};
}

// Neo-Hookean lateral stretch: the root of g(t) = mu (t^2 - 1) + lambda_L ln(stretch t^2).
// g increases with t; Newton from t = 1 on s = ln t, where g is convex-free enough to converge
// monotonically once past the first step (guarded by a bracket all the same).
double neoHookeanLateralStretch(const Lame& m, double stretch) {
  double lo = 1e-12, hi = 1e12;
  double t = 1;
  for (int k = 0; k < 200; ++k) {
    const double g = m.mu * (t * t - 1) + m.lambda * std::log(stretch * t * t);
    if (g > 0)
      hi = t;
    else
      lo = t;
    const double dg = 2 * m.mu * t + 2 * m.lambda / t;
    double next = t - g / dg;
    if (!(next > lo && next < hi)) next = std::sqrt(lo * hi);  // bisection in log scale
    if (std::abs(next - t) <= 1e-15 * t) return next;
    t = next;
  }
  return t;
}

}  // namespace

bool UniaxialStretch::isValid() const {
  return std::isfinite(youngModulus) && std::isfinite(poissonRatio) && youngModulus > 0 &&
         poissonRatio > -1 && poissonRatio < 0.5;
}

double UniaxialStretch::lateralStretch(double stretch) const {
  if (!(stretch > 0)) return kNaN;
  const double nu = poissonRatio;
  switch (material) {
    case UniaxialMaterial::linear:
      return 1 - nu * (stretch - 1);
    case UniaxialMaterial::stVenantKirchhoff: {
      const double t2 = 1 - nu * (stretch * stretch - 1);
      return t2 > 0 ? std::sqrt(t2) : kNaN;
    }
    case UniaxialMaterial::neoHookean:
      return neoHookeanLateralStretch(lameOf(youngModulus, nu), stretch);
  }
  return kNaN;
}

double UniaxialStretch::nominalStress(double stretch) const {
  const double t = lateralStretch(stretch);
  if (std::isnan(t)) return kNaN;
  const double E = youngModulus;
  switch (material) {
    case UniaxialMaterial::linear:
      return E * (stretch - 1);
    case UniaxialMaterial::stVenantKirchhoff:
      return E * stretch * (stretch * stretch - 1) / 2;
    case UniaxialMaterial::neoHookean: {
      const Lame m = lameOf(E, poissonRatio);
      return (m.mu * (stretch * stretch - 1) + m.lambda * std::log(stretch * t * t)) / stretch;
    }
  }
  return kNaN;
}

double UniaxialStretch::stretchForNominalStress(double P) const {
  if (!std::isfinite(P)) return kNaN;
  if (material == UniaxialMaterial::linear) return 1 + P / youngModulus;
  // Bracket [lo, hi] on the monotone branch, then bisect to round-off.
  double lo = material == UniaxialMaterial::stVenantKirchhoff ? 1 / std::sqrt(3.0) : 1e-6;
  double hi = 2;
  const double pLo = nominalStress(lo);
  if (std::isnan(pLo) || P < pLo) return kNaN;
  while (true) {
    const double pHi = nominalStress(hi);
    if (std::isnan(pHi)) return kNaN;  // StVK: no lateral solution before reaching P
    if (pHi >= P) break;
    lo = hi;
    hi *= 2;
    if (hi > 1e6) return kNaN;
  }
  for (int k = 0; k < 200 && hi - lo > 1e-15 * hi; ++k) {
    const double mid = (lo + hi) / 2;
    const double pMid = nominalStress(mid);
    if (std::isnan(pMid) || pMid > P)
      hi = mid;
    else
      lo = mid;
  }
  return (lo + hi) / 2;
}

Eigen::Vector3d UniaxialStretch::displacement(const Eigen::Vector3d& X,
                                              const Eigen::Vector3d& origin,
                                              const Eigen::Vector3d& axis, double stretch) const {
  const Eigen::Vector3d d = X - origin;
  const Eigen::Vector3d along = d.dot(axis) * axis;
  return (stretch - 1) * along + (lateralStretch(stretch) - 1) * (d - along);
}

}  // namespace stroma::reference
