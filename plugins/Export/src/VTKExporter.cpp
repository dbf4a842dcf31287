// SPDX-License-Identifier: MIT
#include "VTKExporter.h"

#include "OutputFile.h"
#include "StateMesh.h"
#include "VtkFiles.h"
#include "core/Node.h"
#include "core/PathResolver.h"
#include "simulation/MechanicalState.h"
#include "topology/Topology.h"

namespace stroma {

namespace {

/// The numbers of a Data's text ("1 2 3  4 5 6"). False when a token is not a number.
bool readNumbers(const std::string& text, std::vector<double>& values) {
  values.clear();
  std::size_t i = 0;
  while (i < text.size()) {
    while (i < text.size() && (text[i] == ' ' || text[i] == '\n' || text[i] == '\t')) ++i;
    if (i >= text.size()) break;
    std::size_t end = i;
    while (end < text.size() && text[end] != ' ' && text[end] != '\n' && text[end] != '\t') ++end;
    try {
      std::size_t used = 0;
      values.push_back(std::stod(text.substr(i, end - i), &used));
      if (used != end - i) return false;
    } catch (...) {
      return false;
    }
    i = end;
  }
  return true;
}

/// SOFA's VTKExporter keeps the name as given: "example.vtk" gives example.vtk0.vtu, ...
std::string outputBase(const std::string& filename) { return filename; }

}  // namespace

bool VTKExporter::resolveFields(const std::vector<std::string>& names,
                                std::vector<const BaseData*>& out, const std::string& field) {
  out.clear();
  for (const std::string& name : names) {
    std::string why;
    const BaseData* data =
        node() ? resolveDataPath(*node(), name.starts_with('@') ? name : "@" + name, why) : nullptr;
    if (!data) {
      msgError("'" + name + "': " + (why.empty() ? "not found" : why) +
                   " (expected object.field of a component in this node)",
               field);
      return false;
    }
    out.push_back(data);
  }
  return true;
}

void VTKExporter::init() {
  m_ready = false;
  const std::string base = outputBase(d_filename.value().original);
  if (!checkOutputFolder(*this, base, "filename")) return setInvalid();
  if (!resolveFields(d_pointsDataFields.value(), m_pointFields, "pointsDataFields") ||
      !resolveFields(d_cellsDataFields.value(), m_cellFields, "cellsDataFields"))
    return setInvalid();
  m_ready = true;
}

void VTKExporter::bwdInit() {
  if (m_ready && m_schedule.atBegin()) write();
}

void VTKExporter::stepEnd(double, double) {
  if (m_ready && m_schedule.stepDone()) write();
}

void VTKExporter::cleanup() {
  if (m_ready && m_schedule.atEnd()) write();
  m_ready = false;
}

void VTKExporter::write() {
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
  if (mesh.cellCount() == 0) vtk::appendCells(nullptr, {}, mesh.points.size(), mesh, error);

  auto addFields = [&](const std::vector<const BaseData*>& fields,
                       const std::vector<std::string>& names, std::size_t items,
                       std::vector<vtk::FieldArray>& out, const char* field, const char* what) {
    for (std::size_t k = 0; k < fields.size(); ++k) {
      // Named by the Data's name, as SOFA's ("position" for "mecha.position"), or by the
      // whole entry when two entries share that name.
      std::string arrayName = fields[k]->name();
      for (std::size_t other = 0; other < fields.size(); ++other)
        if (other != k && fields[other]->name() == arrayName) arrayName = names[k];
      vtk::FieldArray array{arrayName, 1, {}};
      if (!readNumbers(fields[k]->valueText(), array.values) || items == 0 ||
          array.values.empty() || array.values.size() % items != 0) {
        msgError("'" + names[k] + "' has " + std::to_string(array.values.size()) +
                     " numbers, not a multiple of the " + std::to_string(items) + " " + what,
                 field);
        return false;
      }
      array.components = static_cast<int>(array.values.size() / items);
      out.push_back(std::move(array));
    }
    return true;
  };
  if (!addFields(m_pointFields, d_pointsDataFields.value(), mesh.points.size(), mesh.pointFields,
                 "pointsDataFields", "points") ||
      !addFields(m_cellFields, d_cellsDataFields.value(), mesh.cellCount(), mesh.cellFields,
                 "cellsDataFields", "cells")) {
    m_ready = false;
    return;
  }

  const bool xml = d_XMLformat.value();
  const std::string extension = xml ? ".vtu" : ".vtk";
  const std::string base = outputBase(d_filename.value().original);
  const std::string file =
      d_overwrite.value() ? base + extension : base + std::to_string(m_written.size()) + extension;
  const bool ok = xml ? vtk::writeVtu(file, mesh, error) : vtk::writeVtkLegacy(file, mesh, error);
  if (!ok) {
    msgError(error, "filename");
    m_ready = false;
    return;
  }
  m_written.push_back(file);
}

}  // namespace stroma
