// SPDX-License-Identifier: MIT
#include "SpringForceField.h"

#include "SpringKernel.h"
#include "core/Node.h"

namespace stroma {

template <class DataTypes>
typename SpringForceField<DataTypes>::State* SpringForceField<DataTypes>::resolveState(
    const Link<Base>& link) {
  Base* target = link.get();
  if (auto* state = dynamic_cast<State*>(target)) return state;
  if (auto* node = dynamic_cast<Node*>(target)) {
    if (auto* state = node->get<State>()) return state;
    msgError("node " + node->path() + " has no " + DataTypes::name + " mechanical state",
             link.name());
    return nullptr;
  }
  msgError(target->path() + " is a " + target->className() + ", not a " + DataTypes::name +
               " mechanical state (or a node holding one)",
           link.name());
  return nullptr;
}

template <class DataTypes>
bool SpringForceField<DataTypes>::validate(const std::vector<LinearSpring>& springs,
                                           const std::string& field) {
  const std::size_t n1 = m_state1->size(), n2 = m_state2->size();
  std::string bad;
  std::size_t count = 0;
  for (std::size_t k = 0; k < springs.size(); ++k) {
    const LinearSpring& s = springs[k];
    if (s.m1 < n1 && s.m2 < n2) continue;
    if (count++ >= 10) continue;
    bad += "\n  spring " + std::to_string(k) + " (" + std::to_string(s.m1) + " " +
           std::to_string(s.m2) + "): ";
    if (s.m1 >= n1)
      bad += "index1 " + std::to_string(s.m1) + " >= " + std::to_string(n1) + " points of " +
             m_state1->path();
    if (s.m1 >= n1 && s.m2 >= n2) bad += ", ";
    if (s.m2 >= n2)
      bad += "index2 " + std::to_string(s.m2) + " >= " + std::to_string(n2) + " points of " +
             m_state2->path();
  }
  if (count == 0) return true;
  msgError(std::to_string(count) + " springs with indices out of range:" + bad +
               (count > 10 ? "\n  ..." : ""),
           field);
  return false;
}

template <class DataTypes>
void SpringForceField<DataTypes>::init() {
  for (const Data<FileName>* file : {&d_fileSprings, &d_filename})
    if (!file->value().original.empty())
      msgError("spring files (" + file->value().original +
                   ") are not supported: give the springs in 'spring'",
               file->name());
  if (static_cast<bool>(l_object1) != static_cast<bool>(l_object2)) {
    msgError(
        "give both object1 and object2 (springs between two states), or neither (springs "
        "inside the node's state)",
        l_object1 ? "object2" : "object1");
    return;
  }
  if (l_object1) {
    m_state1 = resolveState(l_object1);
    m_state2 = resolveState(l_object2);
  } else {
    m_state1 = m_state2 = node() ? node()->template get<State>() : nullptr;
    if (!m_state1)
      msgError(std::string("no ") + DataTypes::name + " mechanical state in " +
                   (node() ? node()->path() : std::string("?")) +
                   ": add one, or give object1 and object2",
               "object1");
  }
  if (!m_state1 || !m_state2) return;

  // Springs from indices1/indices2/lengths, with the common stiffness and damping.
  const auto& i1 = d_indices1.value();
  const auto& i2 = d_indices2.value();
  const auto& lengths = d_lengths.value();
  m_fromIndices.clear();
  if (i1.size() != i2.size())
    msgError("indices1 has " + std::to_string(i1.size()) + " indices and indices2 " +
                 std::to_string(i2.size()) + ": expected as many",
             "indices2");
  else if (!lengths.empty() && lengths.size() != 1 && lengths.size() != i1.size())
    msgError("expected " + std::to_string(i1.size()) +
                 " lengths (one per spring), one, or none; got " + std::to_string(lengths.size()),
             "lengths");
  else
    for (std::size_t k = 0; k < i1.size(); ++k)
      m_fromIndices.push_back({i1[k], i2[k], d_stiffness.value(), d_damping.value(),
                               lengths.empty() ? 0.0 : lengths[lengths.size() == 1 ? 0 : k]});
  validate(d_springs.value(), "spring");
  validate(m_fromIndices, "indices1");
  m_springsVersion = ~0ull;
}

template <class DataTypes>
const std::vector<LinearSpring>& SpringForceField<DataTypes>::springs() const {
  const std::uint64_t version = d_springs.version();
  if (version != m_springsVersion) {
    // Rebuilt only when `spring` changed. Springs outside the states (a run-time edit) are
    // dropped with a warning rather than read out of bounds.
    m_springsVersion = version;
    m_all.clear();
    const std::size_t n1 = m_state1 ? m_state1->size() : 0, n2 = m_state2 ? m_state2->size() : 0;
    std::size_t dropped = 0;
    for (const auto* list : {&d_springs.value(), &m_fromIndices})
      for (const LinearSpring& s : *list) {
        if (s.m1 < n1 && s.m2 < n2)
          m_all.push_back(s);
        else
          ++dropped;
      }
    if (dropped && isValid())
      msgWarning(std::to_string(dropped) + " springs with indices out of range are ignored",
                 "spring");
  }
  return m_all;
}

template <class DataTypes>
void SpringForceField<DataTypes>::accumulateForce(const MechanicalParams& mp, VecId f) {
  if (!m_state1 || !m_state2) return;
  const SpringStates<kDimension> x{m_state1->readCoord(mp.x), m_state2->readCoord(mp.x)};
  addSpringForces(springs(), x, m_state1->readDeriv(mp.v), m_state2->readDeriv(mp.v),
                  m_state1->writeDeriv(f), m_state2->writeDeriv(f));
}

template <class DataTypes>
void SpringForceField<DataTypes>::accumulateDForce(const MechanicalParams& mp, VecId df, VecId dx) {
  if (!m_state1 || !m_state2) return;
  const SpringStates<kDimension> x{m_state1->readCoord(mp.x), m_state2->readCoord(mp.x),
                                   &m_state1->readDeriv(mp.v), &m_state2->readDeriv(mp.v)};
  addSpringDForces(springs(), x, m_state1->readDeriv(dx), m_state2->readDeriv(dx),
                   m_state1->writeDeriv(df), m_state2->writeDeriv(df), mp.kFactor, mp.bFactor);
}

template <class DataTypes>
void SpringForceField<DataTypes>::accumulateKMatrix(const MechanicalParams& mp,
                                                    MatrixAccumulator& matrix,
                                                    const StateOffsets& offsets) {
  if (!m_state1 || !m_state2) return;
  std::size_t offset1 = 0, offset2 = 0;
  const bool has1 = offsets.find(m_state1, offset1);
  const bool has2 = offsets.find(m_state2, offset2);
  if (!has1 || !has2) {
    if ((has1 || has2) && !m_reportedOutside) {
      m_reportedOutside = true;
      msgWarning(
          "one of its states is outside this assembled system: its springs are left out "
          "of the matrix (the matrix-free path still has them)");
    }
    return;
  }
  const SpringStates<kDimension> x{m_state1->readCoord(mp.x), m_state2->readCoord(mp.x),
                                   &m_state1->readDeriv(mp.v), &m_state2->readDeriv(mp.v)};
  addSpringMatrix(springs(), x, matrix, offset1, offset2, mp.kFactor, mp.bFactor);
}

template <class DataTypes>
double SpringForceField<DataTypes>::energy(const MechanicalParams& mp) const {
  if (!m_state1 || !m_state2) return 0;
  return springEnergy(
      springs(), SpringStates<kDimension>{m_state1->readCoord(mp.x), m_state2->readCoord(mp.x)});
}

template <class DataTypes>
std::vector<BaseMechanicalState*> SpringForceField<DataTypes>::states() const {
  if (!m_state1 || !m_state2) return {};
  if (m_state1 == m_state2) return {m_state1};
  return {m_state1, m_state2};
}

template class SpringForceField<Vec1Types>;
template class SpringForceField<Vec2Types>;
template class SpringForceField<Vec3Types>;

}  // namespace stroma
