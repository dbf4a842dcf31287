// SPDX-License-Identifier: MIT
#pragma once

#include "MeshLoader.h"

namespace stroma {

/// Reads Gmsh .msh files (versions 1, 2.x and 4.1, ASCII and binary; see formats/MeshData.h).
class MeshGmshLoader final : public MeshLoader {
 public:
  MeshGmshLoader() : MeshLoader(MeshFormat::gmsh) {}
};

}  // namespace stroma
