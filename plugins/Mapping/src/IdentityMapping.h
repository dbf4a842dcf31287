// SPDX-License-Identifier: MIT
#pragma once

#include "MappedOutput.h"
#include "core/StateTypes.h"
#include "simulation/Mapping.h"

namespace stroma {

/// The output is a copy of the input (SOFA's IdentityMapping): x_out = x_in, J = I. The output
/// is given the input's number of points. Vec3d -> Vec3d and Rigid3d -> Rigid3d.
template <class DataTypes>
class IdentityMapping final : public Mapping<DataTypes, DataTypes> {
 public:
  using Base_ = Mapping<DataTypes, DataTypes>;
  using typename Base_::InVecCoord;
  using typename Base_::InVecDeriv;
  using typename Base_::OutVecCoord;
  using typename Base_::OutVecDeriv;

  SofaMappingOptions m_options{this};

  void init() override;

  void apply(OutVecCoord& out, const InVecCoord& in) override;
  void applyJ(OutVecDeriv& out, const InVecDeriv& in) override;
  void applyJT(InVecDeriv& in, const OutVecDeriv& out) override;
  /// The identity, (n x derivSize) square.
  const Eigen::SparseMatrix<double>& jacobian() override;

 protected:
  /// A visual output takes the input's points as they are.
  bool prepareVisual(const OutVecCoord&) override { return true; }

 private:
  Eigen::SparseMatrix<double> m_J;
};

}  // namespace stroma
