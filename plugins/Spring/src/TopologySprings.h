// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

#include "LinearSpring.h"
#include "SpringKernel.h"
#include "SpringPairs.h"
#include "core/StateTypes.h"
#include "simulation/ForceField.h"
#include "topology/Topology.h"

namespace stroma {

/// What the spring families built from a topology's elements share (TriangularBendingSprings,
/// QuadularBendingSprings, QuadBendingSprings): the built springs (output `spring`), built again
/// by the family's build() when the topology changes, and their forces, exact tangent, matrix
/// and energy (SpringKernel.h).
template <class DataTypes>
class TopologySprings : public ForceField<DataTypes> {
 public:
  using typename ForceField<DataTypes>::VecCoord;
  using typename ForceField<DataTypes>::VecDeriv;
  static constexpr int kDimension = DataTypes::derivSize;

  Data<std::vector<LinearSpring>> d_springs{
      this, "spring", {}, "The springs built from the mesh (output).", {.output = true}};

  void addForce(const MechanicalParams&, VecDeriv& f, const VecCoord& x,
                const VecDeriv& v) override {
    if (m_topology && this->isValid() && m_topology->revision() != m_topologyRevision) build();
    addSpringForces(d_springs.value(), SpringStates<kDimension>{x, x}, v, v, f, f);
  }
  void addDForce(const MechanicalParams& mp, VecDeriv& df, const VecDeriv& dx) override {
    const VecCoord& x = this->mstate()->readCoord(mp.x);
    const VecDeriv& v = this->mstate()->readDeriv(mp.v);
    addSpringDForces(d_springs.value(), SpringStates<kDimension>{x, x, &v, &v}, dx, dx, df, df,
                     mp.kFactor, mp.bFactor);
  }
  void addKToMatrix(const MechanicalParams& mp, MatrixAccumulator& matrix,
                    std::size_t offset) override {
    const VecCoord& x = this->mstate()->readCoord(mp.x);
    const VecDeriv& v = this->mstate()->readDeriv(mp.v);
    addSpringMatrix(d_springs.value(), SpringStates<kDimension>{x, x, &v, &v}, matrix, offset,
                    offset, mp.kFactor, mp.bFactor);
  }
  double potentialEnergy(const MechanicalParams&, const VecCoord& x) const override {
    return springEnergy(d_springs.value(), SpringStates<kDimension>{x, x});
  }

 protected:
  /// Builds d_springs from m_topology, and records its revision in m_topologyRevision.
  virtual void build() = 0;

  /// init() of a family: the state, the topology (`link`, else the nearest one from the node
  /// up) that must hold `elements` ("triangles" or "quads"), then the springs. An error names
  /// the field otherwise.
  void initSprings(const Link<Topology>& link, const char* elements) {
    ForceField<DataTypes>::init();
    if (!this->mstate()) return;
    m_topology = findSpringTopology(*this, link, elements);
    if (!m_topology) return;
    const bool quads = std::string_view(elements) == "quads";
    if (quads ? m_topology->quads().empty() : m_topology->triangles().empty()) {
      this->msgError("the topology " + m_topology->path() + " has no " + elements, "topology");
      return;
    }
    build();
  }

  const Topology* m_topology = nullptr;
  std::uint64_t m_topologyRevision = 0;
};

}  // namespace stroma
