// SPDX-License-Identifier: MIT
#include "VtkFiles.h"

#include <charconv>
#include <cmath>
#include <fstream>

namespace stroma::vtk {

namespace fs = std::filesystem;

int pointCount(CellType type) {
  switch (type) {
    case CellType::vertex:
      return 1;
    case CellType::line:
      return 2;
    case CellType::triangle:
      return 3;
    case CellType::quad:
      return 4;
    case CellType::tetra:
      return 4;
    case CellType::hexahedron:
      return 8;
  }
  return 0;
}

std::string formatNumber(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

bool checkMesh(const UnstructuredMesh& mesh, std::string& error) {
  std::size_t expected = 0;
  for (CellType type : mesh.cellTypes) expected += static_cast<std::size_t>(pointCount(type));
  if (expected != mesh.connectivity.size()) {
    error = "the cells list " + std::to_string(mesh.connectivity.size()) + " point indices, " +
            std::to_string(expected) + " expected";
    return false;
  }
  for (std::size_t i = 0; i < mesh.connectivity.size(); ++i)
    if (mesh.connectivity[i] >= mesh.points.size()) {
      error = "a cell uses point " + std::to_string(mesh.connectivity[i]) + ", out of the " +
              std::to_string(mesh.points.size()) + " points";
      return false;
    }
  auto checkFields = [&](const std::vector<FieldArray>& fields, std::size_t items,
                         const char* what) {
    for (const FieldArray& f : fields)
      if (f.components < 1 || f.values.size() != items * static_cast<std::size_t>(f.components)) {
        error = std::string(what) + " field '" + f.name + "' has " +
                std::to_string(f.values.size()) + " values, " + std::to_string(items) + " x " +
                std::to_string(f.components) + " expected";
        return false;
      }
    return true;
  };
  return checkFields(mesh.pointFields, mesh.points.size(), "point") &&
         checkFields(mesh.cellFields, mesh.cellCount(), "cell");
}

namespace {

std::string escapeXml(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

/// Opens `file` for writing; false with `error` naming it when it cannot.
bool openForWriting(const fs::path& file, std::ofstream& out, std::string& error) {
  out.open(file, std::ios::binary | std::ios::trunc);
  if (!out) {
    std::error_code ec;
    const fs::path folder = file.parent_path().empty() ? fs::path(".") : file.parent_path();
    error = "cannot write '" + file.string() + "'" +
            (fs::is_directory(folder, ec) ? "" : " (no folder '" + folder.string() + "')");
    return false;
  }
  return true;
}

bool finish(std::ofstream& out, const fs::path& file, std::string& error) {
  out.flush();
  if (!out) {
    error = "writing '" + file.string() + "' failed (disk full?)";
    return false;
  }
  return true;
}

/// Numbers separated by spaces, `perLine` per line.
template <class Range>
void writeNumbers(std::ostream& out, const Range& values, std::size_t perLine, const char* indent) {
  // Formatted into one buffer with to_chars and written at once: a stream insertion per number
  // cost about as much as the formatting.
  std::string text;
  const std::string_view lead(indent);
  char number[32];
  std::size_t n = 0;
  for (const auto& v : values) {
    if (n % perLine == 0)
      text += lead;
    else
      text += ' ';
    text.append(number, std::to_chars(number, number + sizeof number, v).ptr);
    if (++n % perLine == 0) text += '\n';
  }
  if (n % perLine != 0) text += '\n';
  out.write(text.data(), static_cast<std::streamsize>(text.size()));
}

void writeXmlArray(std::ostream& out, const FieldArray& field) {
  out << "        <DataArray type=\"Float64\" Name=\"" << escapeXml(field.name)
      << "\" NumberOfComponents=\"" << field.components << "\" format=\"ascii\">\n";
  writeNumbers(out, field.values, static_cast<std::size_t>(std::max(field.components, 1)) * 3,
               "          ");
  out << "        </DataArray>\n";
}

std::vector<double> flatten(const std::vector<Vec3d>& points) {
  std::vector<double> flat;
  flat.reserve(points.size() * 3);
  for (const Vec3d& p : points) flat.insert(flat.end(), {p.x(), p.y(), p.z()});
  return flat;
}

}  // namespace

bool writeVtu(const fs::path& file, const UnstructuredMesh& mesh, std::string& error) {
  if (!checkMesh(mesh, error)) {
    error = std::string("'").append(file.string()).append("': ").append(error);
    return false;
  }
  std::ofstream out;
  if (!openForWriting(file, out, error)) return false;
  out << "<?xml version=\"1.0\"?>\n"
         "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
         "header_type=\"UInt64\">\n"
         "  <UnstructuredGrid>\n"
      << "    <Piece NumberOfPoints=\"" << mesh.points.size() << "\" NumberOfCells=\""
      << mesh.cellCount() << "\">\n";
  out << "      <PointData>\n";
  for (const FieldArray& f : mesh.pointFields) writeXmlArray(out, f);
  out << "      </PointData>\n      <CellData>\n";
  for (const FieldArray& f : mesh.cellFields) writeXmlArray(out, f);
  out << "      </CellData>\n      <Points>\n";
  writeXmlArray(out, {"Points", 3, flatten(mesh.points)});
  out << "      </Points>\n      <Cells>\n"
         "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
  writeNumbers(out, mesh.connectivity, 12, "          ");
  out << "        </DataArray>\n"
         "        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
  std::vector<std::size_t> offsets;
  std::size_t end = 0;
  for (CellType type : mesh.cellTypes) offsets.push_back(end += pointCount(type));
  writeNumbers(out, offsets, 12, "          ");
  out << "        </DataArray>\n"
         "        <DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
  std::vector<int> types;
  for (CellType type : mesh.cellTypes) types.push_back(static_cast<int>(type));
  writeNumbers(out, types, 24, "          ");
  out << "        </DataArray>\n      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n"
         "</VTKFile>\n";
  return finish(out, file, error);
}

bool writeVtkLegacy(const fs::path& file, const UnstructuredMesh& mesh, std::string& error) {
  if (!checkMesh(mesh, error)) {
    error = std::string("'").append(file.string()).append("': ").append(error);
    return false;
  }
  std::ofstream out;
  if (!openForWriting(file, out, error)) return false;
  out << "# vtk DataFile Version 3.0\nStroma export\nASCII\nDATASET UNSTRUCTURED_GRID\n";
  out << "POINTS " << mesh.points.size() << " double\n";
  writeNumbers(out, flatten(mesh.points), 3, "");
  out << "CELLS " << mesh.cellCount() << ' ' << mesh.cellCount() + mesh.connectivity.size() << '\n';
  std::size_t next = 0;
  for (CellType type : mesh.cellTypes) {
    const int n = pointCount(type);
    out << n;
    for (int i = 0; i < n; ++i) out << ' ' << mesh.connectivity[next++];
    out << '\n';
  }
  out << "CELL_TYPES " << mesh.cellCount() << '\n';
  for (CellType type : mesh.cellTypes) out << static_cast<int>(type) << '\n';
  // Field names may not hold spaces in the legacy format.
  auto writeFields = [&](const std::vector<FieldArray>& fields, std::size_t items,
                         const char* section) {
    if (fields.empty()) return;
    out << section << ' ' << items << "\nFIELD FieldData " << fields.size() << '\n';
    for (const FieldArray& f : fields) {
      std::string name = f.name;
      for (char& c : name)
        if (c == ' ' || c == '\t') c = '_';
      out << name << ' ' << f.components << ' ' << items << " double\n";
      writeNumbers(out, f.values, static_cast<std::size_t>(f.components) * 3, "");
    }
  };
  writeFields(mesh.pointFields, mesh.points.size(), "POINT_DATA");
  writeFields(mesh.cellFields, mesh.cellCount(), "CELL_DATA");
  return finish(out, file, error);
}

bool writePvd(const fs::path& file, const std::vector<CollectionEntry>& entries,
              std::string& error) {
  std::ofstream out;
  if (!openForWriting(file, out, error)) return false;
  out << "<?xml version=\"1.0\"?>\n"
         "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
         "  <Collection>\n";
  for (const CollectionEntry& e : entries)
    out << "    <DataSet timestep=\"" << formatNumber(e.time) << "\" group=\"\" part=\"0\" file=\""
        << escapeXml(e.file) << "\"/>\n";
  out << "  </Collection>\n</VTKFile>\n";
  return finish(out, file, error);
}

}  // namespace stroma::vtk
