// SPDX-License-Identifier: MIT
#pragma once

#include "MeshLoader.h"

namespace stroma {

/// Reads STL files, ASCII or binary; points repeated by the triangles are merged.
class MeshSTLLoader final : public MeshLoader {
 public:
  Data<unsigned> d_headerSize{this,
                              "headerSize",
                              80,
                              "Bytes of the binary header before the triangle count.",
                              {.max = 1e6, .autoLink = false}};
  Data<bool> d_forceBinary{this,
                           "forceBinary",
                           false,
                           "Read as binary even when the file starts with 'solid'.",
                           {.autoLink = false}};
  Data<bool> d_mergePositionUsingMap{
      this,
      "mergePositionUsingMap",
      true,
      "Merge the points at the same position (STL repeats them for each triangle).",
      {.autoLink = false}};

  MeshSTLLoader() : MeshLoader(MeshFormat::stl) {
    addInput(&d_headerSize);
    addInput(&d_forceBinary);
    addInput(&d_mergePositionUsingMap);
  }

 protected:
  MeshParseOptions parseOptions() const override {
    MeshParseOptions options;
    options.stlHeaderSize = d_headerSize.value();
    options.forceBinary = d_forceBinary.value();
    options.mergePositions = d_mergePositionUsingMap.value();
    return options;
  }
};

}  // namespace stroma
