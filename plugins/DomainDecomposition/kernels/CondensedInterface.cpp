// SPDX-License-Identifier: MIT
#include "DomainDecomposition/kernels/CondensedInterface.h"

#include <algorithm>
#include <numeric>

#include "DomainDecomposition/kernels/SingleDomainReference.h"

namespace stroma::domaindecomposition {
namespace {

/// The dense block K[rows, cols] (3 |rows| x 3 |cols|) of node lists.
Eigen::MatrixXd denseBlock(const RowMajorMatrix& K, const std::vector<int>& rows,
                           const std::vector<int>& cols, std::size_t pointCount) {
  std::vector<int> column(pointCount, -1);
  for (std::size_t j = 0; j < cols.size(); ++j) column[cols[j]] = static_cast<int>(j);
  Eigen::MatrixXd block = Eigen::MatrixXd::Zero(3 * rows.size(), 3 * cols.size());
  for (std::size_t i = 0; i < rows.size(); ++i)
    for (int c = 0; c < 3; ++c)
      for (RowMajorMatrix::InnerIterator it(K, 3 * rows[i] + c); it; ++it) {
        const int j = column[it.col() / 3];
        if (j >= 0) block(3 * i + c, 3 * j + it.col() % 3) = it.value();
      }
  return block;
}

}  // namespace

bool CondensedInterface::setup(const RowMajorMatrix& K,
                               const std::vector<std::vector<int>>& zoneNodes,
                               const std::vector<char>& fixed, const std::vector<int>& imposedNodes,
                               const std::vector<int>& loadedNodes, std::string& error) {
  const std::size_t n = fixed.size();
  // G: the free nodes of several zones, and the imposed nodes.
  std::vector<int> zonesAt(n, 0);
  for (const auto& nodes : zoneNodes)
    for (int p : nodes) ++zonesAt[p];
  std::vector<char> imposed(n, 0), loaded(n, 0);
  for (int p : imposedNodes) imposed[p] = 1;
  for (int p : loadedNodes) loaded[p] = 1;
  m_gamma.clear();
  for (std::size_t p = 0; p < n; ++p)
    if (!fixed[p] && (zonesAt[p] > 1 || imposed[p])) m_gamma.push_back(static_cast<int>(p));
  std::vector<int> gammaIndex(n, -1);
  for (std::size_t k = 0; k < m_gamma.size(); ++k) gammaIndex[m_gamma[k]] = static_cast<int>(k);

  m_schur = denseBlock(K, m_gamma, m_gamma, n);
  m_zones.assign(zoneNodes.size(), Zone{});
  for (std::size_t z = 0; z < zoneNodes.size(); ++z) {
    Zone& zone = m_zones[z];
    std::vector<int> gammaNodes, heldNodes;
    for (int p : zoneNodes[z]) {
      if (gammaIndex[p] >= 0) {
        zone.gamma.push_back(gammaIndex[p]);
        gammaNodes.push_back(p);
      } else if (fixed[p]) {
        heldNodes.push_back(p);
      } else {
        zone.interior.push_back(p);
        if (loaded[p]) zone.loaded.push_back(p);
      }
    }
    if (zone.interior.empty()) continue;
    // The interior nodes next to G: the columns of K_IG that are not zero.
    zone.coupling = denseBlock(K, gammaNodes, zone.interior, n);
    std::vector<int> ring;
    for (std::size_t i = 0; i < zone.interior.size(); ++i)
      if (!zone.coupling.middleCols(3 * i, 3).isZero(0)) ring.push_back(static_cast<int>(i));
    // Zone block over I, G and its fixed nodes, G and the fixed nodes held: K_F^-1 = K_II^-1.
    std::vector<int> local = zone.interior;
    local.insert(local.end(), gammaNodes.begin(), gammaNodes.end());
    local.insert(local.end(), heldNodes.begin(), heldNodes.end());
    std::vector<int> heldDofs;
    for (std::size_t i = zone.interior.size(); i < local.size(); ++i)
      for (int c = 0; c < 3; ++c) heldDofs.push_back(static_cast<int>(3 * i) + c);
    std::vector<int> basisNodes = ring;
    for (int p : zone.loaded)
      basisNodes.push_back(static_cast<int>(
          std::lower_bound(zone.interior.begin(), zone.interior.end(), p) - zone.interior.begin()));
    std::sort(basisNodes.begin(), basisNodes.end());
    basisNodes.erase(std::unique(basisNodes.begin(), basisNodes.end()), basisNodes.end());
    std::string why;
    const auto basis = precomputed::DeformationBasis::compute(extractNodeBlock(K, local, n),
                                                              heldDofs, basisNodes, why);
    if (!basis) {
      error = "zone " + std::to_string(z) + " (condensed interface): " + why;
      return false;
    }
    const Eigen::MatrixXd& B = basis->columns();  // rows: every local node, in order
    const Eigen::Index rows = 3 * static_cast<Eigen::Index>(zone.interior.size());
    // T = K_II^-1 K_IG: K_IG = coupling^T is non-zero on the ring rows only.
    zone.transfer = Eigen::MatrixXd::Zero(rows, 3 * gammaNodes.size());
    for (int r : ring) {
      const int b = basis->basisIndex(r);
      zone.transfer += B.block(0, 3 * b, rows, 3) * zone.coupling.middleCols(3 * r, 3).transpose();
    }
    zone.loadResponse.resize(rows, 3 * zone.loaded.size());
    for (std::size_t l = 0; l < zone.loaded.size(); ++l) {
      const int i = static_cast<int>(
          std::lower_bound(zone.interior.begin(), zone.interior.end(), zone.loaded[l]) -
          zone.interior.begin());
      zone.loadResponse.middleCols(3 * l, 3) = B.block(0, 3 * basis->basisIndex(i), rows, 3);
    }
    // S -= K_GI T (eq. 4.6's L12 K2^-1 L21).
    const Eigen::MatrixXd reduction = zone.coupling * zone.transfer;
    for (std::size_t a = 0; a < zone.gamma.size(); ++a)
      for (std::size_t b = 0; b < zone.gamma.size(); ++b)
        m_schur.block<3, 3>(3 * zone.gamma[a], 3 * zone.gamma[b]) -=
            reduction.block<3, 3>(3 * a, 3 * b);
  }
  // The imposed dofs of G are known: S is factorised on the others.
  m_freeDofs.clear();
  m_imposedDofs.clear();
  for (std::size_t k = 0; k < m_gamma.size(); ++k)
    for (int c = 0; c < 3; ++c)
      (imposed[m_gamma[k]] ? m_imposedDofs : m_freeDofs).push_back(static_cast<int>(3 * k) + c);
  const Eigen::Index free = static_cast<Eigen::Index>(m_freeDofs.size());
  Eigen::MatrixXd Sff(free, free);
  for (Eigen::Index a = 0; a < free; ++a)
    for (Eigen::Index b = 0; b < free; ++b) Sff(a, b) = m_schur(m_freeDofs[a], m_freeDofs[b]);
  m_factor.compute(Sff);
  if (free > 0 && (m_factor.info() != Eigen::Success || (m_factor.vectorD().array() <= 0).any())) {
    error = "the condensed interface system is singular (a group of zones with no fixed node)";
    return false;
  }
  return true;
}

void CondensedInterface::solve(const Eigen::VectorXd& f, Eigen::VectorXd& u) const {
  // g = f_G - sum_z K_GI^z w^z, w^z = (K_II^z)^-1 f_I^z.
  Eigen::VectorXd g(3 * m_gamma.size());
  for (std::size_t k = 0; k < m_gamma.size(); ++k)
    g.segment<3>(3 * k) = f.segment<3>(3 * m_gamma[k]);
  std::vector<Eigen::VectorXd> w(m_zones.size());
  for (std::size_t z = 0; z < m_zones.size(); ++z) {
    const Zone& zone = m_zones[z];
    if (zone.interior.empty()) continue;
    Eigen::VectorXd load(3 * zone.loaded.size());
    for (std::size_t l = 0; l < zone.loaded.size(); ++l)
      load.segment<3>(3 * l) = f.segment<3>(3 * zone.loaded[l]);
    w[z] = zone.loadResponse * load;
    const Eigen::VectorXd reduced = zone.coupling * w[z];
    for (std::size_t a = 0; a < zone.gamma.size(); ++a)
      g.segment<3>(3 * zone.gamma[a]) -= reduced.segment<3>(3 * a);
  }
  // S_FF u_F = g_F - S_FD d.
  Eigen::VectorXd uG(3 * m_gamma.size());
  for (std::size_t k = 0; k < m_gamma.size(); ++k)
    uG.segment<3>(3 * k) = u.segment<3>(3 * m_gamma[k]);
  Eigen::VectorXd rhs(m_freeDofs.size());
  for (std::size_t a = 0; a < m_freeDofs.size(); ++a) {
    rhs[a] = g[m_freeDofs[a]];
    for (int d : m_imposedDofs) rhs[a] -= m_schur(m_freeDofs[a], d) * uG[d];
  }
  const Eigen::VectorXd uF =
      m_freeDofs.empty() ? Eigen::VectorXd() : Eigen::VectorXd(m_factor.solve(rhs));
  for (std::size_t a = 0; a < m_freeDofs.size(); ++a) uG[m_freeDofs[a]] = uF[a];
  for (std::size_t k = 0; k < m_gamma.size(); ++k)
    u.segment<3>(3 * m_gamma[k]) = uG.segment<3>(3 * k);
  // u_I = w - T u_G, zone by zone.
  for (std::size_t z = 0; z < m_zones.size(); ++z) {
    const Zone& zone = m_zones[z];
    if (zone.interior.empty()) continue;
    Eigen::VectorXd uZone(3 * zone.gamma.size());
    for (std::size_t a = 0; a < zone.gamma.size(); ++a)
      uZone.segment<3>(3 * a) = uG.segment<3>(3 * zone.gamma[a]);
    const Eigen::VectorXd uI = w[z] - zone.transfer * uZone;
    for (std::size_t i = 0; i < zone.interior.size(); ++i)
      u.segment<3>(3 * zone.interior[i]) = uI.segment<3>(3 * i);
  }
}

std::size_t CondensedInterface::storedTensors() const {
  std::size_t count = static_cast<std::size_t>(m_schur.size()) / 9;
  for (const Zone& zone : m_zones)
    count += static_cast<std::size_t>(zone.transfer.size() + zone.loadResponse.size() +
                                      zone.coupling.size()) /
             9;
  return count;
}

}  // namespace stroma::domaindecomposition
