// SPDX-License-Identifier: MIT
#pragma once

#include "MeshLoader.h"

namespace stroma {

/// Reads VTK files: legacy .vtk (ASCII or binary) and XML .vtu/.vtp, told apart by content.
class MeshVTKLoader final : public MeshLoader {
 public:
  MeshVTKLoader() : MeshLoader(MeshFormat::vtk) {}
};

}  // namespace stroma
