// SPDX-License-Identifier: MIT
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "SolidMechanics/kernels/CorotationalTriangle.h"
#include "core/DataTraits.h"
#include "core/StateTypes.h"
#include "simulation/ForceField.h"
#include "topology/Topology.h"

namespace stroma {

/// The `method` keyword of the triangle force fields (SOFA's): small or large.
enum class TriangleFemMethod { small, large };

template <>
struct EnumKeywords<TriangleFemMethod> {
  static constexpr std::array<std::string_view, 2> names{"small", "large"};
};

/// Linear elastic membrane on triangles in 3D, corotational constant-strain triangles (SOFA's
/// TriangularFEMForceField; also answers to TriangleFEMForceField and
/// TriangularFEMForceFieldOptim, the same element). Per triangle, with its frame R (kernel
/// CorotationalTriangle.h: e1 along the edge 0-1, n the normal), rest corners p in the rest
/// frame and Ke = t A B^T D B (plane stress, or plane strain with planeStrain):
///
///   u_i = P R^T (x_i - x_0) - p_i,   f_i = R P^T (-Ke u)_i,   E = 1/2 u^T Ke u,
///   K = df/dx = -T Ke T^T  (T = diag(R P^T): the corotational tangent, dR/dx ignored, as SOFA).
///
/// `small` keeps the rest frame (linear elasticity, exact f = -dE/dx and K); `large` takes the
/// frame of the current triangle (rigid motions give no force). Membrane only: no bending
/// stiffness, no stiffness across the plane at the rest shape.
///
/// The triangles come from the node's topology (or `topology`); a topology with quads only is
/// split into two triangles per quad, (0 1 2) and (0 2 3). Rest positions are the state's
/// rest_position at init. Constants are computed at init into contiguous arrays, and again at
/// the first step after the material, the topology or the state's size changed.
///
/// Elements are computed in parallel on the scene's threads, each writing its own 3 corners,
/// then added to the vertices in element order: results do not depend on the thread count.
class TriangularFEMForceField final : public ForceField<Vec3Types> {
 public:
  Data<std::vector<double>> d_youngModulus{
      this,
      "youngModulus",
      {1000.0},
      "Young's modulus: one value, or one per triangle (nbTriangles).",
      {.unit = "Pa", .min = 0.0}};
  Data<std::vector<double>> d_poissonRatio{
      this,
      "poissonRatio",
      {0.3},
      "Poisson's ratio, -1 < nu < 0.5: one value, or one per triangle (nbTriangles).",
      {.min = -1.0, .max = 0.5}};
  Data<TriangleFemMethod> d_method{
      this, "method", TriangleFemMethod::large,
      "Rotation of each triangle: small (the rest frame: linear elasticity in the rest plane) or "
      "large (the frame of the current triangle: edge 0-1 and the normal)."};
  Data<double> d_thickness{this,
                           "thickness",
                           1.0,
                           "Thickness of the membrane (TriangleFEMForceField's): the stiffness "
                           "scales with it.",
                           {.unit = "m", .min = 0.0}};
  Data<bool> d_planeStrain{this, "planeStrain", false,
                           "Plane strain instead of plane stress (TriangleFEMForceField's)."};
  Data<double> d_restScale{this,
                           "restScale",
                           1.0,
                           "Scale of the rest shape about each triangle's corner 0 "
                           "(TriangularFEMForceFieldOptim's): below 1 the membrane is stretched "
                           "at its initial positions (pre-tension).",
                           {.min = 0.0}};
  Link<Topology> l_topology{this, "topology",
                            "Topology holding the triangles (default: the node's or above)."};

  // SOFA's output, drawing and fracture options: accepted, without effect on the mechanics.
  Data<bool> d_computeGlobalMatrix{this, "computeGlobalMatrix", false,
                                   "SOFA option, accepted: K is assembled when the linear solver "
                                   "asks for a matrix, and applied matrix-free otherwise."};
  Data<double> d_hosfordExponant{this, "hosfordExponant", 1.0,
                                 "SOFA's exponent of its fracture criterion; accepted, unused "
                                 "(no fracture)."};
  Data<double> d_criteriaValue{this, "criteriaValue", 1e15,
                               "SOFA's fracture threshold; accepted, unused (no fracture)."};
  Data<bool> d_computePrincipalStress{this, "computePrincipalStress", false,
                                      "SOFA's stress output switch; accepted, unused."};
  Data<double> d_stressMaxValue{this, "stressMaxValue", 0.0,
                                "SOFA's stress output; accepted, unused."};
  Data<bool> d_showStressValue{this, "showStressValue", false, "Viewers only."};
  Data<bool> d_showStressVector{this, "showStressVector", false, "Viewers only."};
  Data<bool> d_showFracturableTriangles{this, "showFracturableTriangles", false, "Viewers only."};
  Data<bool> d_showStressMaxValue{this, "showStressMaxValue", false, "Viewers only."};
  Data<std::string> d_showStressColorMap{this, "showStressColorMap", "",
                                         "Viewers only (color map name)."};
  Data<double> d_showStressThreshold{this, "showStressThreshold", 0.0, "Viewers only."};

  void init() override;
  void reinit() override { init(); }

  void addForce(const MechanicalParams& mp, VecDeriv& f, const VecCoord& x,
                const VecDeriv& v) override;
  void addDForce(const MechanicalParams& mp, VecDeriv& df, const VecDeriv& dx) override;
  void addKToMatrix(const MechanicalParams& mp, MatrixAccumulator& matrix,
                    std::size_t offset) override;
  double potentialEnergy(const MechanicalParams& mp, const VecCoord& x) const override;

  /// The triangles computed on (after init), and their constants.
  const std::vector<Triangle>& triangles() const { return m_triangles; }
  const std::vector<fem::CorotationalTriangle>& constants() const { return m_constants; }

 private:
  fem::TriangleMethod method() const {
    return d_method.value() == TriangleFemMethod::small ? fem::TriangleMethod::small
                                                        : fem::TriangleMethod::large;
  }
  /// Reads the triangles of the topology and checks them against the state. Allocates.
  bool readTriangles();
  /// Checks the material against the triangles; reports with msgError (init) or msgWarning
  /// (a change while running). True when valid.
  bool checkMaterial(bool atInit);
  /// Computes the constants from the rest positions; false (with an error) on a degenerate
  /// rest triangle.
  bool computeConstants();
  /// At each addForce: redoes what a change of the topology, the state size or the material
  /// needs. Returns whether the force field can compute.
  bool refresh();
  fem::TriangleVectors corners(const VecCoord& x, std::size_t e) const;
  void sumCorners(VecDeriv& f) const;

  const Topology* m_topology = nullptr;
  bool m_ready = false;
  std::size_t m_stateSize = 0;
  std::uint64_t m_topologyRevision = 0;
  std::array<std::uint64_t, 5> m_materialVersions{};

  std::vector<Triangle> m_triangles;
  std::vector<fem::CorotationalTriangle> m_constants;
  // Per step: the rotation of each triangle at the last addForce (used by addDForce and
  // addKToMatrix of the same step), and each triangle's 3 corner results.
  std::vector<Eigen::Matrix3d> m_rotations;
  std::vector<Vec3d> m_corners;
  double m_kFactor = 0;  ///< of the addDForce in progress
};

}  // namespace stroma
