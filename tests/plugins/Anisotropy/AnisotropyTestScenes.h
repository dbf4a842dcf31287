// SPDX-License-Identifier: MIT
// What the Anisotropy tests share: the reinforcement's XML for a material given by its
// engineering constants, and the fiber-reinforced tissue the tests use.
#pragma once

#include <cstdio>
#include <string>
#include <vector>

#include "Anisotropy/kernels/TransverselyIsotropicMaterial.h"
#include "core/StateTypes.h"

namespace stroma::test {

/// Fibers 6 times stiffer than the matrix (TransverselyIsotropicMaterial_test.cpp).
inline constexpr anisotropy::EngineeringConstants kTissue{.youngModulusL = 30e3,
                                                          .youngModulusT = 5e3,
                                                          .poissonRatioLT = 0.35,
                                                          .poissonRatioTT = 0.45,
                                                          .shearModulusLT = 4e3};

inline std::string exact(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", value);
  return text;
}

inline std::string vectorText(const Vec3d& v) {
  return exact(v.x()) + " " + exact(v.y()) + " " + exact(v.z());
}

/// The attributes of the engineering constants c.
inline std::string constantsText(const anisotropy::EngineeringConstants& c) {
  return "youngModulusL=\"" + exact(c.youngModulusL) + "\" youngModulusT=\"" +
         exact(c.youngModulusT) + "\" poissonRatioLT=\"" + exact(c.poissonRatioLT) +
         "\" poissonRatioTT=\"" + exact(c.poissonRatioTT) + "\" shearModulusLT=\"" +
         exact(c.shearModulusLT) + "\"";
}

/// A TetrahedralFiberReinforcementForceField named "fibers" with the constants c, fibers along
/// `direction`, or per element along `directions` when not empty.
inline std::string fiberField(const anisotropy::EngineeringConstants& c, const Vec3d& direction,
                              const std::vector<Vec3d>& directions = {}) {
  std::string fibers = "fiberDirection=\"" + vectorText(direction) + "\"";
  if (!directions.empty()) {
    fibers = "fiberDirections=\"";
    for (const Vec3d& a : directions) fibers += vectorText(a) + "  ";
    fibers += "\"";
  }
  return "<TetrahedralFiberReinforcementForceField name=\"fibers\" " + constantsText(c) + " " +
         fibers + "/>";
}

/// The isotropic part of c, as the attributes of an isotropic force field.
inline std::string isotropicPartText(const anisotropy::EngineeringConstants& c) {
  const anisotropy::SpencerParameters p = anisotropy::computeSpencerParameters(c);
  const anisotropy::IsotropicConstants iso = anisotropy::computeIsotropicConstants(p.lambda, p.muT);
  return "youngModulus=\"" + exact(iso.youngModulus) + "\" poissonRatio=\"" +
         exact(iso.poissonRatio) + "\"";
}

}  // namespace stroma::test
