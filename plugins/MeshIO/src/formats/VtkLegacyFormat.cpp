// SPDX-License-Identifier: MIT
// Legacy VTK files (.vtk), ASCII and BINARY, datasets UNSTRUCTURED_GRID and POLYDATA.
// Reference: "VTK File Formats" (Kitware), "Simple Legacy Formats". Binary data is big-endian.
#include <algorithm>
#include <cctype>

#include "ByteCursor.h"
#include "FormatParsers.h"
#include "TextCursor.h"
#include "VtkCells.h"

namespace stroma::meshio {

namespace {

bool equalsNoCase(std::string_view a, std::string_view b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return std::tolower(static_cast<unsigned char>(x)) ==
                  std::tolower(static_cast<unsigned char>(y));
         });
}

/// Bytes of one value of a legacy data type; 0 when unknown.
std::size_t typeSize(std::string_view type) {
  if (type == "bit") return 0;
  if (type == "char" || type == "unsigned_char") return 1;
  if (type == "short" || type == "unsigned_short") return 2;
  if (type == "int" || type == "unsigned_int" || type == "float") return 4;
  if (type == "long" || type == "unsigned_long" || type == "double" || type == "vtktypeint64" ||
      type == "vtktypeuint64" || type == "vtkIdType")
    return 8;
  return 0;
}

class VtkLegacyReader {
 public:
  VtkLegacyReader(std::string_view bytes, MeshData& mesh, std::string& error)
      : m_bytes(bytes), m_text(bytes), m_mesh(mesh), m_error(error) {}

  bool read() {
    if (!readHeader()) return false;
    while (!m_text.atEnd()) {
      const std::string_view keyword = m_text.next();
      bool ok = true;
      if (equalsNoCase(keyword, "POINTS"))
        ok = readPoints();
      else if (m_unstructured && equalsNoCase(keyword, "CELLS"))
        ok = readCells(m_cells, "CELLS");
      else if (m_unstructured && equalsNoCase(keyword, "CELL_TYPES"))
        ok = readCellTypes();
      else if (!m_unstructured && equalsNoCase(keyword, "VERTICES"))
        ok = readPoly(VtkPolyKind::vertices, "VERTICES");
      else if (!m_unstructured && equalsNoCase(keyword, "LINES"))
        ok = readPoly(VtkPolyKind::lines, "LINES");
      else if (!m_unstructured && equalsNoCase(keyword, "POLYGONS"))
        ok = readPoly(VtkPolyKind::polygons, "POLYGONS");
      else if (!m_unstructured && equalsNoCase(keyword, "TRIANGLE_STRIPS"))
        ok = readPoly(VtkPolyKind::strips, "TRIANGLE_STRIPS");
      else if (equalsNoCase(keyword, "POINT_DATA"))
        ok = readAttributes(true);
      else if (equalsNoCase(keyword, "CELL_DATA"))
        ok = readAttributes(false);
      else if (equalsNoCase(keyword, "FIELD"))
        ok = skipField();
      else if (equalsNoCase(keyword, "METADATA"))
        ok = skipMetadata();
      else
        return fail(
            m_text.expected("a section keyword (POINTS, CELLS, CELL_TYPES, POLYGONS, "
                            "POINT_DATA...)",
                            keyword));
      if (!ok) return false;
    }
    if (!m_sawPoints) return fail("the file has no POINTS section");
    if (m_unstructured) {
      if (m_cells.size() > 0 || !m_types.empty()) {
        if (!checkVtkCells(m_cells, m_mesh.positions.size(), "cell", m_error)) return false;
        if (!addVtkCells(m_cells, m_types, m_mesh, m_error)) return false;
      }
    }
    return true;
  }

 private:
  bool fail(std::string text) {
    m_error = std::move(text);
    return false;
  }

  bool readHeader() {
    const std::string_view first = m_text.restOfLine();
    std::string lower;
    for (char c : first) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (lower.find("vtk datafile") == std::string::npos)
      return fail("line 1: expected '# vtk DataFile Version x.x', got " + quoted(first));
    m_text.restOfLine();  // title
    const std::string_view format = m_text.next();
    if (equalsNoCase(format, "BINARY"))
      m_binary = true;
    else if (!equalsNoCase(format, "ASCII"))
      return fail(m_text.expected("ASCII or BINARY", format));
    const std::string_view dataset = m_text.next();
    if (!equalsNoCase(dataset, "DATASET")) return fail(m_text.expected("DATASET", dataset));
    const std::string_view type = m_text.next();
    if (equalsNoCase(type, "UNSTRUCTURED_GRID"))
      m_unstructured = true;
    else if (!equalsNoCase(type, "POLYDATA"))
      return fail(m_text.at("unsupported dataset " + quoted(type) +
                            ": expected UNSTRUCTURED_GRID or POLYDATA"));
    return true;
  }

  /// Reads `count` numbers of legacy `type` (ASCII tokens, or big-endian binary after the
  /// header line) into `out`, as doubles.
  template <class T>
  bool readValues(std::size_t count, std::string_view type, std::vector<T>& out,
                  std::string_view what) {
    const std::size_t size = typeSize(type);
    if (size == 0)
      return fail(m_text.at("unsupported data type " + quoted(type) + " for " + std::string(what)));
    out.clear();
    if (!m_binary) {
      out.reserve(std::min(count, maxItems(m_bytes, 2)));
      for (std::size_t i = 0; i < count; ++i) {
        const std::string_view token = m_text.next();
        T v{};
        if (!parseNumber(token, v))
          return fail(m_text.expected(
              std::string(what) + " (" + std::to_string(count) + " numbers)", token));
        out.push_back(v);
      }
      return true;
    }
    m_text.restOfLine();
    ByteCursor in(m_bytes, m_text.offset(), true);
    if (!in.has(count, size))
      return fail(in.truncated(std::to_string(count) + " " + std::string(type) + " values for " +
                               std::string(what)));
    out.resize(count);
    for (auto& v : out) {
      double x = 0;
      if (type == "char")
        x = in.read<std::int8_t>();
      else if (type == "unsigned_char")
        x = in.read<std::uint8_t>();
      else if (type == "short")
        x = in.read<std::int16_t>();
      else if (type == "unsigned_short")
        x = in.read<std::uint16_t>();
      else if (type == "int")
        x = in.read<std::int32_t>();
      else if (type == "unsigned_int")
        x = in.read<std::uint32_t>();
      else if (type == "float")
        x = in.read<float>();
      else if (type == "double")
        x = in.read<double>();
      else if (type == "vtktypeuint64" || type == "unsigned_long")
        x = static_cast<double>(in.read<std::uint64_t>());
      else
        x = static_cast<double>(in.read<std::int64_t>());
      if constexpr (std::is_integral_v<T>) {
        if (!(x >= -9e15 && x <= 9e15) || x != static_cast<double>(static_cast<long long>(x)))
          return fail(in.at("expected an integer for " + std::string(what)));
        v = static_cast<T>(x);
      } else {
        v = x;
      }
    }
    m_text.seek(in.offset());
    return true;
  }

  bool readPoints() {
    std::size_t count = 0;
    if (!m_text.readCount(count, "the number of points", maxItems(m_bytes, 3), m_error))
      return false;
    const std::string type(m_text.next());
    std::vector<double> values;
    if (!readValues(count * 3, type, values, "point coordinates")) return false;
    for (double v : values)
      if (!std::isfinite(v)) return fail(m_text.at("a point coordinate is not a finite number"));
    m_mesh.positions.resize(count);
    for (std::size_t i = 0; i < count; ++i)
      m_mesh.positions[i] = Vec3d(values[3 * i], values[3 * i + 1], values[3 * i + 2]);
    m_sawPoints = true;
    return true;
  }

  /// CELLS / POLYGONS ... in the classic layout (n, then for each cell its size and points) or
  /// the 5.x layout (OFFSETS and CONNECTIVITY arrays).
  bool readCells(VtkCells& cells, std::string_view keyword) {
    std::size_t count = 0, size = 0;
    if (!m_text.readCount(count, "the number of cells", maxItems(m_bytes, 1), m_error) ||
        !m_text.readCount(size, "the size of the cell list", maxItems(m_bytes, 1), m_error))
      return false;
    const std::size_t headerEnd = m_text.offset();
    const std::string_view nextWord = m_text.next();
    if (equalsNoCase(nextWord, "OFFSETS")) {
      // 5.x: count is the number of offsets (cells + 1), size the connectivity length.
      const std::string type(m_text.next());
      if (!readValues(count, type, cells.offsets, std::string(keyword) + " offsets")) return false;
      if (!m_text.expect("CONNECTIVITY", m_error)) return false;
      const std::string ctype(m_text.next());
      if (!readValues(size, ctype, cells.connectivity, std::string(keyword) + " connectivity"))
        return false;
      if (cells.offsets.empty()) cells.offsets.push_back(0);
      return checkOffsets(cells, keyword);
    }
    // Classic: go back before the word just read.
    m_text = TextCursor(m_bytes);
    m_text.seek(headerEnd);
    std::vector<long long> list;
    if (!readValues(size, "int", list, std::string(keyword) + " list")) return false;
    cells.offsets.assign(1, 0);
    cells.connectivity.clear();
    cells.connectivity.reserve(size);
    std::size_t k = 0;
    for (std::size_t i = 0; i < count; ++i) {
      if (k >= list.size())
        return fail(m_text.at(std::string(keyword) + ": the list ends at cell " +
                              std::to_string(i) + " of " + std::to_string(count)));
      const long long n = list[k++];
      if (n < 0 || static_cast<std::size_t>(n) > list.size() - k)
        return fail(m_text.at(std::string(keyword) + ": cell " + std::to_string(i) + " has " +
                              std::to_string(n) + " points, more than the list holds"));
      cells.connectivity.insert(cells.connectivity.end(),
                                list.begin() + static_cast<std::ptrdiff_t>(k),
                                list.begin() + static_cast<std::ptrdiff_t>(k + n));
      k += static_cast<std::size_t>(n);
      cells.offsets.push_back(static_cast<long long>(cells.connectivity.size()));
    }
    if (k != list.size())
      return fail(m_text.at(std::string(keyword) + ": the list has " + std::to_string(list.size()) +
                            " numbers, but its " + std::to_string(count) + " cells use " +
                            std::to_string(k)));
    return true;
  }

  bool checkOffsets(const VtkCells& cells, std::string_view keyword) {
    std::string why;
    if (!checkVtkCells(cells, std::size_t(-1), "cell", why))
      return fail(m_text.at(std::string(keyword) + ": " + why));
    return true;
  }

  bool readCellTypes() {
    std::size_t count = 0;
    if (!m_text.readCount(count, "the number of cell types", maxItems(m_bytes, 1), m_error))
      return false;
    return readValues(count, "int", m_types, "cell types");
  }

  bool readPoly(VtkPolyKind kind, std::string_view keyword) {
    VtkCells cells;
    if (!readCells(cells, keyword)) return false;
    if (!checkVtkCells(cells, m_mesh.positions.size(), keyword == "LINES" ? "line" : "polygon",
                       m_error)) {
      m_error = m_text.at(std::string(keyword) + ": " + m_error);
      return false;
    }
    addVtkPolyData(cells, kind, m_mesh);
    return true;
  }

  /// POINT_DATA / CELL_DATA: keeps point NORMALS, skips the other attributes.
  bool readAttributes(bool pointData) {
    std::size_t count = 0;
    if (!m_text.readCount(count, "the number of values", maxItems(m_bytes, 1), m_error))
      return false;
    std::vector<double> values;
    while (!m_text.atEnd()) {
      const std::string_view word = m_text.peek();
      std::size_t components = 0;
      std::string type;
      if (equalsNoCase(word, "NORMALS") || equalsNoCase(word, "VECTORS") ||
          equalsNoCase(word, "TENSORS")) {
        m_text.next();
        m_text.next();  // name
        type = m_text.next();
        components = equalsNoCase(word, "TENSORS") ? 9 : 3;
        if (!readValues(count * components, type, values, std::string(word))) return false;
        if (pointData && equalsNoCase(word, "NORMALS") && count == m_mesh.positions.size()) {
          m_mesh.normals.resize(count);
          for (std::size_t i = 0; i < count; ++i)
            m_mesh.normals[i] = Vec3d(values[3 * i], values[3 * i + 1], values[3 * i + 2]);
        }
      } else if (equalsNoCase(word, "SCALARS")) {
        m_text.next();
        m_text.next();  // name
        type = m_text.next();
        long long n = 1;
        if (parseNumber(m_text.peek(), n)) m_text.next();
        if (n < 1 || n > 4)
          return fail(
              m_text.at("SCALARS with " + std::to_string(n) + " components: expected 1 to 4"));
        if (equalsNoCase(m_text.peek(), "LOOKUP_TABLE")) {
          m_text.next();
          m_text.next();  // table name
        }
        if (!readValues(count * static_cast<std::size_t>(n), type, values, "SCALARS")) return false;
      } else if (equalsNoCase(word, "TEXTURE_COORDINATES")) {
        m_text.next();
        m_text.next();
        long long dim = 0;
        if (!m_text.readInteger(dim, "the texture coordinate dimension", m_error)) return false;
        if (dim < 1 || dim > 3)
          return fail(m_text.at("texture coordinates of dimension " + std::to_string(dim)));
        type = m_text.next();
        if (!readValues(count * static_cast<std::size_t>(dim), type, values, "TEXTURE_COORDINATES"))
          return false;
      } else if (equalsNoCase(word, "COLOR_SCALARS")) {
        m_text.next();
        m_text.next();
        std::size_t n = 0;
        if (!m_text.readCount(n, "the number of color components", 4, m_error)) return false;
        if (!readValues(count * n, m_binary ? "unsigned_char" : "float", values, "COLOR_SCALARS"))
          return false;
      } else if (equalsNoCase(word, "LOOKUP_TABLE")) {
        m_text.next();
        m_text.next();
        std::size_t n = 0;
        if (!m_text.readCount(n, "the lookup table size", maxItems(m_bytes, 4), m_error))
          return false;
        if (!readValues(n * 4, m_binary ? "unsigned_char" : "float", values, "LOOKUP_TABLE"))
          return false;
      } else if (equalsNoCase(word, "FIELD")) {
        m_text.next();
        if (!skipField()) return false;
      } else if (equalsNoCase(word, "METADATA")) {
        m_text.next();
        if (!skipMetadata()) return false;
      } else {
        return true;  // the next section
      }
    }
    return true;
  }

  /// FIELD name numArrays, then per array: name components tuples type, values.
  bool skipField() {
    m_text.next();  // name
    std::size_t arrays = 0;
    if (!m_text.readCount(arrays, "the number of field arrays", 100000, m_error)) return false;
    std::vector<double> values;
    for (std::size_t a = 0; a < arrays; ++a) {
      m_text.next();  // array name
      std::size_t components = 0, tuples = 0;
      if (!m_text.readCount(components, "the number of components", 1000, m_error) ||
          !m_text.readCount(tuples, "the number of tuples", maxItems(m_bytes, 1), m_error))
        return false;
      const std::string type(m_text.next());
      if (!readValues(components * tuples, type, values, "FIELD array")) return false;
      if (equalsNoCase(m_text.peek(), "METADATA")) {
        m_text.next();
        if (!skipMetadata()) return false;
      }
    }
    return true;
  }

  /// METADATA blocks end with an empty line.
  bool skipMetadata() {
    m_text.restOfLine();
    while (!m_text.atEnd()) {
      const std::string_view line = m_text.restOfLine();
      if (line.find_first_not_of(" \t\r") == std::string_view::npos) return true;
    }
    return true;
  }

  std::string_view m_bytes;
  TextCursor m_text;
  MeshData& m_mesh;
  std::string& m_error;
  bool m_binary = false;
  bool m_unstructured = false;
  bool m_sawPoints = false;
  VtkCells m_cells;
  std::vector<long long> m_types;
};

}  // namespace

bool parseVtkLegacy(std::string_view bytes, MeshData& mesh, std::string& error) {
  VtkLegacyReader reader(bytes, mesh, error);
  return reader.read();
}

}  // namespace stroma::meshio
