// SPDX-License-Identifier: MIT
// libFuzzer target: arbitrary bytes as a mesh file of each format (Gmsh, VTK legacy and XML,
// OBJ, STL) or as a sphere file (.sph). The first byte picks the format and the options, the
// rest is the file: bit 0x40 set reads a sphere file, otherwise its two low bits pick the mesh
// format. Parsing must never crash, hang, leak or trip a sanitizer; a mesh that parses must be
// consistent: every element's point indices in range, per-point data covering every point or
// none; spheres that parse have one finite center and one finite radius >= 0 each.
//
// Built by the sanitizer sub-build (tests/tooling/asan) and run by the ctest tooling_fuzz_mesh
// (tests/tooling/run_fuzzer.sh) with the seed corpus of fuzz/mesh_corpus (one file per format,
// the first byte prepended):  MeshParserFuzzer WORK_CORPUS mesh_corpus/
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

#include "formats/MeshData.h"
#include "formats/SphereData.h"

namespace {

template <class Elements>
void checkIndices(const Elements& elements, std::size_t points, const char* what) {
  for (const auto& element : elements)
    for (const auto index : element)
      if (static_cast<std::size_t>(index) >= points) {
        std::fprintf(stderr, "MeshParserFuzzer: a parsed %s names point %zu of %zu\n", what,
                     static_cast<std::size_t>(index), points);
        std::abort();
      }
}

void fail(const char* why) {
  std::fprintf(stderr, "MeshParserFuzzer: %s\n", why);
  std::abort();
}

void checkSpheres(std::string_view bytes) {
  stroma::SphereData spheres;
  std::string error;
  if (!stroma::parseSpheres(bytes, spheres, error)) {
    if (error.empty()) fail("a failed sphere parse without an error message");
    if (!spheres.centers.empty() || !spheres.radii.empty())
      fail("a failed sphere parse left spheres behind");
    return;
  }
  if (spheres.centers.empty() || spheres.radii.size() != spheres.centers.size())
    fail("parsed spheres without one radius per center");
  for (const stroma::Vec3d& c : spheres.centers)
    if (!c.allFinite()) fail("a parsed sphere center is not finite");
  for (double r : spheres.radii)
    if (!std::isfinite(r) || r < 0) fail("a parsed sphere radius is not a finite number >= 0");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::uint8_t selector = data[0];
  const std::string_view bytes(reinterpret_cast<const char*>(data + 1), size - 1);
  if (selector & 0x40) {
    checkSpheres(bytes);
    return 0;
  }
  const stroma::MeshFormat format = static_cast<stroma::MeshFormat>(selector % 4);
  stroma::MeshParseOptions options;
  options.triangulate = selector & 0x04;
  options.handleSeams = selector & 0x08;
  options.forceBinary = selector & 0x10;
  options.mergePositions = !(selector & 0x20);
  stroma::MeshData mesh;
  std::string error;
  if (!stroma::parseMesh(bytes, format, mesh, error, options)) {
    if (error.empty()) {
      std::fprintf(stderr, "MeshParserFuzzer: a failed parse without an error message\n");
      std::abort();
    }
    return 0;
  }
  const std::size_t n = mesh.positions.size();
  checkIndices(mesh.edges, n, "edge");
  checkIndices(mesh.triangles, n, "triangle");
  checkIndices(mesh.quads, n, "quad");
  checkIndices(mesh.tetrahedra, n, "tetrahedron");
  checkIndices(mesh.hexahedra, n, "hexahedron");
  if ((!mesh.normals.empty() && mesh.normals.size() != n) ||
      (!mesh.texcoords.empty() && mesh.texcoords.size() != n)) {
    std::fprintf(stderr, "MeshParserFuzzer: per-point data does not cover the points\n");
    std::abort();
  }
  return 0;
}
