// SPDX-License-Identifier: MIT
#pragma once

#include <string>
#include <vector>

#include "core/Link.h"
#include "core/Node.h"
#include "simulation/MechanicalState.h"
#include "simulation/VecId.h"

namespace stroma {

/// A constraint applied by projection: it removes the constrained directions from forces and
/// increments (projectResponse), and imposes velocities and positions.
class BaseProjectiveConstraint : public Base {
 public:
  /// Removes the constrained directions from a deriv vector (forces, increments).
  virtual void constrainResponse(VecId dx) = 0;
  /// Imposes the constrained velocities and positions at `time`: the end of the step being
  /// solved (MechanicalOperations::endTime()), whose state they are called on.
  virtual void constrainVelocity(VecId v, double time) = 0;
  virtual void constrainPosition(VecId x, double time) = 0;
  /// The scalar rows (within its state) that are fully fixed, for the assembled path: their
  /// rows and columns become those of the identity.
  virtual void fixedRows(std::vector<std::size_t>& rows) const = 0;
  virtual BaseMechanicalState* state() const = 0;
};

template <class DataTypes>
class ProjectiveConstraint : public BaseProjectiveConstraint {
 public:
  using Coord = typename DataTypes::Coord;
  using Deriv = typename DataTypes::Deriv;
  using VecCoord = std::vector<Coord>;
  using VecDeriv = std::vector<Deriv>;
  using State = MechanicalState<DataTypes>;

  Link<State> l_mstate{this, "mstate", "The state it constrains (default: the node's)."};
  State* mstate() const { return l_mstate.get(); }
  BaseMechanicalState* state() const final { return l_mstate.get(); }

  void init() override {
    if (!l_mstate) l_mstate.set(this->node() ? this->node()->template get<State>() : nullptr);
    if (!l_mstate)
      this->msgError(std::string("no mechanical state of template ") + DataTypes::name +
                     " in " + (this->node() ? this->node()->path() : std::string("?")));
  }

  virtual void projectResponse(VecDeriv& dx) = 0;
  virtual void projectVelocity(VecDeriv& v, double time) = 0;
  virtual void projectPosition(VecCoord& x, double time) = 0;

  void constrainResponse(VecId dx) final { projectResponse(mstate()->writeDeriv(dx)); }
  void constrainVelocity(VecId v, double time) final {
    projectVelocity(mstate()->writeDeriv(v), time);
  }
  void constrainPosition(VecId x, double time) final {
    projectPosition(mstate()->writeCoord(x), time);
  }
};

}  // namespace stroma
