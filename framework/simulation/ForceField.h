// SPDX-License-Identifier: MIT
// Force fields: the interface the solvers use (BaseForceField, untyped, over VecIds), and the
// typed base a component derives from (ForceField<DataTypes>), which reads and writes its
// state's vectors and calls the SOFA-named methods below.
//
// Sign conventions: addForce adds f = -dE/dx (+ damping forces); K = df/dx = -d2E/dx2, so that
// addDForce adds df = kFactor K dx (+ bFactor B dx) and addKToMatrix adds kFactor K. For an
// elastic body K is negative semi-definite; implicit solvers build m M - b B - k K... through
// the factors in MechanicalParams (EulerImplicitSolver uses kFactor = -h^2 etc.).
#pragma once

#include <vector>

#include "core/Link.h"
#include "core/Node.h"
#include "linalg/AssembledMatrix.h"
#include "simulation/MechanicalState.h"
#include "simulation/VecId.h"

namespace stroma {

/// Rows of each independent state in an assembled system.
class StateOffsets {
 public:
  void set(const BaseMechanicalState* state, std::size_t offset) {
    m_entries.push_back({state, offset});
  }
  /// The offset of a state, or false when it is not in the system.
  bool find(const BaseMechanicalState* state, std::size_t& offset) const {
    for (const auto& e : m_entries)
      if (e.state == state) return (offset = e.offset), true;
    return false;
  }

 private:
  struct Entry {
    const BaseMechanicalState* state;
    std::size_t offset;
  };
  std::vector<Entry> m_entries;
};

class BaseForceField : public Base {
 public:
  /// f += forces at positions mp.x and velocities mp.v.
  virtual void accumulateForce(const MechanicalParams& mp, VecId f) = 0;
  /// df += (mp.kFactor K + mp.bFactor B) dx.
  virtual void accumulateDForce(const MechanicalParams& mp, VecId df, VecId dx) = 0;
  /// Adds mp.kFactor K (+ mp.bFactor B) at the rows of its states.
  virtual void accumulateKMatrix(const MechanicalParams& mp, MatrixAccumulator& matrix,
                                 const StateOffsets& offsets) = 0;
  virtual double energy(const MechanicalParams& mp) const = 0;
  /// The states it acts on.
  virtual std::vector<BaseMechanicalState*> states() const = 0;
};

/// Typed base of a force field on one state. The state is the `mstate` link when given, else
/// the node's mechanical state of the same template.
template <class DataTypes, class Interface = BaseForceField>
class ForceField : public Interface {
 public:
  using Coord = typename DataTypes::Coord;
  using Deriv = typename DataTypes::Deriv;
  using VecCoord = std::vector<Coord>;
  using VecDeriv = std::vector<Deriv>;
  using State = MechanicalState<DataTypes>;

  Link<State> l_mstate{this, "mstate",
                       "The state it acts on (default: the node's; in a node without a state, "
                       "the nearest ancestor's, as SOFA's context)."};

  State* mstate() const { return l_mstate.get(); }

  /// Finds the state. Components that override init() call this first.
  void init() override {
    // SOFA's scenes put a field in a child node holding only the elements of a topological
    // mapping (Quad2Triangle, Tetra2Triangle) under the node of its state.
    if (!l_mstate && this->node())
      l_mstate.set(this->node()->template get<BaseMechanicalState>()
                       ? this->node()->template get<State>()
                       : this->node()->template getUp<State>());
    if (!l_mstate)
      this->msgError(std::string("no mechanical state of template ") + DataTypes::name +
                     " in " + (this->node() ? this->node()->path() : std::string("?")));
  }

  virtual void addForce(const MechanicalParams& mp, VecDeriv& f, const VecCoord& x,
                        const VecDeriv& v) = 0;
  virtual void addDForce(const MechanicalParams& mp, VecDeriv& df, const VecDeriv& dx) = 0;
  /// Adds mp.kFactor K (+ mp.bFactor B) with this state's first row at `offset`.
  virtual void addKToMatrix(const MechanicalParams& mp, MatrixAccumulator& matrix,
                            std::size_t offset) = 0;
  virtual double potentialEnergy(const MechanicalParams& mp, const VecCoord& x) const {
    (void)mp;
    (void)x;
    return 0;
  }

  void accumulateForce(const MechanicalParams& mp, VecId f) final {
    addForce(mp, mstate()->writeDeriv(f), mstate()->readCoord(mp.x), mstate()->readDeriv(mp.v));
  }
  void accumulateDForce(const MechanicalParams& mp, VecId df, VecId dx) final {
    addDForce(mp, mstate()->writeDeriv(df), mstate()->readDeriv(dx));
  }
  void accumulateKMatrix(const MechanicalParams& mp, MatrixAccumulator& matrix,
                         const StateOffsets& offsets) final {
    std::size_t offset = 0;
    if (offsets.find(mstate(), offset)) addKToMatrix(mp, matrix, offset);
  }
  double energy(const MechanicalParams& mp) const final {
    return potentialEnergy(mp, mstate()->readCoord(mp.x));
  }
  std::vector<BaseMechanicalState*> states() const final { return {l_mstate.get()}; }
};

}  // namespace stroma
