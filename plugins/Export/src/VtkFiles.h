// SPDX-License-Identifier: MIT
// Writers of VTK files for ParaView and other VTK readers: the XML UnstructuredGrid (.vtu),
// the legacy ASCII format (.vtk) and the XML collection (.pvd) that lists the files of a
// time series. A small library (StromaExportFiles) used by the Export plugin's components and
// by `stroma run --export-vtk`.
//
// Choice: the .vtu data arrays are written in the "ascii" format, every double with the
// shortest decimal text that reads back as the same double (std::to_chars): files are exact,
// readable by any VTK reader, by meshio and by Stroma's own VTU loader (which reads "ascii"
// arrays only), at the cost of about 2.5 times the size of base64 binary.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/Types.h"
#include "topology/TopologyTypes.h"

namespace stroma::vtk {

/// VTK's cell type numbers (vtkCellType.h) of the cells Stroma writes; vertex orders are
/// Stroma's (TopologyTypes.h), which are VTK's for these types.
enum class CellType : int {
  vertex = 1,
  line = 3,
  triangle = 5,
  quad = 9,
  tetra = 10,
  hexahedron = 12
};

/// Number of points of a cell of `type`.
int pointCount(CellType type);

/// A named array of values per point or per cell: `components` numbers per item, item-major.
struct FieldArray {
  std::string name;
  int components = 1;
  std::vector<double> values;
};

/// Points, cells and fields of one unstructured grid.
struct UnstructuredMesh {
  std::vector<Vec3d> points;
  std::vector<CellType> cellTypes;      ///< one per cell
  std::vector<Index> connectivity;      ///< the cells' points, cell after cell
  std::vector<FieldArray> pointFields;  ///< values per point
  std::vector<FieldArray> cellFields;   ///< values per cell

  std::size_t cellCount() const { return cellTypes.size(); }
  void addCell(CellType type, const Index* points) {
    cellTypes.push_back(type);
    connectivity.insert(connectivity.end(), points, points + pointCount(type));
  }
};

/// Checks that fields have points.size() or cellCount() items and cells valid point indices;
/// returns false with `error` saying which.
bool checkMesh(const UnstructuredMesh& mesh, std::string& error);

/// Writes `mesh` as a VTK XML UnstructuredGrid file. False with `error` (the file and why) when
/// the mesh is inconsistent or the file cannot be written.
bool writeVtu(const std::filesystem::path& file, const UnstructuredMesh& mesh, std::string& error);

/// Writes `mesh` as a legacy VTK file (version 3.0, ASCII, DATASET UNSTRUCTURED_GRID; fields
/// as FIELD arrays). Same errors.
bool writeVtkLegacy(const std::filesystem::path& file, const UnstructuredMesh& mesh,
                    std::string& error);

/// One file of a time series: its time and its name relative to the .pvd file.
struct CollectionEntry {
  double time = 0;
  std::string file;
};

/// Writes a ParaView collection (.pvd) listing `entries` in order.
bool writePvd(const std::filesystem::path& file, const std::vector<CollectionEntry>& entries,
              std::string& error);

/// The shortest text that reads back as the same double ("0.1", "1e-300", "nan").
std::string formatNumber(double value);

}  // namespace stroma::vtk
