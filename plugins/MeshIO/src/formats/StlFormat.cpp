// SPDX-License-Identifier: MIT
// STL files, ASCII ("solid ... facet normal ... outer loop ... vertex ...") and binary (a
// header, a 32-bit triangle count, then 50 bytes per triangle, little-endian).
// Reference: 3D Systems, "StereoLithography Interface Specification" (1989).
#include <cstring>
#include <unordered_map>

#include "ByteCursor.h"
#include "FormatParsers.h"
#include "TextCursor.h"

namespace stroma::meshio {

namespace {

/// Numbers STL vertices, merging those at exactly the same position.
class PointMerger {
 public:
  PointMerger(MeshData& mesh, bool merge) : m_mesh(mesh), m_merge(merge) {}

  Index add(const Vec3d& p) {
    if (!m_merge) {
      m_mesh.positions.push_back(p);
      return static_cast<Index>(m_mesh.positions.size() - 1);
    }
    Key key{};
    for (int k = 0; k < 3; ++k) {
      const double x = p[k] == 0.0 ? 0.0 : p[k];  // -0 and +0 are one position
      std::memcpy(&key[k], &x, sizeof x);
    }
    const auto [it, inserted] = m_ids.try_emplace(key, static_cast<Index>(m_mesh.positions.size()));
    if (inserted) m_mesh.positions.push_back(p);
    return it->second;
  }

 private:
  using Key = std::array<std::uint64_t, 3>;
  struct Hash {
    std::size_t operator()(const Key& k) const {
      std::uint64_t h = k[0] * 0x9E3779B97F4A7C15ull;
      h ^= k[1] + 0x632BE59BD9B4E019ull + (h << 6) + (h >> 2);
      h ^= k[2] + 0x85157AF5ull + (h << 6) + (h >> 2);
      return static_cast<std::size_t>(h);
    }
  };
  MeshData& m_mesh;
  bool m_merge;
  std::unordered_map<Key, Index, Hash> m_ids;
};

/// Per-point normals: the normalized sum of the normals of the triangles around each point
/// (the file's facet normal, or the geometric one where the file gives zero).
void computeNormals(MeshData& mesh, const std::vector<Vec3d>& facetNormals) {
  mesh.normals.assign(mesh.positions.size(), Vec3d::Zero());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Triangle& tri = mesh.triangles[t];
    Vec3d n = facetNormals[t];
    if (n.squaredNorm() == 0.0) {
      n = (mesh.positions[tri[1]] - mesh.positions[tri[0]])
              .cross(mesh.positions[tri[2]] - mesh.positions[tri[0]]);
      if (n.squaredNorm() > 0) n.normalize();
    }
    for (Index v : tri) mesh.normals[v] += n;
  }
  for (Vec3d& n : mesh.normals)
    if (n.squaredNorm() > 0) n.normalize();
}

bool parseBinary(std::string_view bytes, const MeshParseOptions& options, MeshData& mesh,
                 std::string& error) {
  ByteCursor in(bytes, 0, false);
  if (!in.has(1, options.stlHeaderSize + 4)) {
    error = in.truncated("a binary STL header of " + std::to_string(options.stlHeaderSize) +
                         " bytes and a triangle count");
    return false;
  }
  in.skip(options.stlHeaderSize);
  const std::uint32_t count = in.read<std::uint32_t>();
  if (!in.has(count, 50)) {
    error = in.truncated(std::to_string(count) + " triangles of 50 bytes (the file has " +
                         std::to_string(bytes.size() - in.offset()) + " bytes after the header)");
    return false;
  }
  PointMerger points(mesh, options.mergePositions);
  std::vector<Vec3d> facetNormals;
  facetNormals.reserve(count);
  mesh.triangles.reserve(count);
  for (std::uint32_t t = 0; t < count; ++t) {
    const std::size_t at = in.offset();
    Vec3d n;
    for (int k = 0; k < 3; ++k) n[k] = in.read<float>();
    Triangle tri;
    for (int v = 0; v < 3; ++v) {
      Vec3d p;
      for (int k = 0; k < 3; ++k) p[k] = in.read<float>();
      if (!p.allFinite()) {
        error = "byte offset " + std::to_string(at) + ": triangle " + std::to_string(t) +
                " has a coordinate that is not a finite number";
        return false;
      }
      tri[v] = points.add(p);
    }
    in.skip(2);  // attribute byte count
    facetNormals.push_back(n.allFinite() ? n : Vec3d::Zero());
    mesh.triangles.push_back(tri);
  }
  computeNormals(mesh, facetNormals);
  return true;
}

bool parseAscii(std::string_view bytes, const MeshParseOptions& options, MeshData& mesh,
                std::string& error) {
  TextCursor in(bytes);
  PointMerger points(mesh, options.mergePositions);
  std::vector<Vec3d> facetNormals;
  bool inSolid = false;
  std::vector<Index> polygon;
  while (!in.atEnd()) {
    const std::string_view word = in.next();
    if (word == "solid") {
      in.restOfLine();  // the solid's name
      inSolid = true;
    } else if (word == "endsolid" ||
               (word == "end" && in.peek() == "solid")) {  // "end solid": some writers
      in.restOfLine();
      inSolid = false;
    } else if (word == "facet") {
      if (!inSolid) {
        error = in.at("'facet' outside 'solid ... endsolid'");
        return false;
      }
      Vec3d n = Vec3d::Zero();
      if (!in.expect("normal", error)) return false;
      for (int k = 0; k < 3; ++k)
        if (!in.readDouble(n[k], "a facet normal component", error)) return false;
      if (!in.expect("outer", error) || !in.expect("loop", error)) return false;
      polygon.clear();
      while (in.peek() == "vertex") {
        in.next();
        Vec3d p;
        for (int k = 0; k < 3; ++k)
          if (!in.readDouble(p[k], "a vertex coordinate", error)) return false;
        polygon.push_back(points.add(p));
      }
      if (polygon.size() < 3) {
        error = in.at("a facet needs 3 vertices, got " + std::to_string(polygon.size()));
        return false;
      }
      if (!in.expect("endloop", error) || !in.expect("endfacet", error)) return false;
      addPolygon(mesh, polygon.data(), polygon.size(), true);
      facetNormals.resize(mesh.triangles.size(), n);
    } else {
      error = in.expected("'solid', 'facet' or 'endsolid'", word);
      return false;
    }
  }
  if (inSolid) {
    error = in.expected("'endsolid'", "");
    return false;
  }
  computeNormals(mesh, facetNormals);
  return true;
}

}  // namespace

bool parseStl(std::string_view bytes, const MeshParseOptions& options, MeshData& mesh,
              std::string& error) {
  // A binary file may also start with "solid": its size (header, count, 50 bytes per
  // triangle) or a NUL byte (never in ASCII STL) tells.
  const std::size_t header = options.stlHeaderSize;
  bool binary = options.forceBinary || bytes.find('\0') != std::string_view::npos;
  if (!binary && bytes.size() >= header + 4) {
    std::uint32_t count = 0;
    std::memcpy(&count, bytes.data() + header, 4);
    if (header + 4 + 50 * static_cast<std::uint64_t>(count) == bytes.size()) binary = true;
  }
  if (!binary) {
    std::size_t i = 0;
    while (i < bytes.size() &&
           (bytes[i] == ' ' || bytes[i] == '\t' || bytes[i] == '\r' || bytes[i] == '\n'))
      ++i;
    binary = bytes.substr(i, 5) != "solid";
  }
  return binary ? parseBinary(bytes, options, mesh, error)
                : parseAscii(bytes, options, mesh, error);
}

}  // namespace stroma::meshio
