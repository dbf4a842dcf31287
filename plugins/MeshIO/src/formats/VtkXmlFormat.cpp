// SPDX-License-Identifier: MIT
// XML VTK files: .vtu (UnstructuredGrid) and .vtp (PolyData), one or more Pieces, DataArrays in
// the "ascii" format or the "binary" one (base64, uncompressed).
// Reference: "VTK File Formats" (Kitware), "XML File Formats".
#include <tinyxml2.h>

#include <algorithm>
#include <cmath>
#include <cstring>

#include "ByteCursor.h"
#include "FormatParsers.h"
#include "TextCursor.h"
#include "VtkCells.h"

namespace stroma::meshio {

namespace {

using tinyxml2::XMLElement;

/// Bytes of one value of an XML data type; 0 when unknown.
std::size_t typeSize(std::string_view type) {
  if (type == "Int8" || type == "UInt8") return 1;
  if (type == "Int16" || type == "UInt16") return 2;
  if (type == "Int32" || type == "UInt32" || type == "Float32") return 4;
  if (type == "Int64" || type == "UInt64" || type == "Float64") return 8;
  return 0;
}

bool decodeBase64(std::string_view text, std::string& out) {
  auto value = [](char c) -> int {
    if (c >= 'A' && c <= 'Z') return c - 'A';
    if (c >= 'a' && c <= 'z') return c - 'a' + 26;
    if (c >= '0' && c <= '9') return c - '0' + 52;
    if (c == '+') return 62;
    if (c == '/') return 63;
    return -1;
  };
  out.clear();
  unsigned bits = 0;
  int count = 0;
  for (char c : text) {
    if (c == '=' || c == ' ' || c == '\n' || c == '\r' || c == '\t') continue;
    const int v = value(c);
    if (v < 0) return false;
    bits = (bits << 6) | static_cast<unsigned>(v);
    count += 6;
    if (count >= 8) {
      count -= 8;
      out.push_back(static_cast<char>((bits >> count) & 0xFF));
    }
  }
  return true;
}

class VtkXmlReader {
 public:
  VtkXmlReader(std::string_view bytes, MeshData& mesh, std::string& error)
      : m_bytes(bytes), m_mesh(mesh), m_error(error) {}

  bool read() {
    if (m_doc.Parse(m_bytes.data(), m_bytes.size()) != tinyxml2::XML_SUCCESS)
      return fail("line " + std::to_string(m_doc.ErrorLineNum()) + ": malformed XML (" +
                  std::string(m_doc.ErrorStr() ? m_doc.ErrorStr() : "") + ")");
    const XMLElement* root = m_doc.RootElement();
    if (!root || std::strcmp(root->Name(), "VTKFile") != 0)
      return fail("expected a <VTKFile> root element");
    const char* type = root->Attribute("type");
    const std::string fileType = type ? type : "";
    if (fileType != "UnstructuredGrid" && fileType != "PolyData")
      return fail(at(root, "unsupported VTKFile type '" + fileType +
                               "': expected UnstructuredGrid (.vtu) or PolyData (.vtp)"));
    const char* order = root->Attribute("byte_order");
    m_bigEndian = order && std::strcmp(order, "BigEndian") == 0;
    const char* header = root->Attribute("header_type");
    m_header64 = header && std::strcmp(header, "UInt64") == 0;
    m_compressed = root->Attribute("compressor") != nullptr;
    const XMLElement* dataset = root->FirstChildElement(fileType.c_str());
    if (!dataset) return fail(at(root, "no <" + fileType + "> element"));
    bool any = false;
    for (const XMLElement* piece = dataset->FirstChildElement("Piece"); piece;
         piece = piece->NextSiblingElement("Piece")) {
      if (!readPiece(piece, fileType == "UnstructuredGrid")) return false;
      any = true;
    }
    if (!any) return fail(at(dataset, "no <Piece> element"));
    return true;
  }

 private:
  bool fail(std::string text) {
    m_error = std::move(text);
    return false;
  }
  static std::string at(const XMLElement* e, std::string_view text) {
    return "line " + std::to_string(e->GetLineNum()) + ": " + std::string(text);
  }

  /// The first DataArray child of `parent` named `name` (or the first one when name is empty).
  static const XMLElement* array(const XMLElement* parent, const char* name) {
    if (!parent) return nullptr;
    for (const XMLElement* a = parent->FirstChildElement("DataArray"); a;
         a = a->NextSiblingElement("DataArray")) {
      if (!name) return a;
      const char* n = a->Attribute("Name");
      if (n && std::strcmp(n, name) == 0) return a;
    }
    return nullptr;
  }

  /// Reads the values of a DataArray, `count` of them.
  template <class T>
  bool readArray(const XMLElement* a, std::size_t count, std::vector<T>& out,
                 std::string_view what) {
    const char* typeAttr = a->Attribute("type");
    const std::string type = typeAttr ? typeAttr : "";
    const std::size_t size = typeSize(type);
    if (size == 0)
      return fail(at(a, "unsupported DataArray type '" + type + "' for " + std::string(what)));
    const char* formatAttr = a->Attribute("format");
    const std::string format = formatAttr ? formatAttr : "ascii";
    const char* text = a->GetText();
    const std::string_view body = text ? text : "";
    out.clear();
    if (format == "ascii") {
      TextCursor in(body);
      out.reserve(std::min(count, maxItems(body, 2)));
      for (std::size_t i = 0; i < count; ++i) {
        const std::string_view token = in.next();
        T v{};
        if (!parseNumber(token, v))
          return fail("line " + std::to_string(a->GetLineNum() + in.line() - 1) + ": " +
                      std::string(what) + ": expected " + std::to_string(count) +
                      " numbers, value " + std::to_string(i) + " is " +
                      (token.empty() ? std::string("missing") : quoted(token)));
        out.push_back(v);
      }
      return true;
    }
    if (format == "appended")
      return fail(at(a, std::string(what) + ": appended data is not supported (write the file "
                                            "with ascii or binary DataArrays)"));
    if (format != "binary")
      return fail(at(a, std::string(what) + ": unknown DataArray format '" + format + "'"));
    if (m_compressed)
      return fail(at(a, std::string(what) + ": compressed binary data is not supported"));
    std::string raw;
    if (!decodeBase64(body, raw)) return fail(at(a, std::string(what) + ": bad base64 data"));
    ByteCursor in(raw, 0, m_bigEndian);
    const std::size_t headerSize = m_header64 ? 8 : 4;
    if (!in.has(1, headerSize))
      return fail(at(a, std::string(what) + ": binary data without its size header"));
    in.skip(headerSize);
    if (!in.has(count, size))
      return fail(at(a, std::string(what) + ": binary data holds fewer than the " +
                            std::to_string(count) + " values expected (truncated?)"));
    out.resize(count);
    for (auto& v : out) {
      double x = 0;
      if (type == "Int8")
        x = in.read<std::int8_t>();
      else if (type == "UInt8")
        x = in.read<std::uint8_t>();
      else if (type == "Int16")
        x = in.read<std::int16_t>();
      else if (type == "UInt16")
        x = in.read<std::uint16_t>();
      else if (type == "Int32")
        x = in.read<std::int32_t>();
      else if (type == "UInt32")
        x = in.read<std::uint32_t>();
      else if (type == "Int64")
        x = static_cast<double>(in.read<std::int64_t>());
      else if (type == "UInt64")
        x = static_cast<double>(in.read<std::uint64_t>());
      else if (type == "Float32")
        x = in.read<float>();
      else
        x = in.read<double>();
      if constexpr (std::is_integral_v<T>) {
        if (!(x >= -9e15 && x <= 9e15) || x != std::floor(x))
          return fail(at(a, std::string(what) + ": expected integers"));
        v = static_cast<T>(x);
      } else {
        if (!std::isfinite(x))
          return fail(at(a, std::string(what) + ": a value is not a finite number"));
        v = x;
      }
    }
    return true;
  }

  bool readCount(const XMLElement* e, const char* name, std::size_t& count) {
    count = 0;
    const char* text = e->Attribute(name);
    if (!text) return true;
    long long v = 0;
    if (!parseNumber(text, v) || v < 0 || static_cast<std::size_t>(v) > maxItems(m_bytes, 1))
      return fail(at(e, std::string(name) + "=\"" + text + "\": expected a count"));
    count = static_cast<std::size_t>(v);
    return true;
  }

  /// Cells of a section (Cells, Polys, Lines...): connectivity and end offsets.
  bool readCells(const XMLElement* section, std::size_t count, std::size_t firstPoint,
                 std::size_t nbPoints, VtkCells& cells, const char* what) {
    const XMLElement* conn = array(section, "connectivity");
    const XMLElement* offsets = array(section, "offsets");
    if (!conn || !offsets)
      return fail(at(section, std::string("<") + section->Name() +
                                  "> needs DataArrays named 'connectivity' and 'offsets'"));
    std::vector<long long> ends;
    if (!readArray(offsets, count, ends, "offsets")) return false;
    const std::size_t total =
        ends.empty() ? 0 : static_cast<std::size_t>(std::max(0LL, ends.back()));
    if (total > maxItems(m_bytes, 1)) return fail(at(offsets, "offsets past what the file holds"));
    if (!readArray(conn, total, cells.connectivity, "connectivity")) return false;
    cells.offsets.assign(1, 0);
    cells.offsets.insert(cells.offsets.end(), ends.begin(), ends.end());
    std::string why;
    if (!checkVtkCells(cells, nbPoints, what, why)) return fail(at(section, why));
    for (auto& p : cells.connectivity) p += static_cast<long long>(firstPoint);
    return true;
  }

  bool readPiece(const XMLElement* piece, bool unstructured) {
    std::size_t nbPoints = 0;
    if (!readCount(piece, "NumberOfPoints", nbPoints)) return false;
    const std::size_t firstPoint = m_mesh.positions.size();
    // Points.
    const XMLElement* points = array(piece->FirstChildElement("Points"), nullptr);
    if (nbPoints > 0 && !points) return fail(at(piece, "<Piece> has no <Points> DataArray"));
    if (points) {
      const char* components = points->Attribute("NumberOfComponents");
      if (components && std::strcmp(components, "3") != 0)
        return fail(at(points, "points need NumberOfComponents=\"3\""));
      std::vector<double> xyz;
      if (!readArray(points, nbPoints * 3, xyz, "points")) return false;
      for (std::size_t i = 0; i < nbPoints; ++i)
        m_mesh.positions.emplace_back(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]);
    }
    // Point normals: the PointData array named by its Normals attribute, or "Normals".
    if (const XMLElement* pointData = piece->FirstChildElement("PointData")) {
      const char* normalsName = pointData->Attribute("Normals");
      if (const XMLElement* n = array(pointData, normalsName ? normalsName : "Normals")) {
        std::vector<double> xyz;
        if (!readArray(n, nbPoints * 3, xyz, "normals")) return false;
        m_mesh.normals.resize(firstPoint, Vec3d::Zero());
        for (std::size_t i = 0; i < nbPoints; ++i)
          m_mesh.normals.emplace_back(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]);
      }
    }
    if (unstructured) {
      std::size_t nbCells = 0;
      if (!readCount(piece, "NumberOfCells", nbCells)) return false;
      if (nbCells == 0) return true;
      const XMLElement* section = piece->FirstChildElement("Cells");
      if (!section) return fail(at(piece, "<Piece> has cells but no <Cells> element"));
      VtkCells cells;
      if (!readCells(section, nbCells, firstPoint, nbPoints, cells, "cell")) return false;
      const XMLElement* types = array(section, "types");
      if (!types) return fail(at(section, "<Cells> needs a DataArray named 'types'"));
      std::vector<long long> typeValues;
      if (!readArray(types, nbCells, typeValues, "types")) return false;
      std::string why;
      if (!addVtkCells(cells, typeValues, m_mesh, why)) return fail(at(section, why));
      return true;
    }
    const struct {
      const char* section;
      const char* count;
      VtkPolyKind kind;
    } kinds[] = {{"Verts", "NumberOfVerts", VtkPolyKind::vertices},
                 {"Lines", "NumberOfLines", VtkPolyKind::lines},
                 {"Strips", "NumberOfStrips", VtkPolyKind::strips},
                 {"Polys", "NumberOfPolys", VtkPolyKind::polygons}};
    for (const auto& k : kinds) {
      std::size_t count = 0;
      if (!readCount(piece, k.count, count)) return false;
      if (count == 0) continue;
      const XMLElement* section = piece->FirstChildElement(k.section);
      if (!section)
        return fail(at(
            piece, std::string("<Piece> has ") + k.count + " but no <" + k.section + "> element"));
      VtkCells cells;
      if (!readCells(section, count, firstPoint, nbPoints, cells, "cell")) return false;
      addVtkPolyData(cells, k.kind, m_mesh);
    }
    return true;
  }

  std::string_view m_bytes;
  MeshData& m_mesh;
  std::string& m_error;
  tinyxml2::XMLDocument m_doc;
  bool m_bigEndian = false;
  bool m_header64 = false;
  bool m_compressed = false;
};

}  // namespace

bool parseVtkXml(std::string_view bytes, MeshData& mesh, std::string& error) {
  VtkXmlReader reader(bytes, mesh, error);
  return reader.read();
}

bool parseVtk(std::string_view bytes, MeshData& mesh, std::string& error) {
  // XML files start with '<' (after an optional byte order mark and spaces); legacy ones with
  // "# vtk DataFile".
  std::size_t i = 0;
  if (bytes.substr(0, 3) == "\xEF\xBB\xBF") i = 3;
  while (i < bytes.size() &&
         (bytes[i] == ' ' || bytes[i] == '\t' || bytes[i] == '\r' || bytes[i] == '\n'))
    ++i;
  if (i < bytes.size() && bytes[i] == '<') return parseVtkXml(bytes, mesh, error);
  return parseVtkLegacy(bytes, mesh, error);
}

}  // namespace stroma::meshio
