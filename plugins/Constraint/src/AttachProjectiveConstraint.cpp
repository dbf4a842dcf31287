// SPDX-License-Identifier: MIT
#include "AttachProjectiveConstraint.h"

#include <string>

#include "core/IndexChecks.h"
#include "simulation/StateLinks.h"

namespace stroma {

namespace {

// The leaders' vector of the same kind: the same id for the standard vectors, the standard one
// for a solver's temporary (which a state outside the solver's system does not hold).
VecId leaderVector(VecId v, VecId standard) {
  return v.index < VecId::kFirstTemporary ? v : standard;
}

}  // namespace

void AttachProjectiveConstraint::init() {
  m_pairs.clear();
  m_leaders = resolveState<Vec3Types>(*this, l_object1, "object1");
  m_followers = resolveState<Vec3Types>(*this, l_object2, "object2");
  if (d_twoWay.value())
    msgError(
        "two-way attachment (the leaders also feel the followers) is not provided: set "
        "twoWay=\"0\" (the followers then follow, one way)",
        "twoWay");
  if (!m_leaders || !m_followers) return;
  const auto& leaders = d_indices1.value();
  const auto& followers = d_indices2.value();
  const auto& factors = d_constraintFactor.value();
  if (leaders.size() != followers.size()) {
    msgError("has " + std::to_string(followers.size()) + " indices for the " +
                 std::to_string(leaders.size()) + " of indices1: give one per pair",
             "indices2");
    return;
  }
  if (!factors.empty() && factors.size() != leaders.size()) {
    msgError("has " + std::to_string(factors.size()) + " factors for " +
                 std::to_string(leaders.size()) + " pairs: give one per pair, or none",
             "constraintFactor");
    return;
  }
  for (double f : factors)
    if (f != 0.0 && f != 1.0) {
      msgError("a factor of " + std::to_string(f) +
                   " is not provided: give 1 (attached) or 0 (released) per pair",
               "constraintFactor");
      return;
    }
  if (leaders.empty()) msgWarning("no pair given: nothing is attached", "indices1");
}

// The pairs are checked once every state has its points: a state may take them from a topology
// or a loader initialized after this component (a sibling node's grid).
void AttachProjectiveConstraint::bwdInit() {
  m_pairs.clear();
  if (!m_leaders || !m_followers || d_twoWay.value()) return;
  const auto& leaders = d_indices1.value();
  const auto& followers = d_indices2.value();
  const auto& factors = d_constraintFactor.value();
  if (leaders.size() != followers.size() || (!factors.empty() && factors.size() != leaders.size()))
    return;  // reported by init
  for (double f : factors)
    if (f != 0.0 && f != 1.0) return;  // reported by init
  const bool leadersOk = reportIndicesOutOfRange(*this, leaders, m_leaders->size(), "indices1",
                                                 "points of " + m_leaders->path());
  const bool followersOk = reportIndicesOutOfRange(*this, followers, m_followers->size(),
                                                   "indices2", "points of " + m_followers->path());
  if (!leadersOk || !followersOk) return;
  for (std::size_t k = 0; k < leaders.size(); ++k)
    if (factors.empty() || factors[k] == 1.0) m_pairs.emplace_back(leaders[k], followers[k]);
}

void AttachProjectiveConstraint::constrainResponse(VecId dx) {
  if (!m_followers) return;
  auto& d = m_followers->writeDeriv(dx);
  for (const auto& [leader, follower] : m_pairs)
    if (follower < d.size()) d[follower].setZero();
}

void AttachProjectiveConstraint::constrainVelocity(VecId v, double) {
  if (!m_followers || !m_leaders) return;
  const auto& lead = m_leaders->readDeriv(leaderVector(v, VecId::velocity()));
  auto& follow = m_followers->writeDeriv(v);
  for (const auto& [leader, follower] : m_pairs)
    if (leader < lead.size() && follower < follow.size()) follow[follower] = lead[leader];
}

void AttachProjectiveConstraint::constrainPosition(VecId x, double) {
  if (!m_followers || !m_leaders) return;
  const auto& lead = m_leaders->readCoord(leaderVector(x, VecId::position()));
  auto& follow = m_followers->writeCoord(x);
  for (const auto& [leader, follower] : m_pairs)
    if (leader < lead.size() && follower < follow.size()) follow[follower] = lead[leader];
}

void AttachProjectiveConstraint::fixedRows(std::vector<std::size_t>& rows) const {
  for (const auto& [leader, follower] : m_pairs)
    for (std::size_t k = 0; k < 3; ++k) rows.push_back(3 * std::size_t{follower} + k);
}

}  // namespace stroma
