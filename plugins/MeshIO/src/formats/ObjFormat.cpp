// SPDX-License-Identifier: MIT
// Wavefront OBJ (.obj): v, vt, vn, f and l lines. Other statements (g, o, s, usemtl, mtllib,
// curves) are ignored: they carry no mesh geometry.
// Reference: "Object Files (.obj)", Wavefront Advanced Visualizer manual, appendix B1.
#include <map>
#include <tuple>

#include "FormatParsers.h"
#include "TextCursor.h"

namespace stroma::meshio {

namespace {

/// One corner of a face: indices into the v, vt and vn lists (-1 when absent).
struct Corner {
  long long v = -1, vt = -1, vn = -1;
  auto key() const { return std::tie(v, vt, vn); }
  bool operator<(const Corner& o) const { return key() < o.key(); }
};

struct Face {
  std::vector<Corner> corners;
  int line = 0;
  bool isLine = false;  // an "l" statement
};

class ObjReader {
 public:
  ObjReader(std::string_view bytes, const MeshParseOptions& options, MeshData& mesh,
            std::string& error)
      : m_text(bytes), m_options(options), m_mesh(mesh), m_error(error) {}

  bool read() {
    while (m_text.offset() < m_text.text().size()) {
      std::string_view line = m_text.restOfLine();
      const int lineNumber = m_line++;
      if (const auto hash = line.find('#'); hash != std::string_view::npos)
        line = line.substr(0, hash);
      TextCursor in(line);
      const std::string_view keyword = in.next();
      bool ok = true;
      if (keyword == "v")
        ok = readVector(in, lineNumber, 3, 3, m_v, "vertex");
      else if (keyword == "vn")
        ok = readVector(in, lineNumber, 3, 3, m_vn, "normal");
      else if (keyword == "vt")
        ok = readVector(in, lineNumber, 1, 2, m_vt, "texture coordinate");
      else if (keyword == "f" || keyword == "l")
        ok = readFace(in, lineNumber, keyword == "l");
      if (!ok) return false;
    }
    return build();
  }

 private:
  bool fail(int line, const std::string& text) {
    m_error = "line " + std::to_string(line) + ": " + text;
    return false;
  }

  /// Reads `min` to 3 numbers (keeps the first `keep`); a 4th (the weight w) is allowed.
  bool readVector(TextCursor& in, int line, int min, int keep, std::vector<Vec3d>& out,
                  const char* what) {
    Vec3d v = Vec3d::Zero();
    int n = 0;
    for (std::string_view token = in.next(); !token.empty(); token = in.next()) {
      double x = 0;
      if (!parseNumber(token, x))
        return fail(line,
                    std::string("expected a number in the ") + what + ", got " + quoted(token));
      if (n < 3 && n < keep) v[n] = x;
      if (++n > 4) return fail(line, std::string("too many numbers in the ") + what);
    }
    if (n < min)
      return fail(line, std::string("expected ") + std::to_string(min) + " numbers in the " + what +
                            ", got " + std::to_string(n));
    out.push_back(v);
    return true;
  }

  /// A 1-based or negative (relative) OBJ index to a 0-based one, checked later against the
  /// list size (vertices may be defined after the faces that use them).
  bool resolve(std::string_view token, std::size_t defined, long long& index, int line,
               const char* what) {
    long long i = 0;
    if (!parseNumber(token, i))
      return fail(line, std::string("expected a ") + what + " index, got " + quoted(token));
    if (i == 0) return fail(line, std::string("bad ") + what + " index 0 (OBJ indices start at 1)");
    index = i > 0 ? i - 1 : static_cast<long long>(defined) + i;
    if (index < 0)
      return fail(line, std::string(what) + " index " + std::to_string(i) +
                            " points before the first " + what);
    return true;
  }

  bool readFace(TextCursor& in, int line, bool isLine) {
    Face face;
    face.line = line;
    face.isLine = isLine;
    for (std::string_view token = in.next(); !token.empty(); token = in.next()) {
      Corner c;
      const auto slash1 = token.find('/');
      const std::string_view v = token.substr(0, slash1);
      if (!resolve(v, m_v.size(), c.v, line, "vertex")) return false;
      if (slash1 != std::string_view::npos) {
        const std::string_view rest = token.substr(slash1 + 1);
        const auto slash2 = rest.find('/');
        const std::string_view vt = rest.substr(0, slash2);
        if (!vt.empty() && !resolve(vt, m_vt.size(), c.vt, line, "texture coordinate"))
          return false;
        if (slash2 != std::string_view::npos) {
          const std::string_view vn = rest.substr(slash2 + 1);
          if (!vn.empty() && !resolve(vn, m_vn.size(), c.vn, line, "normal")) return false;
        }
      }
      face.corners.push_back(c);
    }
    if (face.corners.size() < 2)
      return fail(line, std::string("expected at least 2 vertices in the ") +
                            (isLine ? "line" : "face") + ", got " +
                            std::to_string(face.corners.size()));
    m_faces.push_back(std::move(face));
    return true;
  }

  bool build() {
    // Check every index now that all lists are known. A bad vertex index is an error; a bad
    // texture coordinate or normal index only loses that attribute (some exporters write them).
    std::size_t badAttributes = 0;
    int firstBadLine = 0;
    for (Face& face : m_faces)
      for (Corner& c : face.corners) {
        if (c.v >= static_cast<long long>(m_v.size()))
          return fail(face.line, "vertex index " + std::to_string(c.v + 1) +
                                     " is out of range: the file defines " +
                                     std::to_string(m_v.size()) + " vertices");
        const bool badVt = c.vt >= static_cast<long long>(m_vt.size());
        const bool badVn = c.vn >= static_cast<long long>(m_vn.size());
        if (badVt) c.vt = -1;
        if (badVn) c.vn = -1;
        if ((badVt || badVn) && badAttributes++ == 0) firstBadLine = face.line;
      }
    if (badAttributes > 0)
      m_mesh.warnings.push_back(
          std::to_string(badAttributes) +
          " face corners use a texture coordinate or normal index past those defined (first at "
          "line " +
          std::to_string(firstBadLine) + "); those are ignored");
    // Points: the v list, or one point per distinct corner when seams are kept.
    std::map<Corner, Index> seamPoints;
    auto pointOf = [&](const Corner& c) -> Index {
      if (!m_options.handleSeams) return static_cast<Index>(c.v);
      const auto [it, inserted] =
          seamPoints.try_emplace(c, static_cast<Index>(m_mesh.positions.size()));
      if (inserted) {
        m_mesh.positions.push_back(m_v[c.v]);
        if (!m_vt.empty())
          m_mesh.texcoords.push_back(c.vt >= 0 ? Vec2d(m_vt[c.vt].head<2>()) : Vec2d::Zero());
        if (!m_vn.empty()) m_mesh.normals.push_back(c.vn >= 0 ? m_vn[c.vn] : Vec3d::Zero());
      }
      return it->second;
    };
    if (!m_options.handleSeams) {
      m_mesh.positions = m_v;
      if (!m_vt.empty()) m_mesh.texcoords.assign(m_v.size(), Vec2d::Zero());
      if (!m_vn.empty()) m_mesh.normals.assign(m_v.size(), Vec3d::Zero());
    }
    std::vector<Index> polygon;
    for (const Face& face : m_faces) {
      polygon.clear();
      for (const Corner& c : face.corners) {
        const Index p = pointOf(c);
        polygon.push_back(p);
        // Without seams, a point keeps the last texture coordinate and normal given for it.
        if (!m_options.handleSeams) {
          if (c.vt >= 0) m_mesh.texcoords[p] = m_vt[c.vt].head<2>();
          if (c.vn >= 0) m_mesh.normals[p] = m_vn[c.vn];
        }
      }
      if (face.isLine || polygon.size() == 2) {
        for (std::size_t k = 0; k + 1 < polygon.size(); ++k)
          m_mesh.edges.push_back({polygon[k], polygon[k + 1]});
      } else {
        addPolygon(m_mesh, polygon.data(), polygon.size(), m_options.triangulate);
      }
    }
    return true;
  }

  TextCursor m_text;
  const MeshParseOptions& m_options;
  MeshData& m_mesh;
  std::string& m_error;
  int m_line = 1;
  std::vector<Vec3d> m_v, m_vn, m_vt;
  std::vector<Face> m_faces;
};

}  // namespace

bool parseObj(std::string_view bytes, const MeshParseOptions& options, MeshData& mesh,
              std::string& error) {
  ObjReader reader(bytes, options, mesh, error);
  return reader.read();
}

}  // namespace stroma::meshio
