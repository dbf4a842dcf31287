// SPDX-License-Identifier: MIT
#include "TensorMass/kernels/TetrahedronTensors.h"

#include <cmath>

namespace stroma::tensormass {

TetrahedronTensors::TetrahedronTensors(const fem::TetrahedronShape& shape,
                                       const fem::LameParameters& lame)
    : m_alpha(shape.gradients),
      m_dot(shape.gradients.transpose() * shape.gradients),
      m_volume(std::abs(shape.volume)),
      m_lambda(lame.lambda),
      m_mu(lame.mu) {}

Eigen::Matrix3d TetrahedronTensors::B(int j, int k) const {
  const auto aj = m_alpha.col(j), ak = m_alpha.col(k);
  return m_volume *
         (0.5 * m_lambda * aj * ak.transpose() +
          0.5 * m_mu * (ak * aj.transpose() + m_dot(j, k) * Eigen::Matrix3d::Identity()));
}

Eigen::Vector3d TetrahedronTensors::C(int j, int k, int l) const {
  return m_volume * (0.5 * m_lambda * m_alpha.col(j) * m_dot(k, l) +
                     0.5 * m_mu * (m_alpha.col(l) * m_dot(j, k) + m_alpha.col(k) * m_dot(j, l)));
}

double TetrahedronTensors::D(int j, int k, int l, int m) const {
  return m_volume *
         (m_lambda / 8 * m_dot(j, k) * m_dot(l, m) + m_mu / 4 * m_dot(j, m) * m_dot(k, l));
}

Eigen::Matrix3d TetrahedronTensors::stiffness(int j, int k) const { return 2 * B(j, k); }

Eigen::Vector3d TetrahedronTensors::cubic(int j, int k, int l) const {
  return k == l ? C(j, k, k) : Eigen::Vector3d(C(j, k, l) + C(j, l, k));
}

double TetrahedronTensors::quartic(int j, int k, int l, int m) const {
  // Every ordered (p1 p2 q1 q2) whose product (U_p1.U_p2)(U_q1.U_q2) is this one: both orders
  // of each pair, and the two pairs swapped when they differ.
  const bool samePair = (j == l && k == m) || (j == m && k == l);
  double sum = 0;
  const int firstPair[2][2] = {{j, k}, {k, j}};
  const int secondPair[2][2] = {{l, m}, {m, l}};
  for (int a = 0; a < (j == k ? 1 : 2); ++a)
    for (int b = 0; b < (l == m ? 1 : 2); ++b) {
      const int* p = firstPair[a];
      const int* q = secondPair[b];
      sum += D(p[0], p[1], q[0], q[1]);
      if (!samePair) sum += D(q[0], q[1], p[0], p[1]);
    }
  return sum;
}

}  // namespace stroma::tensormass
