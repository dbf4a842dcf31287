// SPDX-License-Identifier: MIT
#pragma once

#include <array>
#include <cstdint>
#include <string_view>
#include <vector>

#include "TensorMass/kernels/HyperelasticTetrahedron.h"
#include "TetrahedralMesh.h"
#include "core/DataTraits.h"
#include "simulation/ForceField.h"

namespace stroma {

/// SOFA's material names. Stroma implements StVenantKirchhoff and NeoHookean; the others are
/// accepted by the parser so that init can say so.
enum class HyperelasticMaterialName {
  ArrudaBoyce,
  StVenantKirchhoff,
  NeoHookean,
  MooneyRivlin,
  VerondaWestman,
  Costa,
  Ogden
};

template <>
struct EnumKeywords<HyperelasticMaterialName> {
  static constexpr std::array<std::string_view, 7> names{
      "ArrudaBoyce", "StVenantKirchhoff", "NeoHookean", "MooneyRivlin", "VerondaWestman", "Costa",
      "Ogden"};
};

/// Hyperelastic tetrahedra computed element by element (SOFA's
/// StandardTetrahedralFEMForceField): per element, P = dW/dF and f_j = -V P alpha_j, the exact
/// tangent df = -V dP alpha_j (HyperelasticTetrahedron.h), W integrated over the rest volume.
///
/// materialName: StVenantKirchhoff (W = lambda/2 (tr E)^2 + mu tr E^2, seed 004 eq. 10: the
/// same forces as TetrahedralStVKTensorMassForceField, element by element) or NeoHookean
/// (compressible, W = mu/2 (I1 - 3) - mu ln J + lambda/2 (ln J)^2). SOFA's other materials and
/// its default, ArrudaBoyce, are errors at init. Parameters: ParameterSet = "mu lambda" (Pa)
/// as SOFA writes it for StVenantKirchhoff, or youngModulus and poissonRatio; not both. (SOFA's
/// NeoHookean reads "mu k" and has another volumetric term; with ParameterSet Stroma reads
/// the second number as lambda.)
///
/// Bad input: flat or inverted rest tetrahedra, a material out of range (errors naming the
/// field). A neo-Hookean element that inverts while running (det F <= 0) gives no force while
/// inverted, with a warning the first time.
class StandardTetrahedralFEMForceField final : public ForceField<Vec3Types> {
 public:
  Data<HyperelasticMaterialName> d_materialName{
      this, "materialName", HyperelasticMaterialName::ArrudaBoyce,
      "Material law: StVenantKirchhoff or NeoHookean (SOFA's default ArrudaBoyce, and "
      "MooneyRivlin, VerondaWestman, Costa, Ogden, are not implemented: an error)."};
  Data<std::vector<double>> d_parameterSet{
      this,
      "ParameterSet",
      {},
      "Material parameters as SOFA writes them: \"mu lambda\" (Pa) for StVenantKirchhoff and "
      "NeoHookean (SOFA's NeoHookean reads \"mu k\", k a bulk modulus with another "
      "volumetric term: here the second number is lambda). Empty: from youngModulus and "
      "poissonRatio.",
      {.unit = "Pa"}};
  Data<double> d_youngModulus{this,
                              "youngModulus",
                              1000.0,
                              "Young's modulus, > 0, when ParameterSet is not given.",
                              {.unit = "Pa", .min = 0.0}};
  Data<double> d_poissonRatio{this,
                              "poissonRatio",
                              0.3,
                              "Poisson's ratio, -1 < nu < 0.5, when ParameterSet is not given.",
                              {.min = -1.0, .max = 0.5}};
  Link<Topology> l_topology{this, "topology",
                            "Topology holding the tetrahedra (default: the node's or above)."};

  void init() override;
  void reinit() override { init(); }

  void addForce(const MechanicalParams& mp, VecDeriv& f, const VecCoord& x,
                const VecDeriv& v) override;
  void addDForce(const MechanicalParams& mp, VecDeriv& df, const VecDeriv& dx) override;
  void addKToMatrix(const MechanicalParams& mp, MatrixAccumulator& matrix,
                    std::size_t offset) override;
  double potentialEnergy(const MechanicalParams& mp, const VecCoord& x) const override;

  /// The Lame parameters in use (after init).
  const fem::LameParameters& lameParameters() const { return m_lame; }

 private:
  bool readMaterial(bool atInit);
  bool refresh();

  struct Element {
    Tetrahedron vertices;
    fem::TetrahedronVectors alpha;  // shape vectors (1/m)
    double volume;                  // rest volume (m^3)
  };

  TetrahedralMesh m_mesh;
  tensormass::HyperelasticMaterial m_material = tensormass::HyperelasticMaterial::stVenantKirchhoff;
  fem::LameParameters m_lame;
  std::vector<Element> m_elements;
  std::vector<tensormass::MaterialPoint> m_points;  // at the last addForce
  std::vector<char> m_inverted;                     // at the last addForce (neo-Hookean)
  bool m_inversionReported = false;
  std::uint64_t m_materialVersion = 0;
  bool m_ready = false;
};

}  // namespace stroma
