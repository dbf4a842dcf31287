// SPDX-License-Identifier: MIT
#pragma once

#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "ExportSchedule.h"
#include "core/Base.h"
#include "core/Data.h"
#include "core/DataTraits.h"
#include "core/Types.h"
#include "simulation/StepListener.h"

namespace stroma {

/// SOFA's MeshExporter formats. netgen is refused at init (Stroma writes no Netgen file);
/// ALL writes every other format.
enum class MeshExportFormat { ALL, vtkxml, vtk, netgen, tetgen, gmsh };

template <>
struct EnumKeywords<MeshExportFormat> {
  static constexpr std::array<std::string_view, 6> names{"ALL",    "vtkxml", "vtk",
                                                         "netgen", "tetgen", "gmsh"};
};

/// SOFA's MeshExporter: writes the mesh of its node (points of `position`, else of the node's
/// mechanical state, else of its topology; the element lists switched on) in a mesh format:
/// vtkxml (.vtu), vtk (legacy ASCII .vtk), gmsh (.msh 2.2 ASCII), tetgen (.node + .ele,
/// tetrahedra only: refused with an error when other cells are selected and present). Files:
/// `filename` (a known extension dropped) + the export's number on 5 digits from 00001 + ".ext"
/// when exportEveryNumberOfSteps > 0 (as SOFA's: outFile00001.vtk), else `filename.ext`.
/// When: ExportSchedule.h.
class MeshExporter final : public Base, public StepListener {
 public:
  Data<FileName> d_filename{this,
                            "filename",
                            {},
                            "Output file name, without extension; relative to the working "
                            "folder.",
                            {.output = true}};
  Data<MeshExportFormat> d_format{this, "format", MeshExportFormat::vtkxml,
                                  "File format: vtkxml, vtk, gmsh, tetgen, or ALL of them "
                                  "(netgen is refused)."};
  Data<std::vector<Vec3d>> d_position{this,
                                      "position",
                                      {},
                                      "Points to write (nbPoints x 3); empty: the positions of "
                                      "the node's mechanical state, else of its topology.",
                                      {.unit = "m"}};
  Data<bool> d_edges{this, "edges", true, "Write the topology's edges."};
  Data<bool> d_triangles{this, "triangles", true, "Write the topology's triangles."};
  Data<bool> d_quads{this, "quads", true, "Write the topology's quads."};
  Data<bool> d_tetras{this, "tetras", true, "Write the topology's tetrahedra."};
  Data<bool> d_hexas{this, "hexas", true, "Write the topology's hexahedra."};
  ExportSchedule m_schedule{*this};

  void init() override;
  void bwdInit() override;
  void cleanup() override;
  void stepEnd(double time, double dt) override;

  /// Files written so far.
  const std::vector<std::string>& writtenFiles() const { return m_written; }

 private:
  void write(const std::string& suffix);

  std::vector<std::string> m_written;
  bool m_ready = false;
};

}  // namespace stroma
