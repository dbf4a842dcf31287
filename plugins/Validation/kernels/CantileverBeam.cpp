// SPDX-License-Identifier: MIT
#include "Validation/kernels/CantileverBeam.h"

#include <algorithm>
#include <cmath>

namespace stroma::reference {

bool CantileverBeam::isValid() const {
  for (double v :
       {length, height, width, youngModulus, poissonRatio, tipForce, lineLoad, shearCorrection})
    if (!std::isfinite(v)) return false;
  return length > 0 && height > 0 && width > 0 && youngModulus > 0 && poissonRatio > -1 &&
         poissonRatio < 0.5 && shearCorrection >= 0;
}

double CantileverBeam::secondMomentOfArea() const { return width * height * height * height / 12; }

double CantileverBeam::effectiveShearCorrection() const {
  if (shearCorrection > 0) return shearCorrection;
  return 10 * (1 + poissonRatio) / (12 + 11 * poissonRatio);
}

double CantileverBeam::deflection(double s) const {
  s = std::clamp(s, 0.0, length);
  const double L = length, EI = youngModulus * secondMomentOfArea();
  const double P = tipForce, q = lineLoad;
  double w =
      P * s * s * (3 * L - s) / (6 * EI) + q * s * s * (6 * L * L - 4 * L * s + s * s) / (24 * EI);
  if (theory == BeamTheory::timoshenko) {
    const double kGA =
        effectiveShearCorrection() * youngModulus / (2 * (1 + poissonRatio)) * width * height;
    w += (P * s + q * (L * s - s * s / 2)) / kGA;
  }
  return w;
}

double CantileverBeam::slope(double s) const {
  s = std::clamp(s, 0.0, length);
  const double L = length, EI = youngModulus * secondMomentOfArea();
  const double P = tipForce, q = lineLoad;
  double dw = P * s * (2 * L - s) / (2 * EI) + q * s * (3 * L * L - 3 * L * s + s * s) / (6 * EI);
  if (theory == BeamTheory::timoshenko) {
    const double kGA =
        effectiveShearCorrection() * youngModulus / (2 * (1 + poissonRatio)) * width * height;
    dw += (P + q * (L - s)) / kGA;
  }
  return dw;
}

}  // namespace stroma::reference
