// SPDX-License-Identifier: MIT
#pragma once

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

namespace stroma {

/// Eigen's SimplicialLDLT (lower triangle, AMD ordering) whose numeric factorization writes the
/// permuted matrix into storage kept from one factorization to the next: Eigen's factorize()
/// builds a new permuted copy each time (two heap allocations a solve, every step of a scene
/// with a direct solver). Same arithmetic, same factors.
class ReusingLDLT : public Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower> {
 public:
  void factorize(const Eigen::SparseMatrix<double>& a) {
    if (m_P.size() == 0) {  // no ordering (not the case with AMD): Eigen's own path
      Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower>::factorize(a);
      return;
    }
    m_permuted.selfadjointView<Eigen::Upper>() =
        a.selfadjointView<Eigen::Lower>().twistedBy(m_P);
    factorize_preordered<true>(m_permuted);
  }

 private:
  Eigen::SparseMatrix<double> m_permuted;  // P A P^T, upper triangle
};

}  // namespace stroma
