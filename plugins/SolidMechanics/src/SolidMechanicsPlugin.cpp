// SPDX-License-Identifier: MIT
#include "HexahedronFEMForceField.h"
#include "HexahedronFEMForceFieldAndMass.h"
#include "TetrahedronFEMForceField.h"
#include "TriangularFEMForceField.h"
#include "core/Plugin.h"

namespace {

void registerComponents(stroma::PluginRegistry& registry) {
  using namespace stroma;
  // SOFA's TetrahedralCorotationalFEMForceField and FastTetrahedralCorotationalForceField are
  // the same corotational linear tetrahedron with the same default method (large, which the
  // latter calls qr) and a subset of these attributes.
  registry.add("TetrahedronFEMForceField", "Corotational linear elasticity on tetrahedra")
      .with<TetrahedronFEMForceField>("Vec3d")
      .alias("TetrahedralCorotationalFEMForceField")
      .alias("FastTetrahedralCorotationalForceField");
  // SOFA's HexahedralFEMForceField(AndMass) is the same element, written for topological
  // changes; its scenes use youngModulus, poissonRatio and method (large or polar) only.
  registry.add("HexahedronFEMForceField", "Corotational linear elasticity on hexahedra")
      .with<HexahedronFEMForceField>("Vec3d")
      .alias("HexahedralFEMForceField");
  registry
      .add("HexahedronFEMForceFieldAndMass",
           "Corotational linear elasticity and the consistent or lumped mass of hexahedra")
      .with<HexahedronFEMForceFieldAndMass>("Vec3d")
      .alias("HexahedralFEMForceFieldAndMass");
  // SOFA's TriangleFEMForceField and TriangularFEMForceFieldOptim are the same corotational
  // constant-strain membrane with the same default method (large); each name's own attributes
  // (thickness, planeStrain; restScale) are accepted under all three.
  registry
      .add("TriangularFEMForceField",
           "Corotational linear elastic membrane on triangles (plane stress)")
      .with<TriangularFEMForceField>("Vec3d")
      .alias("TriangleFEMForceField")
      .alias("TriangularFEMForceFieldOptim");
}

}  // namespace

extern "C" STROMA_PLUGIN_EXPORT const stroma::PluginEntry* stroma_plugin_entry() {
  static const stroma::PluginEntry entry = stroma::makePluginEntry(
      "SolidMechanics", "0.1.0",
      "Finite-element force fields (tetrahedra, hexahedra, membrane triangles)",
      registerComponents);
  return &entry;
}
