// SPDX-License-Identifier: MIT
#pragma once

#include "simulation/ForceField.h"

namespace stroma {

/// A mass is a force field (it applies gravity, m g, in addForce) that also multiplies by M.
class BaseMass : public BaseForceField {
 public:
  /// f += factor M dx.
  virtual void accumulateMDx(VecId f, VecId dx, double factor) = 0;
  /// a = M^-1 f; only for lumped (diagonal) masses, see isDiagonal().
  virtual void accumulateAccFromF(VecId a, VecId f) = 0;
  /// Adds factor M at the rows of its state.
  virtual void accumulateMMatrix(MatrixAccumulator& matrix, const StateOffsets& offsets,
                                 double factor) = 0;
  virtual double kineticEnergyAt(VecId v) const = 0;
  /// True when M is diagonal, so that explicit solvers can use accFromF.
  virtual bool isDiagonal() const = 0;
};

template <class DataTypes>
class Mass : public ForceField<DataTypes, BaseMass> {
 public:
  using typename ForceField<DataTypes, BaseMass>::VecDeriv;
  using typename ForceField<DataTypes, BaseMass>::VecCoord;

  virtual void addMDx(VecDeriv& f, const VecDeriv& dx, double factor) = 0;
  virtual void accFromF(VecDeriv& a, const VecDeriv& f) = 0;
  virtual void addMToMatrix(MatrixAccumulator& matrix, std::size_t offset, double factor) = 0;
  virtual double kineticEnergy(const VecDeriv& v) const = 0;

  void accumulateMDx(VecId f, VecId dx, double factor) final {
    addMDx(this->mstate()->writeDeriv(f), this->mstate()->readDeriv(dx), factor);
  }
  void accumulateAccFromF(VecId a, VecId f) final {
    accFromF(this->mstate()->writeDeriv(a), this->mstate()->readDeriv(f));
  }
  void accumulateMMatrix(MatrixAccumulator& matrix, const StateOffsets& offsets,
                         double factor) final {
    std::size_t offset = 0;
    if (offsets.find(this->mstate(), offset)) addMToMatrix(matrix, offset, factor);
  }
  double kineticEnergyAt(VecId v) const final {
    return kineticEnergy(this->mstate()->readDeriv(v));
  }
};

}  // namespace stroma
