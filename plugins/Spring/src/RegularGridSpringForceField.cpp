// SPDX-License-Identifier: MIT
#include "RegularGridSpringForceField.h"

#include "SpringKernel.h"
#include "SpringPairs.h"
#include "core/Node.h"

namespace stroma {

template <class DataTypes>
void RegularGridSpringForceField<DataTypes>::init() {
  ForceField<DataTypes>::init();
  if (!this->mstate()) return;
  m_topology = findSpringTopology(*this, l_topology, "a grid of hexahedra, quads or edges");
  if (!m_topology) return;
  // As SOFA: the common values, when given, replace the kinds' own ones.
  for (const auto& [common, kinds] :
       {std::pair{&d_stiffness,
                  std::array{&d_linesStiffness, &d_quadsStiffness, &d_cubesStiffness}},
        std::pair{&d_damping, std::array{&d_linesDamping, &d_quadsDamping, &d_cubesDamping}}}) {
    if (!common->isSet()) continue;
    for (const Data<double>* kind : kinds)
      if (kind->isSet() && kind->value() != common->value())
        this->msgWarning(kind->name() + " (" + std::to_string(kind->value()) + ") is replaced by " +
                             common->name() + " (" + std::to_string(common->value()) +
                             "), as in SOFA",
                         kind->name());
  }
  build();
}

template <class DataTypes>
void RegularGridSpringForceField<DataTypes>::build() {
  m_topologyRevision = m_topology->revision();
  const std::size_t n = this->mstate()->size();
  // Rest lengths from the grid's own points when it has one per point of the state (SOFA uses
  // the grid's spacing), else from the state's rest positions.
  const std::vector<Vec3d>& gridPoints = m_topology->positions();
  VecCoord x0;
  if (gridPoints.size() == n) {
    x0.resize(n);
    for (std::size_t i = 0; i < n; ++i) x0[i] = gridPoints[i].template head<kDimension>();
  } else {
    const VecCoord& rest = this->mstate()->readCoord(VecId::restPosition());
    x0 = rest.size() == n ? rest : this->mstate()->readCoord(VecId::position());
  }
  auto valueOf = [](const Data<double>& kind, const Data<double>& common) {
    return common.isSet() ? common.value() : kind.value();
  };

  const GridPairs pairs = findGridPairs(*m_topology);
  std::vector<LinearSpring> springs;
  springs.reserve(pairs.lines.size() + pairs.faceDiagonals.size() + pairs.cellDiagonals.size());
  std::size_t outOfRange = 0;
  for (const auto& [list, stiffness, damping] :
       {std::tuple{&pairs.lines, &d_linesStiffness, &d_linesDamping},
        std::tuple{&pairs.faceDiagonals, &d_quadsStiffness, &d_quadsDamping},
        std::tuple{&pairs.cellDiagonals, &d_cubesStiffness, &d_cubesDamping}}) {
    const double ks = valueOf(*stiffness, d_stiffness), kd = valueOf(*damping, d_damping);
    if (ks == 0 && kd == 0) continue;
    outOfRange += appendSprings<kDimension>(*list, x0, ks, kd, true, springs);
  }
  if (outOfRange) {
    this->msgError("the elements of " + m_topology->path() + " use points out of range of the " +
                       std::to_string(n) + " points of " + this->mstate()->path() + " (" +
                       std::to_string(outOfRange) + " springs)",
                   "topology");
    d_springs.setValue({});
    return;
  }
  if (springs.empty() && pairs.lines.empty())
    this->msgError(
        "the topology " + m_topology->path() + " has no grid: no hexahedra, quads or edges",
        "topology");
  d_springs.setValue(std::move(springs));
}

template <class DataTypes>
void RegularGridSpringForceField<DataTypes>::addForce(const MechanicalParams&, VecDeriv& f,
                                                      const VecCoord& x, const VecDeriv& v) {
  if (m_topology && this->isValid() && m_topology->revision() != m_topologyRevision) build();
  addSpringForces(d_springs.value(), SpringStates<kDimension>{x, x}, v, v, f, f);
}

template <class DataTypes>
void RegularGridSpringForceField<DataTypes>::addDForce(const MechanicalParams& mp, VecDeriv& df,
                                                       const VecDeriv& dx) {
  const VecCoord& x = this->mstate()->readCoord(mp.x);
  const VecDeriv& v = this->mstate()->readDeriv(mp.v);
  addSpringDForces(d_springs.value(), SpringStates<kDimension>{x, x, &v, &v}, dx, dx, df, df,
                   mp.kFactor, mp.bFactor);
}

template <class DataTypes>
void RegularGridSpringForceField<DataTypes>::addKToMatrix(const MechanicalParams& mp,
                                                          MatrixAccumulator& matrix,
                                                          std::size_t offset) {
  const VecCoord& x = this->mstate()->readCoord(mp.x);
  const VecDeriv& v = this->mstate()->readDeriv(mp.v);
  addSpringMatrix(d_springs.value(), SpringStates<kDimension>{x, x, &v, &v}, matrix, offset, offset,
                  mp.kFactor, mp.bFactor);
}

template <class DataTypes>
double RegularGridSpringForceField<DataTypes>::potentialEnergy(const MechanicalParams&,
                                                               const VecCoord& x) const {
  return springEnergy(d_springs.value(), SpringStates<kDimension>{x, x});
}

template class RegularGridSpringForceField<Vec1Types>;
template class RegularGridSpringForceField<Vec2Types>;
template class RegularGridSpringForceField<Vec3Types>;

}  // namespace stroma
