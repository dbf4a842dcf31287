// SPDX-License-Identifier: MIT
#pragma once

#include "MappedOutput.h"
#include "core/StateTypes.h"
#include "simulation/Mapping.h"

namespace stroma {

/// The output is a subset of the input's points (SOFA's SubsetMapping):
/// x_out[i] = x_in[indices[i]]; J selects rows, J^T adds each output force to its input point.
/// Without `indices`, the points `first`..`last` are taken, else each output point is matched
/// to the input point at the same place (within `radius`). The output is given one point per
/// index.
class SubsetMapping final : public Mapping<Vec3Types, Vec3Types> {
 public:
  Data<std::vector<unsigned>> d_indices{
      this,
      "indices",
      {},
      "Input point of each output point (nbOutput). Default: first..last, else found by "
      "position."};
  Data<int> d_first{this,
                    "first",
                    -1,
                    "First input point of the subset when no indices are given.",
                    {.min = -1.0}};
  Data<int> d_last{this,
                   "last",
                   -1,
                   "Last input point (included) of the subset when no indices are given.",
                   {.min = -1.0}};
  Data<double> d_radius{this,
                        "radius",
                        1e-5,
                        "Largest distance between an output point and the input point it is "
                        "matched to, when neither indices nor first/last are given.",
                        {.unit = "m", .min = 0.0}};
  Data<bool> d_ignoreNotFound{this, "ignoreNotFound", false,
                              "When matching by position, drop output points that match no "
                              "input point instead of reporting an error."};
  Data<bool> d_resizeToModel{this, "resizeToModel", false,
                             "SOFA option, accepted: the output always has one point per index."};
  Data<bool> d_handleTopologyChange{this, "handleTopologyChange", true,
                                    "SOFA option, accepted (no topological changes yet)."};
  SofaMappingOptions m_options{this};

  void init() override;

  void apply(OutVecCoord& out, const InVecCoord& in) override;
  void applyJ(OutVecDeriv& out, const InVecDeriv& in) override;
  void applyJT(InVecDeriv& in, const OutVecDeriv& out) override;
  /// nbOutput*3 x nbInput*3, one 3x3 identity block per output point.
  const Eigen::SparseMatrix<double>& jacobian() override;

 protected:
  bool prepareVisual(const OutVecCoord& points) override;

 private:
  bool computeIndices(const std::vector<Vec3d>& xout, VecId inputPoints);
  Eigen::SparseMatrix<double> m_J;
  std::uint64_t m_jacobianVersion = ~std::uint64_t{0};
};

}  // namespace stroma
