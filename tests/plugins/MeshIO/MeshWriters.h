// SPDX-License-Identifier: MIT
// Writers of small binary mesh files for the loader tests (the ASCII ones are committed in
// data/): Gmsh 2.2 and 4.1 binary, legacy VTK BINARY, XML VTK with base64 data, binary STL.
#pragma once

#include <bit>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "core/Types.h"
#include "topology/TopologyTypes.h"

namespace stroma::test {

/// The unit cube's corners and its split into five tetrahedra (TopologyTypes.h orders).
inline std::vector<Vec3d> cubePoints() {
  return {Vec3d(0, 0, 0), Vec3d(1, 0, 0), Vec3d(1, 1, 0), Vec3d(0, 1, 0),
          Vec3d(0, 0, 1), Vec3d(1, 0, 1), Vec3d(1, 1, 1), Vec3d(0, 1, 1)};
}
inline std::vector<Tetrahedron> cubeTetrahedra() {
  return {{1, 0, 5, 2}, {3, 0, 2, 7}, {4, 0, 7, 5}, {6, 2, 5, 7}, {0, 2, 7, 5}};
}

class Bytes {
 public:
  explicit Bytes(bool bigEndian = false) : m_big(bigEndian) {}
  template <class T>
  Bytes& put(T value) {
    unsigned char raw[sizeof(T)];
    std::memcpy(raw, &value, sizeof(T));
    if (m_big != (std::endian::native == std::endian::big))
      for (std::size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(raw[i], raw[sizeof(T) - 1 - i]);
    m_text.append(reinterpret_cast<const char*>(raw), sizeof(T));
    return *this;
  }
  Bytes& text(const std::string& s) {
    m_text += s;
    return *this;
  }
  const std::string& str() const { return m_text; }

 private:
  bool m_big;
  std::string m_text;
};

/// Gmsh 2.2 binary: node tags 10, 20, ... 80; the five tetrahedra in one block, one triangle.
inline std::string gmsh22Binary() {
  Bytes b;
  b.text("$MeshFormat\n2.2 1 8\n").put<std::int32_t>(1).text("\n$EndMeshFormat\n");
  const auto p = cubePoints();
  b.text("$Nodes\n8\n");
  for (int i = 0; i < 8; ++i) {
    b.put<std::int32_t>((i + 1) * 10);
    for (int k = 0; k < 3; ++k) b.put<double>(p[i][k]);
  }
  b.text("\n$EndNodes\n$Elements\n6\n");
  b.put<std::int32_t>(4).put<std::int32_t>(5).put<std::int32_t>(2);  // type, count, tags
  int id = 1;
  for (const auto& t : cubeTetrahedra()) {
    b.put<std::int32_t>(id++).put<std::int32_t>(1).put<std::int32_t>(1);
    for (Index v : t) b.put<std::int32_t>(std::int32_t((v + 1) * 10));
  }
  b.put<std::int32_t>(2).put<std::int32_t>(1).put<std::int32_t>(0);
  b.put<std::int32_t>(id++).put<std::int32_t>(10).put<std::int32_t>(40).put<std::int32_t>(30);
  b.text("\n$EndElements\n");
  return b.str();
}

/// Gmsh 4.1 binary: one node block (tags 10 ... 80), one block of five tetrahedra; with
/// `volumeGroup` > 0, an $Entities section puts their volume (entity 1) in that physical group.
inline std::string gmsh41Binary(int volumeGroup = 0) {
  Bytes b;
  b.text("$MeshFormat\n4.1 1 8\n").put<std::int32_t>(1).text("\n$EndMeshFormat\n");
  if (volumeGroup > 0) {
    b.text("$Entities\n");
    b.put<std::uint64_t>(0).put<std::uint64_t>(0).put<std::uint64_t>(0).put<std::uint64_t>(1);
    b.put<std::int32_t>(1);  // the volume's tag, its bounding box, one group, no bounding surface
    for (double v : {0.0, 0.0, 0.0, 1.0, 1.0, 1.0}) b.put<double>(v);
    b.put<std::uint64_t>(1).put<std::int32_t>(volumeGroup).put<std::uint64_t>(0);
    b.text("\n$EndEntities\n");
  }
  b.text("$Nodes\n");
  b.put<std::uint64_t>(1).put<std::uint64_t>(8).put<std::uint64_t>(10).put<std::uint64_t>(80);
  b.put<std::int32_t>(3).put<std::int32_t>(1).put<std::int32_t>(0).put<std::uint64_t>(8);
  for (int i = 0; i < 8; ++i) b.put<std::uint64_t>((i + 1) * 10);
  for (const Vec3d& x : cubePoints())
    for (int k = 0; k < 3; ++k) b.put<double>(x[k]);
  b.text("\n$EndNodes\n$Elements\n");
  b.put<std::uint64_t>(1).put<std::uint64_t>(5).put<std::uint64_t>(1).put<std::uint64_t>(5);
  b.put<std::int32_t>(3).put<std::int32_t>(1).put<std::int32_t>(4).put<std::uint64_t>(5);
  std::uint64_t id = 1;
  for (const auto& t : cubeTetrahedra()) {
    b.put<std::uint64_t>(id++);
    for (Index v : t) b.put<std::uint64_t>((v + 1) * 10);
  }
  b.text("\n$EndElements\n");
  return b.str();
}

/// Legacy VTK BINARY (big-endian) unstructured grid of the five tetrahedra, with point normals.
inline std::string vtkLegacyBinary() {
  Bytes b(true);
  b.text("# vtk DataFile Version 3.0\nbinary cube\nBINARY\nDATASET UNSTRUCTURED_GRID\n");
  b.text("POINTS 8 float\n");
  for (const Vec3d& x : cubePoints())
    for (int k = 0; k < 3; ++k) b.put<float>(float(x[k]));
  b.text("\nCELLS 5 25\n");
  for (const auto& t : cubeTetrahedra()) {
    b.put<std::int32_t>(4);
    for (Index v : t) b.put<std::int32_t>(std::int32_t(v));
  }
  b.text("\nCELL_TYPES 5\n");
  for (int i = 0; i < 5; ++i) b.put<std::int32_t>(10);
  b.text("\nPOINT_DATA 8\nNORMALS normals float\n");
  for (int i = 0; i < 8; ++i) b.put<float>(0).put<float>(0).put<float>(1);
  b.text("\n");
  return b.str();
}

inline std::string base64(const std::string& raw) {
  static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  std::size_t i = 0;
  for (; i + 2 < raw.size(); i += 3) {
    const unsigned n =
        (unsigned char)raw[i] << 16 | (unsigned char)raw[i + 1] << 8 | (unsigned char)raw[i + 2];
    out += table[n >> 18 & 63];
    out += table[n >> 12 & 63];
    out += table[n >> 6 & 63];
    out += table[n & 63];
  }
  if (i + 1 == raw.size()) {
    const unsigned n = (unsigned char)raw[i] << 16;
    out += table[n >> 18 & 63];
    out += table[n >> 12 & 63];
    out += "==";
  } else if (i + 2 == raw.size()) {
    const unsigned n = (unsigned char)raw[i] << 16 | (unsigned char)raw[i + 1] << 8;
    out += table[n >> 18 & 63];
    out += table[n >> 12 & 63];
    out += table[n >> 6 & 63];
    out += '=';
  }
  return out;
}

/// An XML array's binary form: a UInt32 byte count then the values, base64.
template <class T>
std::string vtuBinaryArray(const std::vector<T>& values) {
  Bytes b;
  b.put<std::uint32_t>(std::uint32_t(values.size() * sizeof(T)));
  for (T v : values) b.put<T>(v);
  return base64(b.str());
}

/// XML VTK unstructured grid of the five tetrahedra, every DataArray in the binary format.
inline std::string vtuBinary() {
  std::vector<double> xyz;
  for (const Vec3d& x : cubePoints()) xyz.insert(xyz.end(), {x[0], x[1], x[2]});
  std::vector<std::int64_t> connectivity, offsets;
  for (const auto& t : cubeTetrahedra()) {
    for (Index v : t) connectivity.push_back(v);
    offsets.push_back(std::int64_t(connectivity.size()));
  }
  const std::vector<std::uint8_t> types(5, 10);
  return "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" "
         "byte_order=\"LittleEndian\">\n<UnstructuredGrid>\n<Piece NumberOfPoints=\"8\" "
         "NumberOfCells=\"5\">\n<Points><DataArray type=\"Float64\" NumberOfComponents=\"3\" "
         "format=\"binary\">" +
         vtuBinaryArray(xyz) +
         "</DataArray></Points>\n<Cells>\n<DataArray type=\"Int64\" Name=\"connectivity\" "
         "format=\"binary\">" +
         vtuBinaryArray(connectivity) +
         "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"binary\">" +
         vtuBinaryArray(offsets) +
         "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"binary\">" +
         vtuBinaryArray(types) +
         "</DataArray>\n</Cells>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
}

/// Binary STL of the cube's 12 boundary triangles (36 corners, 8 distinct points). The header
/// starts with "solid" on purpose: the size tells it is binary.
inline std::string stlBinary() {
  const auto p = cubePoints();
  const int quads[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                           {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  Bytes b;
  std::string header = "solid cube written as binary";
  header.resize(80, ' ');
  b.text(header).put<std::uint32_t>(12);
  for (const auto& q : quads)
    for (const auto& t :
         {std::array<int, 3>{q[0], q[1], q[2]}, std::array<int, 3>{q[0], q[2], q[3]}}) {
      const Vec3d n = (p[t[1]] - p[t[0]]).cross(p[t[2]] - p[t[0]]).normalized();
      for (int k = 0; k < 3; ++k) b.put<float>(float(n[k]));
      for (int v : t)
        for (int k = 0; k < 3; ++k) b.put<float>(float(p[v][k]));
      b.put<std::uint16_t>(0);
    }
  return b.str();
}

}  // namespace stroma::test
