// SPDX-License-Identifier: MIT
#include "MeshSpringForceField.h"

#include <unordered_set>

#include "SpringKernel.h"
#include "core/Node.h"

namespace stroma {

namespace {

// A kind's value: its own when given, else the common one (SOFA's alias sets them all).
double valueOf(const Data<double>& own, const Data<double>& common) {
  return own.isSet() ? own.value() : common.value();
}

}  // namespace

template <class DataTypes>
void MeshSpringForceField<DataTypes>::init() {
  ForceField<DataTypes>::init();
  if (!this->mstate()) return;
  m_topology = l_topology ? l_topology.get()
                          : (this->node() ? this->node()->template getUp<Topology>() : nullptr);
  if (!m_topology) {
    this->msgError(
        "needs a topology (MeshTopology, TetrahedronSetTopologyContainer, "
        "RegularGridTopology, ...) in its node or above, or a 'topology' link",
        "topology");
    return;
  }
  if (build() && d_springs.value().empty())
    this->msgWarning(
        "no spring was made: the topology has no element of a kind with a non-zero "
        "stiffness or damping",
        "stiffness");
}

template <class DataTypes>
bool MeshSpringForceField<DataTypes>::build() {
  const std::size_t n = this->mstate()->size();
  const VecCoord& rest = this->mstate()->readCoord(VecId::restPosition());
  const VecCoord& x0 = rest.size() == n ? rest : this->mstate()->readCoord(VecId::position());
  const Vec2i range = d_localRange.value();

  std::vector<LinearSpring> springs;
  std::unordered_set<std::uint64_t> made;
  std::size_t outOfRange = 0;
  // One spring per unordered pair, the first kind that names it deciding its parameters.
  auto add = [&](Index a, Index b, double stiffness, double damping) {
    if (a >= n || b >= n) {
      ++outOfRange;
      return;
    }
    if (a == b) return;
    if (range[0] >= 0 && (a < Index(range[0]) || b < Index(range[0]))) return;
    if (range[1] >= 0 && a > Index(range[1]) && b > Index(range[1])) return;
    const std::uint64_t key = (std::uint64_t{std::min(a, b)} << 32) | std::max(a, b);
    if (!made.insert(key).second) return;
    const double length = (x0[b] - x0[a]).norm();
    const double perLength = length > 1e-12 ? 1 / length : 1.0;
    springs.push_back(
        {a, b, stiffness * perLength, damping * perLength, length, d_noCompression.value()});
  };
  auto addPairs = [&](const auto& elements, double stiffness, double damping, auto pairs) {
    if (stiffness == 0 && damping == 0) return;
    for (const auto& e : elements)
      for (const auto& [i, j] : pairs) add(e[i], e[j], stiffness, damping);
  };
  static constexpr std::array<std::pair<int, int>, 1> kEdge{{{0, 1}}};
  static constexpr std::array<std::pair<int, int>, 3> kTriangle{{{0, 1}, {0, 2}, {1, 2}}};
  static constexpr std::array<std::pair<int, int>, 6> kSixPairs{
      {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}}};
  std::array<std::pair<int, int>, 28> hexahedronPairs{};
  for (int i = 0, k = 0; i < 8; ++i)
    for (int j = i + 1; j < 8; ++j) hexahedronPairs[k++] = {i, j};

  const Data<double>& tetraStiffness =
      d_tetrahedraStiffness.isSet() ? d_tetrahedraStiffness : d_tetrasStiffness;
  const Data<double>& tetraDamping =
      d_tetrahedraDamping.isSet() ? d_tetrahedraDamping : d_tetrasDamping;
  addPairs(m_topology->allEdges(), valueOf(d_linesStiffness, d_stiffness),
           valueOf(d_linesDamping, d_damping), kEdge);
  addPairs(m_topology->triangles(), valueOf(d_trianglesStiffness, d_stiffness),
           valueOf(d_trianglesDamping, d_damping), kTriangle);
  addPairs(m_topology->quads(), valueOf(d_quadsStiffness, d_stiffness),
           valueOf(d_quadsDamping, d_damping), kSixPairs);
  addPairs(m_topology->tetrahedra(), valueOf(tetraStiffness, d_stiffness),
           valueOf(tetraDamping, d_damping), kSixPairs);
  addPairs(m_topology->hexahedra(), valueOf(d_cubesStiffness, d_stiffness),
           valueOf(d_cubesDamping, d_damping), hexahedronPairs);

  m_topologyRevision = m_topology->revision();
  if (outOfRange) {
    this->msgError("the elements of " + m_topology->path() + " use points out of range of the " +
                       std::to_string(n) + " points of " + this->mstate()->path() + " (" +
                       std::to_string(outOfRange) + " pairs)",
                   "topology");
    d_springs.setValue({});
    return false;
  }
  d_springs.setValue(std::move(springs));
  return true;
}

template <class DataTypes>
void MeshSpringForceField<DataTypes>::refresh() {
  if (m_topology && this->isValid() && m_topology->revision() != m_topologyRevision) build();
}

template <class DataTypes>
void MeshSpringForceField<DataTypes>::addForce(const MechanicalParams&, VecDeriv& f,
                                               const VecCoord& x, const VecDeriv& v) {
  refresh();
  addSpringForces(d_springs.value(), SpringStates<kDimension>{x, x}, v, v, f, f);
}

template <class DataTypes>
void MeshSpringForceField<DataTypes>::addDForce(const MechanicalParams& mp, VecDeriv& df,
                                                const VecDeriv& dx) {
  const VecCoord& x = this->mstate()->readCoord(mp.x);
  const VecDeriv& v = this->mstate()->readDeriv(mp.v);
  addSpringDForces(d_springs.value(), SpringStates<kDimension>{x, x, &v, &v}, dx, dx, df, df,
                   mp.kFactor, mp.bFactor);
}

template <class DataTypes>
void MeshSpringForceField<DataTypes>::addKToMatrix(const MechanicalParams& mp,
                                                   MatrixAccumulator& matrix, std::size_t offset) {
  const VecCoord& x = this->mstate()->readCoord(mp.x);
  const VecDeriv& v = this->mstate()->readDeriv(mp.v);
  addSpringMatrix(d_springs.value(), SpringStates<kDimension>{x, x, &v, &v}, matrix, offset, offset,
                  mp.kFactor, mp.bFactor);
}

template <class DataTypes>
double MeshSpringForceField<DataTypes>::potentialEnergy(const MechanicalParams&,
                                                        const VecCoord& x) const {
  return springEnergy(d_springs.value(), SpringStates<kDimension>{x, x});
}

template class MeshSpringForceField<Vec1Types>;
template class MeshSpringForceField<Vec2Types>;
template class MeshSpringForceField<Vec3Types>;

}  // namespace stroma
