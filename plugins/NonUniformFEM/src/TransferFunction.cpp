// SPDX-License-Identifier: MIT
#include "TransferFunction.h"

#include <algorithm>
#include <cmath>

#include "core/Message.h"

namespace stroma::nonuniform {

std::optional<TransferFunction> TransferFunction::parse(std::span<const double> pairs,
                                                        double minimum, bool strict,
                                                        std::string& why) {
  if (pairs.empty() || pairs.size() % 2 != 0) {
    why = "expected pairs 'imageValue value ...', got " + std::to_string(pairs.size()) + " numbers";
    return std::nullopt;
  }
  TransferFunction f;
  for (std::size_t k = 0; k < pairs.size(); k += 2) {
    const double v = pairs[k], y = pairs[k + 1];
    if (!std::isfinite(v) || !std::isfinite(y)) {
      why = "expected finite numbers, got " + formatNumber(v) + " " + formatNumber(y);
      return std::nullopt;
    }
    if (!f.m_inputs.empty() && !(v > f.m_inputs.back())) {
      why = "expected strictly increasing image values, got " + formatNumber(v) + " after " +
            formatNumber(f.m_inputs.back());
      return std::nullopt;
    }
    // Linear pieces between valid points stay valid: checking the points is enough.
    if (y < minimum || (strict && y == minimum)) {
      why = "gives " + formatNumber(y) + " at image value " + formatNumber(v) + ", expected a value " +
            (strict ? "> " : ">= ") + formatNumber(minimum);
      return std::nullopt;
    }
    f.m_inputs.push_back(v);
    f.m_outputs.push_back(y);
  }
  return f;
}

double TransferFunction::operator()(double imageValue) const {
  if (imageValue <= m_inputs.front()) return m_outputs.front();
  if (imageValue >= m_inputs.back()) return m_outputs.back();
  const auto upper = std::upper_bound(m_inputs.begin(), m_inputs.end(), imageValue);
  const std::size_t k = std::size_t(upper - m_inputs.begin());
  const double t = (imageValue - m_inputs[k - 1]) / (m_inputs[k] - m_inputs[k - 1]);
  return m_outputs[k - 1] + t * (m_outputs[k] - m_outputs[k - 1]);
}

}  // namespace stroma::nonuniform
