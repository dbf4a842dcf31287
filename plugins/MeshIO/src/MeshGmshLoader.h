// SPDX-License-Identifier: MIT
#pragma once

#include "MeshLoader.h"

namespace stroma {

/// Reads Gmsh .msh files (versions 1, 2.x and 4.1, ASCII and binary; see formats/MeshData.h),
/// with the physical group of each volume element, so that a scene can give each region of a
/// mesh its own material or zone (`elementGroups="@loader.tetrahedraPhysicalGroups"`).
class MeshGmshLoader final : public MeshLoader {
 public:
  Data<std::vector<int>> d_tetrahedraPhysicalGroups{
      this,
      "tetrahedraPhysicalGroups",
      {},
      "Physical group of each tetrahedron (nbTetrahedra; 0: in no group), as the file tags it.",
      {.output = true}};
  Data<std::vector<int>> d_hexahedraPhysicalGroups{
      this,
      "hexahedraPhysicalGroups",
      {},
      "Physical group of each hexahedron (nbHexahedra; 0: in no group), as the file tags it.",
      {.output = true}};

  MeshGmshLoader() : MeshLoader(MeshFormat::gmsh) {
    addOutput(&d_tetrahedraPhysicalGroups);
    addOutput(&d_hexahedraPhysicalGroups);
  }

 protected:
  void setFormatOutputs(const MeshData& mesh) override {
    d_tetrahedraPhysicalGroups.setValue(mesh.tetrahedronGroups);
    d_hexahedraPhysicalGroups.setValue(mesh.hexahedronGroups);
  }
  void clearFormatOutputs() override {
    d_tetrahedraPhysicalGroups.setValue({});
    d_hexahedraPhysicalGroups.setValue({});
  }
};

}  // namespace stroma
