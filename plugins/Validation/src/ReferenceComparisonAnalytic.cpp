// SPDX-License-Identifier: MIT
// ReferenceComparison's analytic references: the compared points and their reference
// positions (or, for the cantilever, deflections) from the kernels of
// plugins/Validation/kernels, with the checks of their parameters.
#include <cmath>

#include "ReferenceComparison.h"
#include "Validation/kernels/AffinePatch.h"
#include "Validation/kernels/CantileverBeam.h"
#include "Validation/kernels/CylinderTorsion.h"
#include "Validation/kernels/LameCylinder.h"
#include "Validation/kernels/UniaxialStretch.h"
#include "core/Message.h"

namespace stroma {

bool ReferenceComparison::prepareAnalytic(const State::VecCoord& rest) {
  using namespace reference;
  const std::size_t n = rest.size();
  const AnalyticReference kind = d_analytic.value();
  const Vec3d origin = d_origin.value();
  if (d_axis.value().norm() == 0) {
    msgError("the axis is zero", "axis");
    return false;
  }
  const Vec3d axis = d_axis.value().normalized();

  // Compared points: `indices`, else all (cantileverTip: those of the free end's section).
  std::vector<unsigned> points;
  if (!selectIndices(n, "state points", points)) return false;
  if (kind == AnalyticReference::cantileverTip && d_indices.value().empty())
    std::erase_if(points, [&](unsigned i) {
      return std::abs((rest[i] - origin).dot(axis) - d_length.value()) > 1e-6 * d_length.value();
    });
  if (points.empty()) {
    if (kind == AnalyticReference::cantileverTip)
      msgError("no state point lies at the free end (distance length = " +
                   formatNumber(d_length.value()) + " from origin along axis): set indices",
               "length");
    else
      msgError("the state has no point", "state");
    return false;
  }
  m_pointIndex = m_reportIndex = points;
  for (unsigned i : points) m_rest.push_back(rest[i]);

  switch (kind) {
    case AnalyticReference::cantileverTip:
    case AnalyticReference::cantileverCurve: {
      CantileverBeam beam;
      beam.length = d_length.value();
      beam.height = d_sectionHeight.value();
      beam.width = d_sectionWidth.value();
      beam.youngModulus = d_youngModulus.value();
      beam.poissonRatio = d_poissonRatio.value();
      beam.tipForce = d_tipForce.value();
      beam.lineLoad = d_lineLoad.value();
      beam.shearCorrection = d_shearCorrection.value();
      beam.theory = d_beamTheory.value() == ReferenceBeamTheory::timoshenko
                        ? BeamTheory::timoshenko
                        : BeamTheory::eulerBernoulli;
      if (!beam.isValid()) {
        msgError(
            "the beam needs length, sectionHeight, sectionWidth, youngModulus > 0 and -1 < "
            "poissonRatio < 0.5",
            "youngModulus");
        return false;
      }
      if (d_loadDirection.value().norm() == 0) {
        msgError("the load direction is zero", "loadDirection");
        return false;
      }
      if (std::abs(d_loadDirection.value().normalized().dot(axis)) > 1e-6) {
        msgError("the load direction must be across the beam axis", "loadDirection");
        return false;
      }
      m_deflectionOnly = true;
      for (const Vec3d& X : m_rest)
        m_targetDeflection.push_back(beam.deflection((X - origin).dot(axis)));
      return true;
    }
    case AnalyticReference::uniaxialBlock: {
      UniaxialStretch block;
      block.material = d_material.value() == ReferenceMaterial::linear ? UniaxialMaterial::linear
                       : d_material.value() == ReferenceMaterial::StVenantKirchhoff
                           ? UniaxialMaterial::stVenantKirchhoff
                           : UniaxialMaterial::neoHookean;
      block.youngModulus = d_youngModulus.value();
      block.poissonRatio = d_poissonRatio.value();
      if (!block.isValid()) {
        msgError("the block needs youngModulus > 0 and -1 < poissonRatio < 0.5", "poissonRatio");
        return false;
      }
      const bool byStress = d_nominalStress.isSet();
      const double stretch =
          byStress ? block.stretchForNominalStress(d_nominalStress.value()) : d_stretch.value();
      if (!std::isfinite(block.lateralStretch(stretch))) {
        msgError(byStress ? "no uniaxial state carries this nominal stress for this material"
                          : "no uniaxial state at this stretch for this material (St "
                            "Venant-Kirchhoff: lateral stretch imaginary)",
                 byStress ? "nominalStress" : "stretch");
        return false;
      }
      for (const Vec3d& X : m_rest)
        m_target.push_back(X + block.displacement(X, origin, axis, stretch));
      return true;
    }
    case AnalyticReference::patch: {
      const std::vector<double>& g = d_displacementGradient.value();
      if (g.size() != 9) {
        msgError("expected 9 numbers (du/dX row by row), got " + std::to_string(g.size()),
                 "displacementGradient");
        return false;
      }
      AffinePatch patch;
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) patch.gradient(r, c) = g[static_cast<std::size_t>(3 * r + c)];
      patch.translation = d_translation.value();
      for (const Vec3d& X : m_rest) m_target.push_back(X + patch.displacement(X));
      return true;
    }
    case AnalyticReference::torsion: {
      CylinderTorsion cylinder;
      cylinder.radius = d_radius.value();
      cylinder.length = d_length.value();
      cylinder.torque = d_torque.value();
      cylinder.youngModulus = d_youngModulus.value();
      cylinder.poissonRatio = d_poissonRatio.value();
      if (!cylinder.isValid()) {
        msgError("torsion needs radius, length, youngModulus > 0 and -1 < poissonRatio < 0.5",
                 "radius");
        return false;
      }
      for (const Vec3d& X : m_rest) m_target.push_back(X + cylinder.displacement(X, origin, axis));
      return true;
    }
    case AnalyticReference::lame: {
      LameCylinder cylinder;
      cylinder.innerRadius = d_innerRadius.value();
      cylinder.outerRadius = d_outerRadius.value();
      cylinder.pressure = d_pressure.value();
      cylinder.youngModulus = d_youngModulus.value();
      cylinder.poissonRatio = d_poissonRatio.value();
      if (!cylinder.isValid()) {
        msgError(
            "lame needs 0 < innerRadius < outerRadius, youngModulus > 0 and -1 < "
            "poissonRatio <= 0.5",
            "innerRadius");
        return false;
      }
      for (const Vec3d& X : m_rest) {
        const Vec3d d = X - origin;
        const Vec3d radial = d - d.dot(axis) * axis;
        const double r = radial.norm();
        m_target.push_back(r > 0 ? X + cylinder.radialDisplacement(r) / r * radial : X);
      }
      return true;
    }
    case AnalyticReference::none:
      break;
  }
  return false;
}

}  // namespace stroma
