// SPDX-License-Identifier: MIT
#pragma once

#include "core/StateTypes.h"
#include "simulation/Mass.h"

namespace stroma {

/// The same mass at every point (SOFA's UniformMass): `vertexMass`, or `totalMass` spread
/// evenly. It applies gravity (the node's) as a force m g. M is diagonal.
/// Changing vertexMass or totalMass while running takes effect at the next step.
class UniformMass final : public Mass<Vec3Types> {
 public:
  Data<double> d_vertexMass{this, "vertexMass", 1.0, "Mass of each point (when totalMass is 0).",
                            {.unit = "kg", .min = 0.0}};
  Data<double> d_totalMass{this, "totalMass", 0.0,
                           "Total mass, spread evenly over the points; 0 to use vertexMass.",
                           {.unit = "kg", .min = 0.0}};
  Data<std::vector<unsigned>> d_indices{this, "indices", {},
                                        "Points that have mass (default: all)."};
  Data<bool> d_handleTopologicalChanges{this, "handleTopologicalChanges", false,
                                        "SOFA option, accepted: the mass follows the state's "
                                        "size."};
  Data<bool> d_preserveTotalMass{this, "preserveTotalMass", false,
                                 "SOFA option, accepted and without effect yet."};
  Data<double> d_showAxisSizeFactor{this, "showAxisSizeFactor", 1.0, "Viewers only."};

  void init() override;

  /// The mass of one point now (vertexMass, or totalMass / number of points with mass).
  double pointMass() const;

  void addForce(const MechanicalParams& mp, VecDeriv& f, const VecCoord& x,
                const VecDeriv& v) override;
  void addDForce(const MechanicalParams&, VecDeriv&, const VecDeriv&) override {}
  void addKToMatrix(const MechanicalParams&, MatrixAccumulator&, std::size_t) override {}
  double potentialEnergy(const MechanicalParams& mp, const VecCoord& x) const override;

  void addMDx(VecDeriv& f, const VecDeriv& dx, double factor) override;
  void accFromF(VecDeriv& a, const VecDeriv& f) override;
  void addMToMatrix(MatrixAccumulator& matrix, std::size_t offset, double factor) override;
  double kineticEnergy(const VecDeriv& v) const override;
  bool isDiagonal() const override { return true; }

 private:
  template <class F>
  void forEachPoint(std::size_t n, F&& f) const;
};

}  // namespace stroma
