// SPDX-License-Identifier: MIT
// The condensed form of the precomputed/precomputed interface (seed 000 section 4.2.2.3, eqs.
// 4.6 and 4.7, after Bro-Nielsen and Cotin): with every zone precomputed, the interface
// displacements solve the Schur complement system
//
//   S u_G = g,   S = K_GG - sum_z K_GI^z (K_II^z)^-1 K_IG^z,
//                g = f_G  - sum_z K_GI^z (K_II^z)^-1 f_I^z,                    (eqs. 4.6, 4.7)
//
// G the nodes shared by zones (and the nodes given an imposed displacement, condensed too), I^z
// the other nodes of zone z, whose rows hold zone z's elements only. Each zone precomputes,
// with its interface held (Precomputed/kernels/DeformationBasis.h: G and the fixed nodes are
// the basis's fixed dofs), the response of its nodes to unit forces on the nodes next to G and
// on its loaded nodes; T^z = (K_II^z)^-1 K_IG^z follows. S is dense, factorised once. A solve
// is then exact: u_G from S, u_I^z = (K_II^z)^-1 f_I^z - T^z u_G (one "iteration").
#pragma once

#include <Eigen/Cholesky>
#include <optional>
#include <string>
#include <vector>

#include "DomainDecomposition/kernels/HybridDecomposition.h"

namespace stroma::domaindecomposition {

class CondensedInterface {
 public:
  /// `K` the stiffness (3n x 3n), `zoneNodes` the nodes of each zone, `fixed` per node,
  /// `imposedNodes` and `loadedNodes` (forces) global indices. False and `error` when a zone's
  /// interior or the condensed system is singular.
  bool setup(const RowMajorMatrix& K, const std::vector<std::vector<int>>& zoneNodes,
             const std::vector<char>& fixed, const std::vector<int>& imposedNodes,
             const std::vector<int>& loadedNodes, std::string& error);

  /// u (3n) for forces f (3n); the imposed nodes take their values from u on entry.
  void solve(const Eigen::VectorXd& f, Eigen::VectorXd& u) const;

  /// 3x3 blocks stored: the zones' responses and the condensed matrix.
  std::size_t storedTensors() const;

 private:
  struct Zone {
    std::vector<int> interior;     ///< global nodes of I^z (free)
    std::vector<int> gamma;        ///< positions in m_gamma of the zone's interface nodes
    std::vector<int> loaded;       ///< global loaded nodes of I^z
    Eigen::MatrixXd transfer;      ///< T^z, 3 |I^z| x 3 |gamma|
    Eigen::MatrixXd loadResponse;  ///< (K_II^z)^-1 on the loaded nodes, 3 |I^z| x 3 |loaded|
    Eigen::MatrixXd coupling;      ///< K_GI^z, 3 |gamma| x 3 |I^z|
  };
  std::vector<Zone> m_zones;
  std::vector<int> m_gamma;  ///< global nodes of G (free or imposed), sorted
  std::vector<char> m_imposedInGamma;
  std::vector<int> m_freeDofs, m_imposedDofs;  ///< dofs of G (positions in 3 |G|)
  Eigen::MatrixXd m_schur;                     ///< S, 3 |G| x 3 |G|
  Eigen::LDLT<Eigen::MatrixXd> m_factor;       ///< of S on the free dofs
};

}  // namespace stroma::domaindecomposition
