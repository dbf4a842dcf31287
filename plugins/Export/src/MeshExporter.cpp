// SPDX-License-Identifier: MIT
#include "MeshExporter.h"

#include "MeshFiles.h"
#include "OutputFile.h"
#include "StateMesh.h"
#include "core/Node.h"
#include "simulation/MechanicalState.h"
#include "topology/Topology.h"

namespace stroma {

namespace {

std::string outputBase(const std::string& filename) {
  for (const char* extension : {".vtu", ".vtk", ".msh", ".node", ".ele", ".mesh"})
    if (filename.ends_with(extension)) return stripExtension(filename, extension).string();
  return filename;
}

}  // namespace

void MeshExporter::init() {
  m_ready = false;
  if (d_format.value() == MeshExportFormat::netgen) {
    msgError("format 'netgen' is not written by Stroma; use vtkxml, vtk, gmsh or tetgen", "format");
    return setInvalid();
  }
  if (!checkOutputFolder(*this, outputBase(d_filename.value().original), "filename"))
    return setInvalid();
  m_ready = true;
}

void MeshExporter::bwdInit() {
  if (m_ready && m_schedule.atBegin()) write(m_schedule.nextFileSuffix());
}

void MeshExporter::stepEnd(double, double) {
  if (m_ready && m_schedule.stepDone()) write(m_schedule.nextFileSuffix());
}

void MeshExporter::cleanup() {
  if (m_ready && m_schedule.atEnd()) write(m_schedule.nextFileSuffix());
  m_ready = false;
}

void MeshExporter::write(const std::string& suffix) {
  vtk::UnstructuredMesh mesh;
  vtk::CellSelection selection;
  selection.edges = d_edges.value();
  selection.triangles = d_triangles.value();
  selection.quads = d_quads.value();
  selection.tetrahedra = d_tetras.value();
  selection.hexahedra = d_hexas.value();
  std::string error;
  if (!vtk::nodeMesh(node(), d_position.value(), selection, mesh, error)) {
    msgError("the topology does not fit the points: " + error);
    m_ready = false;
    return;
  }

  const std::string base = outputBase(d_filename.value().original) + suffix;
  const MeshExportFormat format = d_format.value();
  const bool all = format == MeshExportFormat::ALL;
  auto fail = [&](const std::string& why) {
    msgError(why, format == MeshExportFormat::tetgen ? "format" : "filename");
    m_ready = false;
  };
  if (all || format == MeshExportFormat::vtkxml) {
    if (!vtk::writeVtu(base + ".vtu", mesh, error)) return fail(error);
    m_written.push_back(base + ".vtu");
  }
  if (all || format == MeshExportFormat::vtk) {
    if (!vtk::writeVtkLegacy(base + ".vtk", mesh, error)) return fail(error);
    m_written.push_back(base + ".vtk");
  }
  if (all || format == MeshExportFormat::gmsh) {
    if (!vtk::writeGmsh(base + ".msh", mesh, error)) return fail(error);
    m_written.push_back(base + ".msh");
  }
  if (all || format == MeshExportFormat::tetgen) {
    // With ALL, a mesh that is not only tetrahedra skips TetGen's format (it has no other cell).
    bool onlyTetrahedra = mesh.cellCount() > 0;
    for (auto type : mesh.cellTypes)
      onlyTetrahedra = onlyTetrahedra && type == vtk::CellType::tetra;
    if (!all || onlyTetrahedra) {
      if (!vtk::writeTetgen(base, mesh, error)) return fail(error);
      m_written.push_back(base + ".node");
      m_written.push_back(base + ".ele");
    }
  }
}

}  // namespace stroma
