// SPDX-License-Identifier: MIT
#pragma once

#include <type_traits>

#include "RigidMass.h"
#include "core/StateTypes.h"
#include "simulation/Mass.h"

namespace stroma {

namespace internal {
/// The mass of one degree of freedom: a number for points, a RigidMass3 for rigid frames.
template <class DataTypes>
struct UniformMassType {
  using Type = double;
  static Type unit() { return 1.0; }
};
template <>
struct UniformMassType<Rigid3Types> {
  using Type = RigidMass3;
  static Type unit() { return RigidMass3{}; }
};
}  // namespace internal

/// The same mass at every point or frame (SOFA's UniformMass): `vertexMass`, or `totalMass`
/// spread evenly. It applies gravity (the node's) as a force m g at each point or frame centre.
///
/// Points (Vec3d, and Vec2d and Vec1d, which take the first 2 or 1 components of the gravity,
/// as SOFA does): M is diagonal, m per coordinate.
/// Rigid frames (Rigid3d): `vertexMass` is "mass volume inertia(9)" (RigidMass.h), the inertia
/// per unit mass in the body frame. Angular velocities are in the world frame (as in
/// MechanicalObject), so the 6x6 block of a frame with orientation R is
///   diag(m I3, m R J R^T),
/// the world inertia (SOFA's UniformMass uses J unrotated; that is only right for an isotropic
/// J). The gyroscopic term w x (I w) is left out, as in SOFA, so a free spinning body about a
/// non-principal axis is not exact. M is block diagonal: isDiagonal() is true, and accFromF
/// inverts each 3x3 block.
///
/// Changing vertexMass or totalMass while running takes effect at the next step (nothing is
/// cached).
template <class DataTypes>
class UniformMass final : public Mass<DataTypes> {
 public:
  using MassType = typename internal::UniformMassType<DataTypes>::Type;
  using typename Mass<DataTypes>::VecCoord;
  using typename Mass<DataTypes>::VecDeriv;
  static constexpr bool kRigid = std::is_same_v<DataTypes, Rigid3Types>;

  Data<MassType> d_vertexMass{this,
                              "vertexMass",
                              internal::UniformMassType<DataTypes>::unit(),
                              kRigid ? "Mass of each frame, 'mass volume inertia(3x3 per unit "
                                       "mass)' (when totalMass is 0)."
                                     : "Mass of each point (when totalMass is 0).",
                              {.unit = "kg", .min = 0.0}};
  Data<double> d_totalMass{this,
                           "totalMass",
                           0.0,
                           "Total mass, spread evenly over the points; 0 to use vertexMass.",
                           {.unit = "kg", .min = 0.0}};
  Data<std::vector<unsigned>> d_indices{
      this, "indices", {}, "Points that have mass (default: all)."};
  Data<FileName> d_filename{this,
                            "filename",
                            {},
                            "SOFA's .rigid mass file: not supported (an error when given).",
                            {.mustExist = false}};
  Data<bool> d_handleTopologicalChanges{this, "handleTopologicalChanges", false,
                                        "SOFA option, accepted: the mass follows the state's "
                                        "size."};
  Data<bool> d_preserveTotalMass{this, "preserveTotalMass", false,
                                 "SOFA option, accepted and without effect yet."};
  Data<double> d_showAxisSizeFactor{this, "showAxisSizeFactor", 1.0, "Viewers only."};
  Link<Base> l_topology{this, "topology", "SOFA option, accepted (the mass is per point)."};

  void init() override;
  void reinit() override { init(); }

  /// The mass of one point or frame now (vertexMass, or totalMass / number with mass).
  MassType pointMass() const;

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
