// SPDX-License-Identifier: MIT
#include "FemMaterial.h"

#include <cmath>

#include "SolidMechanics/kernels/IsotropicMaterial.h"
#include "core/Message.h"

namespace stroma {

std::optional<MaterialProblem> checkMaterial(std::span<const double> youngModulus,
                                             double poissonRatio, std::size_t elementCount,
                                             const char* elements) {
  if (youngModulus.size() != 1 && youngModulus.size() != elementCount)
    return MaterialProblem{"youngModulus", "expected one value or one per element (" +
                                               std::to_string(elementCount) + " " + elements +
                                               "), got " + std::to_string(youngModulus.size()) +
                                               " values"};
  for (std::size_t i = 0; i < youngModulus.size(); ++i)
    if (!(youngModulus[i] > 0) || !std::isfinite(youngModulus[i]))
      return MaterialProblem{
          "youngModulus",
          "expected values > 0, got " + formatNumber(youngModulus[i]) +
              (youngModulus.size() > 1 ? " for element " + std::to_string(i) : std::string())};
  if (!(poissonRatio > -1 && poissonRatio < 0.5))
    return MaterialProblem{"poissonRatio",
                           "expected -1 < poissonRatio < 0.5 (0.5 is incompressible: the "
                           "elasticity matrix would be infinite), got " +
                               formatNumber(poissonRatio)};
  if (!fem::isValidIsotropicMaterial(youngModulus[0], poissonRatio))
    return MaterialProblem{"youngModulus", "the material is out of the valid range"};
  return std::nullopt;
}

}  // namespace stroma
