// SPDX-License-Identifier: MIT
#pragma once

#include <Eigen/Core>
#include <vector>

#include "core/BaseState.h"
#include "simulation/VecId.h"

namespace stroma {

/// A set of degrees of freedom with state vectors identified by VecId. The untyped operations
/// are what MechanicalOperations needs to run solvers over any mix of states.
class BaseMechanicalState : public BaseState {
 public:
  /// Makes a temporary vector of size size(), zeroed; a no-op for standard vectors.
  virtual void vAlloc(VecId v) = 0;
  virtual void vFree(VecId v) = 0;
  /// v = a + b * f. A null a or b counts as zero. When v and a are coords and b is a deriv,
  /// this is an integration step x + dx f (rigid orientations are updated by the rotation
  /// vector dx f).
  virtual void vOp(VecId v, VecId a, VecId b, double f) = 0;
  /// Sum of the products of the components of two deriv vectors.
  virtual double vDot(VecId a, VecId b) const = 0;
  /// Largest absolute component, and where: the first non-finite one when there is any
  /// (then the result is NaN or infinity).
  virtual double vMaxAbs(VecId a, std::size_t& where) const = 0;

  /// Numbers per deriv times size(): this state's rows in an assembled system.
  std::size_t matrixSize() const { return size() * static_cast<std::size_t>(derivDimension()); }
  /// Copies a deriv vector into (from) the global vector `g` at `offset`.
  virtual void copyToGlobal(VecId v, Eigen::Ref<Eigen::VectorXd> g, std::size_t offset) const = 0;
  virtual void copyFromGlobal(VecId v, const Eigen::Ref<const Eigen::VectorXd>& g,
                              std::size_t offset) = 0;
};

/// Typed access to the vectors, for components written for one kind of degrees of freedom.
template <class DataTypes>
class MechanicalState : public BaseMechanicalState {
 public:
  using Coord = typename DataTypes::Coord;
  using Deriv = typename DataTypes::Deriv;
  using VecCoord = std::vector<Coord>;
  using VecDeriv = std::vector<Deriv>;

  virtual const VecCoord& readCoord(VecId v) const = 0;
  virtual VecCoord& writeCoord(VecId v) = 0;
  virtual const VecDeriv& readDeriv(VecId v) const = 0;
  virtual VecDeriv& writeDeriv(VecId v) = 0;

  int coordDimension() const override { return DataTypes::coordSize; }
  int derivDimension() const override { return DataTypes::derivSize; }
};

}  // namespace stroma
