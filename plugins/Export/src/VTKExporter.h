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

class BaseData;

/// SOFA's VTKExporter: writes the points and elements of its node's topology, and Data of the
/// node's components as point or cell fields, to VTK files during the run.
///
/// Points: `position` when given, else the node's mechanical state's positions, else the
/// topology's. Cells: the element lists switched on (edges, triangles, quads, tetras, hexas);
/// one vertex per point when none gives a cell. Fields: "object.field" names of Data in this
/// node (pointsDataFields: one value or vector per point; cellsDataFields: per cell), their
/// numbers split evenly over the points or cells, each array named by its Data's name (as
/// SOFA's; the whole entry when two share a name). Files: `filename` as given + the file's number
/// (0, 1, ...) + ".vtu" (XMLformat) or ".vtk", as SOFA's (filename="example.vtk" gives
/// example.vtk0.vtu); `filename` + the extension, rewritten each time, with overwrite. When:
/// exportEveryNumberOfSteps, exportAtBegin, exportAtEnd (ExportSchedule.h).
class VTKExporter final : public Base, public StepListener {
 public:
  Data<FileName> d_filename{this,
                            "filename",
                            {},
                            "Output file name, without extension; relative to the working "
                            "folder.",
                            {.output = true}};
  Data<bool> d_XMLformat{this, "XMLformat", true,
                         "Write VTK XML UnstructuredGrid (.vtu) files; false: the legacy ASCII "
                         "format (.vtk)."};
  Data<std::vector<Vec3d>> d_position{this,
                                      "position",
                                      {},
                                      "Points to write (nbPoints x 3); empty: the positions of "
                                      "the node's mechanical state, else of its topology.",
                                      {.unit = "m"}};
  Data<bool> d_edges{this, "edges", true, "Write the topology's edges as cells."};
  Data<bool> d_triangles{this, "triangles", false, "Write the topology's triangles as cells."};
  Data<bool> d_quads{this, "quads", false, "Write the topology's quads as cells."};
  Data<bool> d_tetras{this, "tetras", false, "Write the topology's tetrahedra as cells."};
  Data<bool> d_hexas{this, "hexas", false, "Write the topology's hexahedra as cells."};
  Data<std::vector<std::string>> d_pointsDataFields{
      this,
      "pointsDataFields",
      {},
      "Data written per point, as object.field names in this node (\"dofs.velocity\")."};
  Data<std::vector<std::string>> d_cellsDataFields{
      this, "cellsDataFields", {}, "Data written per cell, as object.field names in this node."};
  ExportSchedule m_schedule{*this};
  Data<bool> d_overwrite{this, "overwrite", false,
                         "Rewrite one file (filename.vtu) instead of numbering them."};

  void init() override;
  void bwdInit() override;
  void cleanup() override;
  void stepEnd(double time, double dt) override;

  /// Files written so far.
  const std::vector<std::string>& writtenFiles() const { return m_written; }

 private:
  bool resolveFields(const std::vector<std::string>& names, std::vector<const BaseData*>& out,
                     const std::string& field);
  void write();

  std::vector<const BaseData*> m_pointFields, m_cellFields;
  std::vector<std::string> m_written;
  bool m_ready = false;
};

}  // namespace stroma
