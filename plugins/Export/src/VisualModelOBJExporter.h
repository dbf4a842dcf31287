// SPDX-License-Identifier: MIT
#pragma once

#include <string>
#include <vector>

#include "ExportSchedule.h"
#include "core/Base.h"
#include "core/Data.h"
#include "core/Types.h"
#include "simulation/StepListener.h"

namespace stroma {

/// SOFA's VisualModelOBJExporter (alias OBJExporter): writes the surfaces of the visual models
/// under its node (VisualModel::surface(), after updateVisual(), as a renderer draws them) to
/// one Wavefront OBJ file with a material library beside it: one object ("o") and one material
/// per model, positions, texture coordinates and normals when the surface has them, triangles.
/// Files: `filename` (an extension .obj dropped) + the export's number on 5 digits from 00001
/// when exportEveryNumberOfSteps > 0 (as SOFA's exporters) + ".obj" and ".mtl". When:
/// ExportSchedule.h. A scene without any visual surface writes an OBJ with no object, and says so
/// once (a warning).
class VisualModelOBJExporter final : public Base, public StepListener {
 public:
  Data<FileName> d_filename{this,
                            "filename",
                            {},
                            "Output file name, without extension; relative to the working "
                            "folder.",
                            {.output = true}};
  ExportSchedule m_schedule{*this};

  void init() override;
  void bwdInit() override;
  void cleanup() override;
  void stepEnd(double time, double dt) override;

  /// OBJ files written so far.
  const std::vector<std::string>& writtenFiles() const { return m_written; }

 private:
  void write(const std::string& suffix);

  std::vector<std::string> m_written;
  bool m_ready = false;
  bool m_warnedEmpty = false;
};

}  // namespace stroma
