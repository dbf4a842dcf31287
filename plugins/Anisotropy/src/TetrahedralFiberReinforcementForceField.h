// SPDX-License-Identifier: MIT
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "Anisotropy/kernels/TransverselyIsotropicMaterial.h"
#include "SolidMechanics/kernels/LinearTetrahedron.h"
#include "core/DataTraits.h"
#include "core/StateTypes.h"
#include "simulation/ForceField.h"
#include "topology/Topology.h"

namespace stroma {

/// The `method` keyword of TetrahedralFiberReinforcementForceField: small strain, or
/// corotational with the polar rotation of each element (large is accepted as polar, so that
/// the reinforcement reads like the corotational isotropic field beside it).
enum class FiberMethod { small, large, polar };

template <>
struct EnumKeywords<FiberMethod> {
  static constexpr std::array<std::string_view, 3> names{"small", "large", "polar"};
};

/// The anisotropic part of Spencer's transversely isotropic linear elasticity on linear
/// tetrahedra (TransverselyIsotropicMaterial.h), to be added to an isotropic force field on the
/// same tetrahedra (TetrahedralTensorMassForceField, TetrahedronFEMForceField method="small",
/// ...) whose Lame parameters are the material's (lambda, mu_T): together they are the
/// transversely isotropic material. With the unit fiber direction a of each tetrahedron, its
/// rest volume V, the strain eps = B u of its nodal displacements u = x - X (X: the state's rest
/// positions at init) and the Voigt matrix C_r of the reinforcement,
///
///   E_e = V (alpha (tr eps)(a.eps a) + 2 (mu_L - mu_T) a.eps^2 a + beta/2 (a.eps a)^2)
///       = 1/2 u^T Ke u,   Ke = V B^T C_r B,   f = -Ke u,   df = -Ke dx.
///
/// method="small": linear, not rotation invariant (like its isotropic partner with
/// method="small"). Ke is not definite in general (the reinforcement can soften), only the sum
/// with the isotropic part is. method="polar" (or "large"): corotational, the same energy of the
/// strain S - I in the frame of the polar rotation of each element, F = R S, so that the fibers
/// turn with the element; forces and tangent are the exact derivatives of that energy, rotation
/// included (CorotationalReinforcement.h), the tangent recomputed at each addForce.
///
/// The material is given either by the engineering constants of the fiber-reinforced material
/// (youngModulusL, youngModulusT, poissonRatioLT, poissonRatioTT, shearModulusLT: all five),
/// from which it derives lambda, mu_T, alpha, beta, mu_L, reports at init the youngModulus and
/// poissonRatio the isotropic field must have, writes them to isotropicYoungModulus and
/// isotropicPoissonRatio (which that field can link to), and warns when a force field beside it
/// has other values; or by Spencer's parameters (alpha, beta, shearModulusL, shearModulusT: all
/// four; mu_T must be the isotropic field's shear modulus E / (2 (1 + nu))).
///
/// Bad input (errors naming the field): both or neither set of parameters, one missing, a
/// material that is not positive definite, a zero fiber direction, a per-element list whose
/// size is not the number of tetrahedra, no tetrahedra, flat rest tetrahedra. Changes of the
/// parameters or fiber directions while running take effect at the next addForce (an invalid
/// change is a warning and the previous values stay). Tetrahedra removed by the topology
/// (cutting, Topology::removeTetrahedra) are followed incrementally: the element data and
/// fiberDirections are renumbered as the topology's (TopologyChange.h); any other change of the
/// elements or of the state's size rebuilds everything.
class TetrahedralFiberReinforcementForceField final : public ForceField<Vec3Types> {
 public:
  Data<Vec3d> d_fiberDirection{this, "fiberDirection", Vec3d(1, 0, 0),
                               "Fiber direction of every tetrahedron (normalized; not zero)."};
  Data<std::vector<Vec3d>> d_fiberDirections{
      this,
      "fiberDirections",
      {},
      "Fiber direction of each tetrahedron (nbTetrahedra x 3, normalized; none zero); when "
      "given, replaces fiberDirection."};

  Data<FiberMethod> d_method{
      this, "method", FiberMethod::small,
      "small: linear (small strain); polar: corotational, the strain measured in the polar "
      "rotation of each element, fibers turning with it (exact tangent); large: as polar."};

  Data<double> d_youngModulusL{
      this, "youngModulusL", 0.0, "E_L: Young's modulus along the fiber, > 0.", {.unit = "Pa"}};
  Data<double> d_youngModulusT{
      this, "youngModulusT", 0.0, "E_T: Young's modulus across the fiber, > 0.", {.unit = "Pa"}};
  Data<double> d_poissonRatioLT{this, "poissonRatioLT", 0.0,
                                "nu_LT: contraction across the fiber per unit extension along it "
                                "(load along the fiber); nu_LT^2 < (1 - nu_TT) E_L / (2 E_T)."};
  Data<double> d_poissonRatioTT{this, "poissonRatioTT", 0.0,
                                "nu_TT: Poisson's ratio in the plane across the fiber, "
                                "-1 < nu_TT < 1."};
  Data<double> d_shearModulusLT{this,
                                "shearModulusLT",
                                0.0,
                                "G_LT: shear modulus of the planes that contain the fiber, > 0.",
                                {.unit = "Pa"}};

  Data<double> d_alpha{this,
                       "alpha",
                       0.0,
                       "Spencer's alpha (instead of the engineering constants): the coupling "
                       "term alpha (tr eps)(a.eps a).",
                       {.unit = "Pa"}};
  Data<double> d_beta{this,
                      "beta",
                      0.0,
                      "Spencer's beta (instead of the engineering constants): the term "
                      "beta/2 (a.eps a)^2.",
                      {.unit = "Pa"}};
  Data<double> d_shearModulusL{this,
                               "shearModulusL",
                               0.0,
                               "Spencer's mu_L (instead of the engineering constants): shear "
                               "modulus along the fiber, > 0.",
                               {.unit = "Pa"}};
  Data<double> d_shearModulusT{this,
                               "shearModulusT",
                               0.0,
                               "Spencer's mu_T (with alpha, beta, shearModulusL): the shear "
                               "modulus of the isotropic force field beside, E / (2 (1 + nu)), "
                               "> 0.",
                               {.unit = "Pa"}};

  Data<double> d_isotropicYoungModulus{
      this,
      "isotropicYoungModulus",
      0.0,
      "Output: the youngModulus of the isotropic part, for the isotropic force field beside "
      "(engineering constants only).",
      {.unit = "Pa", .output = true}};
  Data<double> d_isotropicPoissonRatio{this,
                                       "isotropicPoissonRatio",
                                       0.0,
                                       "Output: the poissonRatio of the isotropic part, for the "
                                       "isotropic force field beside (engineering constants "
                                       "only).",
                                       {.output = true}};

  Link<Topology> l_topology{this, "topology",
                            "Topology holding the tetrahedra (default: the node's or above)."};

  void init() override;
  /// Compares the isotropic force fields beside it (same state) with the material.
  void bwdInit() override;
  void reinit() override {
    init();
    bwdInit();
  }

  void addForce(const MechanicalParams& mp, VecDeriv& f, const VecCoord& x,
                const VecDeriv& v) override;
  void addDForce(const MechanicalParams& mp, VecDeriv& df, const VecDeriv& dx) override;
  void addKToMatrix(const MechanicalParams& mp, MatrixAccumulator& matrix,
                    std::size_t offset) override;
  double potentialEnergy(const MechanicalParams& mp, const VecCoord& x) const override;

  /// The material's parameters (after init; lambda is 0 when given by Spencer's parameters).
  const anisotropy::SpencerParameters& parameters() const { return m_parameters; }
  /// Ke of each tetrahedron (after init); with method polar, the tangent d2E/dx2 at the last
  /// addForce.
  const std::vector<fem::Matrix12d>& elementStiffness() const { return m_stiffness; }

 private:
  bool readMesh();
  std::optional<anisotropy::SpencerParameters> readMaterial(bool atInit);
  bool readFibers(bool atInit, std::vector<Vec3d>& directions);
  bool build(bool atInit);
  bool refresh();
  bool followRemovals();
  void compareWithIsotropicNeighbours(bool atInit);
  std::uint64_t parameterVersion() const;
  void addCorotationalForce(VecDeriv& f, const VecCoord& x);
  /// Calls element(t) for every tetrahedron, in parallel on the scene's threads.
  template <class Element>
  void computeElements(const Element& element);
  /// f += m_elementForces, summed per point in element order.
  void addElementForces(VecDeriv& f) const;
  static constexpr std::size_t kGrain = 128;
  const fem::Matrix6d& elasticity(std::size_t t) const {
    return m_elasticity.size() == 1 ? m_elasticity[0] : m_elasticity[t];
  }
  void report(bool atInit, const std::string& text, const std::string& field);

  const Topology* m_topology = nullptr;
  std::uint64_t m_topologyRevision = 0;
  std::size_t m_pointCount = 0;
  std::vector<Tetrahedron> m_tetrahedra;
  std::vector<Vec3d> m_restPositions;
  std::vector<fem::TetrahedronShape> m_shapes;  // gradients and volume of each rest tetrahedron
  std::vector<fem::Matrix6d> m_elasticity;      // C_r: one, or one per tetrahedron
  std::vector<fem::Matrix12d> m_stiffness;      // Ke of each tetrahedron (polar: the tangent)
  std::vector<fem::TetrahedronVectors> m_elementForces;  // scratch: per-element results
  std::vector<char> m_elementInverted;                   // scratch (polar)
  std::size_t m_invertedWarnings = 0;                    // polar: inverted elements reported so far
  anisotropy::SpencerParameters m_parameters;
  bool m_engineering = true;  // the material came from the engineering constants
  std::uint64_t m_parameterVersion = 0;
  bool m_ready = false;
};

}  // namespace stroma
