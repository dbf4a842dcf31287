// SPDX-License-Identifier: MIT
// Gmsh .msh files: version 1 ($NOD/$ELM), 2.x ASCII and binary, 4.1 ASCII and binary.
// Reference: the Gmsh reference manual, section "MSH file format" (versions 4.1 and 2.2, and
// the legacy version 1).
#include <algorithm>
#include <array>
#include <cctype>
#include <limits>
#include <map>
#include <optional>
#include <unordered_map>

#include "ByteCursor.h"
#include "FormatParsers.h"
#include "TextCursor.h"

namespace stroma::meshio {

namespace {

enum class Kind { point, edge, triangle, quad, tetrahedron, hexahedron, other };

struct ElementType {
  int nodes = 0;  // nodes listed per element
  Kind kind = Kind::other;
  bool higherOrder = false;  // corners first, then more nodes
  const char* name = "";
};

/// Gmsh element types 1-31, 92, 93 (the manual's table): nodes per element and the linear
/// element their first nodes make.
std::optional<ElementType> elementType(long long type) {
  switch (type) {
    case 1:
      return ElementType{2, Kind::edge, false, "line"};
    case 2:
      return ElementType{3, Kind::triangle, false, "triangle"};
    case 3:
      return ElementType{4, Kind::quad, false, "quad"};
    case 4:
      return ElementType{4, Kind::tetrahedron, false, "tetrahedron"};
    case 5:
      return ElementType{8, Kind::hexahedron, false, "hexahedron"};
    case 6:
      return ElementType{6, Kind::other, false, "prism"};
    case 7:
      return ElementType{5, Kind::other, false, "pyramid"};
    case 8:
      return ElementType{3, Kind::edge, true, "second-order line"};
    case 9:
      return ElementType{6, Kind::triangle, true, "second-order triangle"};
    case 10:
      return ElementType{9, Kind::quad, true, "second-order quad"};
    case 11:
      return ElementType{10, Kind::tetrahedron, true, "second-order tetrahedron"};
    case 12:
      return ElementType{27, Kind::hexahedron, true, "second-order hexahedron"};
    case 13:
      return ElementType{18, Kind::other, false, "second-order prism"};
    case 14:
      return ElementType{14, Kind::other, false, "second-order pyramid"};
    case 15:
      return ElementType{1, Kind::point, false, "point"};
    case 16:
      return ElementType{8, Kind::quad, true, "serendipity quad"};
    case 17:
      return ElementType{20, Kind::hexahedron, true, "serendipity hexahedron"};
    case 18:
      return ElementType{15, Kind::other, false, "serendipity prism"};
    case 19:
      return ElementType{13, Kind::other, false, "serendipity pyramid"};
    case 20:
      return ElementType{9, Kind::other, false, "incomplete third-order triangle"};
    case 21:
      return ElementType{10, Kind::other, false, "third-order triangle"};
    case 22:
      return ElementType{12, Kind::other, false, "incomplete fourth-order triangle"};
    case 23:
      return ElementType{15, Kind::other, false, "fourth-order triangle"};
    case 24:
      return ElementType{15, Kind::other, false, "incomplete fifth-order triangle"};
    case 25:
      return ElementType{21, Kind::other, false, "fifth-order triangle"};
    case 26:
      return ElementType{4, Kind::other, false, "third-order line"};
    case 27:
      return ElementType{5, Kind::other, false, "fourth-order line"};
    case 28:
      return ElementType{6, Kind::other, false, "fifth-order line"};
    case 29:
      return ElementType{20, Kind::other, false, "third-order tetrahedron"};
    case 30:
      return ElementType{35, Kind::other, false, "fourth-order tetrahedron"};
    case 31:
      return ElementType{56, Kind::other, false, "fifth-order tetrahedron"};
    case 92:
      return ElementType{64, Kind::other, false, "third-order hexahedron"};
    case 93:
      return ElementType{125, Kind::other, false, "fourth-order hexahedron"};
    default:
      return std::nullopt;
  }
}

std::string unsupportedType(long long type) {
  return "unsupported Gmsh element type " + std::to_string(type) +
         " (known types: 1-31, 92, 93; Stroma keeps lines 1, triangles 2, quads 3, tetrahedra 4, "
         "hexahedra 5)";
}

/// Node tags (any positive numbers) to point indices in file order.
class NodeNumbering {
 public:
  /// False when the tag was already given.
  bool add(long long tag, Index index) {
    if (tag < 0) return false;
    return m_map.try_emplace(tag, index).second;
  }
  /// kInvalidIndex when unknown.
  Index find(long long tag) const {
    const auto it = m_map.find(tag);
    return it == m_map.end() ? kInvalidIndex : it->second;
  }

 private:
  std::unordered_map<long long, Index> m_map;
};

/// Collects elements and counts those skipped, for one warning per type at the end.
class ElementSink {
 public:
  explicit ElementSink(MeshData& mesh) : m_mesh(mesh) {}

  /// `points` holds the element's point indices (at least the corners); `physical` is the
  /// element's physical group (0: none), kept for tetrahedra and hexahedra.
  void add(long long type, const ElementType& info, const Index* points, long long physical) {
    switch (info.kind) {
      case Kind::edge:
        m_mesh.edges.push_back({points[0], points[1]});
        break;
      case Kind::triangle:
        m_mesh.triangles.push_back({points[0], points[1], points[2]});
        break;
      case Kind::quad:
        m_mesh.quads.push_back({points[0], points[1], points[2], points[3]});
        break;
      case Kind::tetrahedron:
        m_mesh.tetrahedra.push_back({points[0], points[1], points[2], points[3]});
        m_mesh.tetrahedronGroups.push_back(static_cast<int>(physical));
        break;
      case Kind::hexahedron: {
        Hexahedron h;
        std::copy(points, points + 8, h.begin());
        m_mesh.hexahedra.push_back(h);
        m_mesh.hexahedronGroups.push_back(static_cast<int>(physical));
        break;
      }
      case Kind::point:
        return;
      case Kind::other:
        ++m_skipped[type];
        return;
    }
    if (info.higherOrder) ++m_reduced[type];
  }

  void reportSkipped() {
    for (const auto& [type, count] : m_skipped)
      m_mesh.warnings.push_back(std::to_string(count) + " " + elementType(type)->name +
                                " elements (Gmsh type " + std::to_string(type) +
                                ") skipped: Stroma keeps lines, triangles, quads, tetrahedra and "
                                "hexahedra");
    for (const auto& [type, count] : m_reduced)
      m_mesh.warnings.push_back(std::to_string(count) + " " + elementType(type)->name +
                                " elements (Gmsh type " + std::to_string(type) +
                                ") read as first-order elements (corner nodes only)");
  }

 private:
  MeshData& m_mesh;
  std::map<long long, std::size_t> m_skipped;
  std::map<long long, std::size_t> m_reduced;
};

class GmshReader {
 public:
  GmshReader(std::string_view bytes, MeshData& mesh, std::string& error)
      : m_bytes(bytes), m_text(bytes), m_mesh(mesh), m_elements(mesh), m_error(error) {}

  bool read() {
    const std::string_view first = m_text.peek();
    if (first == "$NOD")
      m_version = 1;
    else if (first != "$MeshFormat")
      return fail(
          m_text.expected("'$MeshFormat' (Gmsh 2 or 4) or '$NOD' (Gmsh 1) at the start "
                          "of a Gmsh file",
                          first));
    bool sawNodes = false;
    while (!m_text.atEnd()) {
      const std::string_view token = m_text.next();
      if (token.empty() || token.front() != '$')
        return fail(m_text.expected("a section such as '$Nodes'", token));
      const std::string_view name = token.substr(1);
      bool ok = true;
      if (name == "MeshFormat")
        ok = readFormat();
      else if (name == "NOD" && m_version == 1)
        ok = readNodesV1V2("$ENDNOD"), sawNodes = true;
      else if (name == "ELM" && m_version == 1)
        ok = readElementsV1V2("$ENDELM");
      else if (name == "Nodes" && m_version >= 2) {
        ok = m_version == 2 ? (m_binary ? readNodesV2Binary() : readNodesV1V2("$EndNodes"))
                            : readNodesV4();
        sawNodes = true;
      } else if (name == "Elements" && m_version >= 2) {
        if (!sawNodes) return fail(m_text.at("$Elements comes before $Nodes"));
        ok = m_version == 2 ? (m_binary ? readElementsV2Binary() : readElementsV1V2("$EndElements"))
                            : readElementsV4();
      } else if (name == "Entities" && m_version == 4)
        ok = readEntitiesV4();
      else
        ok = skipSection(name);
      if (!ok) return false;
    }
    if (m_version == 0) return fail("the file has no $MeshFormat section");
    if (!sawNodes) return fail("the file has no node section ($Nodes or $NOD)");
    m_elements.reportSkipped();
    return true;
  }

 private:
  bool fail(std::string text) {
    m_error = std::move(text);
    return false;
  }

  bool readFormat() {
    double version = 0;
    long long fileType = 0, dataSize = 0;
    if (!m_text.readDouble(version, "the format version (2.2 or 4.1)", m_error)) return false;
    if (!m_text.readInteger(fileType, "the file type (0 ASCII, 1 binary)", m_error)) return false;
    if (!m_text.readInteger(dataSize, "the data size (8)", m_error)) return false;
    if (version >= 2 && version < 3)
      m_version = 2;
    else if (version >= 4.1 && version < 5)
      m_version = 4;
    else
      return fail(m_text.at("unsupported Gmsh format version " + std::to_string(version) +
                            " (supported: 1, 2.x, 4.1)"));
    if (fileType != 0 && fileType != 1)
      return fail(m_text.at("file type " + std::to_string(fileType) +
                            ": expected 0 (ASCII) or 1 (binary)"));
    m_binary = fileType == 1;
    if (m_binary && dataSize != 8)
      return fail(m_text.at("binary data size " + std::to_string(dataSize) +
                            ": only 8 (double precision) is supported"));
    if (m_binary) {
      // A binary 1 tells the byte order.
      m_text.restOfLine();
      ByteCursor in(m_bytes, m_text.offset(), false);
      if (!in.has(1, 4)) return fail(in.truncated("the binary integer 1 (byte order)"));
      const std::uint32_t one = in.read<std::uint32_t>();
      if (one == 1)
        m_bigEndian = false;
      else if (one == 0x01000000u)
        m_bigEndian = true;
      else
        return fail(in.at("expected the binary integer 1 that tells the byte order"));
      m_text.seek(in.offset());
    }
    return m_text.expect("$EndMeshFormat", m_error);
  }

  bool skipSection(std::string_view name) {
    const std::string end = "$End" + std::string(name);
    while (!m_text.atEnd()) {
      const std::string_view token = m_text.next();
      if (token.size() == end.size() &&
          std::equal(token.begin(), token.end(), end.begin(),
                     [](char a, char b) { return std::tolower(a) == std::tolower(b); }))
        return true;
    }
    return fail(
        m_text.at("section $" + std::string(name) + " has no '" + end + "' (truncated file?)"));
  }

  bool addNode(long long tag, const Vec3d& p, const std::string& where) {
    if (!m_nodes.add(tag, static_cast<Index>(m_mesh.positions.size())))
      return fail(where + "node tag " + std::to_string(tag) +
                  (tag < 0 ? " is negative" : " is defined twice"));
    m_mesh.positions.push_back(p);
    return true;
  }

  // --- Version 1 and 2, ASCII ----------------------------------------------------------------

  bool readNodesV1V2(std::string_view endKeyword) {
    std::size_t count = 0;
    if (!m_text.readCount(count, "the number of nodes", maxItems(m_bytes, 8), m_error))
      return false;
    m_mesh.positions.reserve(count);
    for (std::size_t i = 0; i < count; ++i) {
      long long tag = 0;
      Vec3d p;
      if (!m_text.readInteger(tag, "a node tag", m_error)) return false;
      for (int k = 0; k < 3; ++k)
        if (!m_text.readDouble(p[k], "a node coordinate", m_error)) return false;
      if (!addNode(tag, p, "line " + std::to_string(m_text.line()) + ": ")) return false;
    }
    return m_text.expect(endKeyword, m_error);
  }

  bool readElementsV1V2(std::string_view endKeyword) {
    std::size_t count = 0;
    if (!m_text.readCount(count, "the number of elements", maxItems(m_bytes, 8), m_error))
      return false;
    std::vector<Index> points;
    for (std::size_t i = 0; i < count; ++i) {
      long long number = 0, type = 0;
      if (!m_text.readInteger(number, "an element number", m_error)) return false;
      const int line = m_text.line();
      if (!m_text.readInteger(type, "an element type", m_error)) return false;
      const auto info = elementType(type);
      if (!info) return fail(m_text.at(unsupportedType(type)));
      long long nodeCount = info->nodes;
      long long physical = 0;  // version 1: reg-phys; version 2: the first tag
      if (m_version == 1) {
        long long elementary = 0;
        if (!m_text.readInteger(physical, "the physical region", m_error) ||
            !m_text.readInteger(elementary, "the elementary region", m_error) ||
            !m_text.readInteger(nodeCount, "the number of nodes", m_error))
          return false;
        if (nodeCount != info->nodes)
          return fail(m_text.at("element " + std::to_string(number) + " of type " +
                                std::to_string(type) + " (" + info->name + ") has " +
                                std::to_string(nodeCount) + " nodes; expected " +
                                std::to_string(info->nodes)));
      } else {
        long long tags = 0;
        if (!m_text.readInteger(tags, "the number of tags", m_error)) return false;
        if (tags < 0 || tags > 1000)
          return fail(m_text.at("bad number of tags " + std::to_string(tags)));
        for (long long t = 0; t < tags; ++t) {
          long long tag = 0;
          if (!m_text.readInteger(tag, "an element tag", m_error)) return false;
          if (t == 0) physical = tag;
        }
      }
      points.clear();
      for (long long k = 0; k < nodeCount; ++k) {
        long long tag = 0;
        if (!m_text.readInteger(tag, "a node tag of element " + std::to_string(number), m_error))
          return false;
        const Index index = m_nodes.find(tag);
        if (index == kInvalidIndex)
          return fail("line " + std::to_string(line) + ": element " + std::to_string(number) +
                      " uses node " + std::to_string(tag) + ", which is not in the node section");
        points.push_back(index);
      }
      if (!checkGroup(physical, "line " + std::to_string(line) + ": element " +
                                    std::to_string(number)))
        return false;
      m_elements.add(type, *info, points.data(), physical);
    }
    return m_text.expect(endKeyword, m_error);
  }

  // --- Version 2, binary -----------------------------------------------------------------------

  /// After a count at the end of a line: the binary data starts on the next line.
  ByteCursor binaryAfterLine() {
    m_text.restOfLine();
    return ByteCursor(m_bytes, m_text.offset(), m_bigEndian);
  }

  bool endBinary(const ByteCursor& in, std::string_view endKeyword) {
    m_text.seek(in.offset());
    const std::string_view token = m_text.next();
    if (token == endKeyword) return true;
    return fail("byte offset " + std::to_string(in.offset()) + ": expected '" +
                std::string(endKeyword) + "' after the binary data, got " +
                (token.empty() ? std::string("the end of the file") : quoted(token)));
  }

  bool readNodesV2Binary() {
    std::size_t count = 0;
    if (!m_text.readCount(count, "the number of nodes", maxItems(m_bytes, 28), m_error))
      return false;
    ByteCursor in = binaryAfterLine();
    if (!in.has(count, 4 + 3 * 8)) return fail(in.truncated(std::to_string(count) + " nodes"));
    m_mesh.positions.reserve(count);
    for (std::size_t i = 0; i < count; ++i) {
      const std::size_t where = in.offset();
      const long long tag = in.read<std::int32_t>();
      Vec3d p;
      for (int k = 0; k < 3; ++k) p[k] = in.read<double>();
      if (!p.allFinite())
        return fail("byte offset " + std::to_string(where) + ": node " + std::to_string(tag) +
                    " has a coordinate that is not a finite number");
      if (!addNode(tag, p, "byte offset " + std::to_string(where) + ": ")) return false;
    }
    return endBinary(in, "$EndNodes");
  }

  bool readElementsV2Binary() {
    std::size_t count = 0;
    if (!m_text.readCount(count, "the number of elements", maxItems(m_bytes, 8), m_error))
      return false;
    ByteCursor in = binaryAfterLine();
    std::vector<Index> points;
    std::size_t done = 0;
    while (done < count) {
      // Block header: element type, number of elements that follow, number of tags.
      if (!in.has(3, 4)) return fail(in.truncated("an element block header (3 integers)"));
      const std::size_t headerAt = in.offset();
      const long long type = in.read<std::int32_t>();
      const long long following = in.read<std::int32_t>();
      const long long tags = in.read<std::int32_t>();
      const auto info = elementType(type);
      if (!info)
        return fail("byte offset " + std::to_string(headerAt) + ": " + unsupportedType(type));
      if (following <= 0 || static_cast<std::size_t>(following) > count - done || tags < 0 ||
          tags > 1000)
        return fail("byte offset " + std::to_string(headerAt) + ": bad element block header (" +
                    std::to_string(following) + " elements, " + std::to_string(tags) + " tags)");
      const std::size_t perElement = 1 + static_cast<std::size_t>(tags) + info->nodes;
      if (!in.has(static_cast<std::size_t>(following) * perElement, 4))
        return fail(
            in.truncated(std::to_string(following) + " elements of type " + std::to_string(type)));
      for (long long e = 0; e < following; ++e) {
        const std::size_t where = in.offset();
        const long long number = in.read<std::int32_t>();
        const long long physical = tags > 0 ? in.read<std::int32_t>() : 0;
        in.skip(4 * static_cast<std::size_t>(tags > 0 ? tags - 1 : 0));
        points.clear();
        for (int k = 0; k < info->nodes; ++k) {
          const long long tag = in.read<std::int32_t>();
          const Index index = m_nodes.find(tag);
          if (index == kInvalidIndex)
            return fail("byte offset " + std::to_string(where) + ": element " +
                        std::to_string(number) + " uses node " + std::to_string(tag) +
                        ", which is not in the node section");
          points.push_back(index);
        }
        if (!checkGroup(physical, "byte offset " + std::to_string(where) + ": element " +
                                      std::to_string(number)))
          return false;
        m_elements.add(type, *info, points.data(), physical);
      }
      done += static_cast<std::size_t>(following);
    }
    return endBinary(in, "$EndElements");
  }

  // --- Version 4.1, ASCII and binary -------------------------------------------------------------

  /// Reads the four numbers that start $Nodes and $Elements, and each block's header.
  /// A count (bounded by what the file can hold) or, with bounded = false, a tag.
  bool readSize(std::size_t& value, std::string_view what, ByteCursor* in, bool bounded = true) {
    const std::size_t max = bounded ? maxItems(m_bytes, 2) : std::size_t{1} << 62;
    if (!in) return m_text.readCount(value, what, max, m_error);
    if (!in->has(1, 8)) return fail(in->truncated(what));
    const std::uint64_t v = in->read<std::uint64_t>();
    if (v > max)
      return fail(in->at(std::string(what) + " " + std::to_string(v) +
                         " is larger than the file can hold"));
    value = static_cast<std::size_t>(v);
    return true;
  }
  bool readInt(long long& value, std::string_view what, ByteCursor* in) {
    if (!in) return m_text.readInteger(value, what, m_error);
    if (!in->has(1, 4)) return fail(in->truncated(what));
    value = in->read<std::int32_t>();
    return true;
  }
  bool readReal(std::string_view what, ByteCursor* in) {
    double ignored = 0;
    if (!in) return m_text.readDouble(ignored, what, m_error);
    if (!in->has(1, 8)) return fail(in->truncated(what));
    in->read<double>();
    return true;
  }
  std::string where(const ByteCursor* in) const {
    return in ? "byte offset " + std::to_string(in->offset()) + ": "
              : "line " + std::to_string(m_text.line()) + ": ";
  }

  bool readNodesV4() {
    std::optional<ByteCursor> binary;
    if (m_binary) binary = binaryAfterLine();
    ByteCursor* in = binary ? &*binary : nullptr;
    std::size_t blocks = 0, total = 0, minTag = 0, maxTag = 0;
    if (!readSize(blocks, "the number of node blocks", in) ||
        !readSize(total, "the number of nodes", in) ||
        !readSize(minTag, "the smallest node tag", in, false) ||
        !readSize(maxTag, "the largest node tag", in, false))
      return false;
    m_mesh.positions.reserve(std::min(total, maxItems(m_bytes, 24)));
    std::vector<long long> tags;
    for (std::size_t b = 0; b < blocks; ++b) {
      long long dim = 0, entity = 0, parametric = 0;
      std::size_t count = 0;
      if (!readInt(dim, "the entity dimension of a node block", in) ||
          !readInt(entity, "the entity tag of a node block", in) ||
          !readInt(parametric, "the parametric flag of a node block", in) ||
          !readSize(count, "the number of nodes in a block", in))
        return false;
      if (dim < 0 || dim > 3 || (parametric != 0 && parametric != 1))
        return fail(where(in) + "bad node block header (dimension " + std::to_string(dim) +
                    ", parametric " + std::to_string(parametric) + ")");
      const int values = 3 + (parametric ? static_cast<int>(dim) : 0);
      tags.resize(count);
      if (in) {
        if (!in->has(count, 8 + 8 * values))
          return fail(in->truncated(std::to_string(count) + " nodes"));
        for (auto& tag : tags) tag = static_cast<long long>(in->read<std::uint64_t>());
      } else {
        for (auto& tag : tags)
          if (!m_text.readInteger(tag, "a node tag", m_error)) return false;
      }
      for (std::size_t i = 0; i < count; ++i) {
        const std::string at = where(in);
        Vec3d p;
        for (int k = 0; k < values; ++k) {
          double v = 0;
          if (in)
            v = in->read<double>();
          else if (!m_text.readDouble(v, "a node coordinate", m_error))
            return false;
          if (k < 3) p[k] = v;
        }
        if (!p.allFinite())
          return fail(at + "node " + std::to_string(tags[i]) +
                      " has a coordinate that is not a finite number");
        if (!addNode(tags[i], p, at)) return false;
      }
    }
    if (in) return endBinary(*in, "$EndNodes");
    return m_text.expect("$EndNodes", m_error);
  }

  /// A physical group is a positive number (0: none); it is kept as an int.
  bool checkGroup(long long physical, const std::string& element) {
    if (physical >= 0 && physical <= std::numeric_limits<int>::max()) return true;
    return fail(element + " has the physical group " + std::to_string(physical) +
                ": expected a number from 0 to " +
                std::to_string(std::numeric_limits<int>::max()));
  }

  /// Version 4.1 $Entities: points, curves, surfaces and volumes with their physical groups
  /// (the first one is the elements' group; an entity in several groups is rare and its other
  /// groups are not kept). Bounding boxes and bounding entities are skipped.
  bool readEntitiesV4() {
    std::optional<ByteCursor> binary;
    if (m_binary) binary = binaryAfterLine();
    ByteCursor* in = binary ? &*binary : nullptr;
    std::size_t counts[4] = {};
    for (std::size_t& c : counts)
      if (!readSize(c, "the number of entities of a dimension", in)) return false;
    for (long long dim = 0; dim < 4; ++dim)
      for (std::size_t e = 0; e < counts[dim]; ++e) {
        long long tag = 0;
        if (!readInt(tag, "an entity tag", in)) return false;
        // A point has its coordinates, the others their bounding box.
        for (int k = 0; k < (dim == 0 ? 3 : 6); ++k)
          if (!readReal("an entity coordinate", in)) return false;
        std::size_t physicalCount = 0;
        if (!readSize(physicalCount, "the number of physical groups of an entity", in))
          return false;
        for (std::size_t k = 0; k < physicalCount; ++k) {
          long long physical = 0;
          if (!readInt(physical, "a physical group", in)) return false;
          if (!checkGroup(physical < 0 ? -physical : physical,
                          where(in) + "entity " + std::to_string(tag)))
            return false;
          // Gmsh writes a group negative to flip its orientation: the group is its magnitude.
          if (k == 0) m_entityGroups[{dim, tag}] = physical < 0 ? -physical : physical;
        }
        if (dim == 0) continue;
        std::size_t bounding = 0;
        if (!readSize(bounding, "the number of bounding entities", in)) return false;
        for (std::size_t k = 0; k < bounding; ++k) {
          long long ignored = 0;
          if (!readInt(ignored, "a bounding entity tag", in)) return false;
        }
      }
    if (in) return endBinary(*in, "$EndEntities");
    return m_text.expect("$EndEntities", m_error);
  }

  bool readElementsV4() {
    std::optional<ByteCursor> binary;
    if (m_binary) binary = binaryAfterLine();
    ByteCursor* in = binary ? &*binary : nullptr;
    std::size_t blocks = 0, total = 0, minTag = 0, maxTag = 0;
    if (!readSize(blocks, "the number of element blocks", in) ||
        !readSize(total, "the number of elements", in) ||
        !readSize(minTag, "the smallest element tag", in, false) ||
        !readSize(maxTag, "the largest element tag", in, false))
      return false;
    std::vector<Index> points;
    for (std::size_t b = 0; b < blocks; ++b) {
      long long dim = 0, entity = 0, type = 0;
      std::size_t count = 0;
      if (!readInt(dim, "the entity dimension of an element block", in) ||
          !readInt(entity, "the entity tag of an element block", in))
        return false;
      const std::string typeAt = where(in);
      if (!readInt(type, "the element type of a block", in) ||
          !readSize(count, "the number of elements in a block", in))
        return false;
      const auto info = elementType(type);
      if (!info) return fail(typeAt + unsupportedType(type));
      const auto group = m_entityGroups.find({dim, entity});
      const long long physical = group == m_entityGroups.end() ? 0 : group->second;
      if (in && !in->has(count, 8 * (1 + info->nodes)))
        return fail(
            in->truncated(std::to_string(count) + " elements of type " + std::to_string(type)));
      for (std::size_t e = 0; e < count; ++e) {
        long long number = 0;
        const std::string at = where(in);
        if (in)
          number = static_cast<long long>(in->read<std::uint64_t>());
        else if (!m_text.readInteger(number, "an element tag", m_error))
          return false;
        points.clear();
        for (int k = 0; k < info->nodes; ++k) {
          long long tag = 0;
          if (in)
            tag = static_cast<long long>(in->read<std::uint64_t>());
          else if (!m_text.readInteger(tag, "a node tag of element " + std::to_string(number),
                                       m_error))
            return false;
          const Index index = m_nodes.find(tag);
          if (index == kInvalidIndex)
            return fail(at + "element " + std::to_string(number) + " uses node " +
                        std::to_string(tag) + ", which is not in the node section");
          points.push_back(index);
        }
        m_elements.add(type, *info, points.data(), physical);
      }
    }
    if (in) return endBinary(*in, "$EndElements");
    return m_text.expect("$EndElements", m_error);
  }

  std::string_view m_bytes;
  TextCursor m_text;
  MeshData& m_mesh;
  ElementSink m_elements;
  std::string& m_error;
  NodeNumbering m_nodes;
  /// Version 4: (dimension, entity tag) -> the entity's first physical group, from $Entities.
  std::map<std::pair<long long, long long>, long long> m_entityGroups;
  int m_version = 0;  // 1, 2 or 4
  bool m_binary = false;
  bool m_bigEndian = false;
};

}  // namespace

bool parseGmsh(std::string_view bytes, MeshData& mesh, std::string& error) {
  GmshReader reader(bytes, mesh, error);
  return reader.read();
}

}  // namespace stroma::meshio
