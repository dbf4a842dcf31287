// SPDX-License-Identifier: MIT
#include "SparseGridTopology.h"

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "formats/MeshData.h"

namespace stroma {

using sparsegrid::GridBox;

namespace {

// Below this filled share of its cells, a grid without full cells is around an open surface.
constexpr double kOpenSurfaceShare = 0.05;

// Share of each side of the surface's bounding box added around it when the scene gives no
// box (SOFA's).
constexpr double kBoxMargin = 0.01;

std::string describeBytes(double bytes) {
  const char* units[] = {"bytes", "kB", "MB", "GB", "TB", "PB"};
  int u = 0;
  while (bytes >= 1000 && u < 5) {
    bytes /= 1000;
    ++u;
  }
  char text[64];
  std::snprintf(text, sizeof text, "%.3g %s", bytes, units[u]);
  return text;
}

std::string describe(const Vec3d& v) {
  char text[96];
  std::snprintf(text, sizeof text, "%g %g %g", v.x(), v.y(), v.z());
  return text;
}

// Half of this machine's memory: more would leave nothing to the simulation.
double memoryBudget() {
  const long pages = ::sysconf(_SC_PHYS_PAGES), pageSize = ::sysconf(_SC_PAGESIZE);
  if (pages <= 0 || pageSize <= 0) return 8e9;
  return 0.5 * double(pages) * double(pageSize);
}

void appendQuads(const std::vector<Quad>& quads, std::vector<Triangle>& triangles) {
  for (const Quad& q : quads) {
    triangles.push_back({q[0], q[1], q[2]});
    triangles.push_back({q[0], q[2], q[3]});
  }
}

}  // namespace

SparseGridTopology::SparseGridTopology() {
  m_inputs = {&d_n,
              &d_min,
              &d_max,
              &d_cellWidth,
              &d_nbVirtualFinerLevels,
              &d_fractionSamples,
              &d_fileTopology,
              &d_filename,
              &d_vertices,
              &d_inputTriangles,
              &d_inputQuads,
              &d_fileImage,
              &d_threshold,
              &d_labels,
              &d_dataResolution,
              &d_voxelSize};
  for (BaseData* input : m_inputs) addInput(input);
  for (BaseData* output : std::initializer_list<BaseData*>{&d_position, &d_edges, &d_triangles,
                                                           &d_quads, &d_tetrahedra, &d_hexahedra,
                                                           &d_cellTypes, &d_volumeFractions})
    addOutput(output);
}

void SparseGridTopology::init() {
  d_hexahedra.value();  // builds now, so that bad input is reported at init
}

void SparseGridTopology::reinit() {
  m_builtVersions.clear();  // rebuild even if no input's version moved
  setDirty();
  d_hexahedra.value();
}

const sparsegrid::SparseGrid& SparseGridTopology::grid() const {
  d_hexahedra.value();
  return m_grid;
}

void SparseGridTopology::adoptSurface() {
  if (m_adopted) return;
  m_adopted = true;
  std::string ignored;
  auto adopt = [&](auto& output, auto& input) {
    if (BaseData* parent = output.parent()) {
      if (!input.isSet()) input.setParent(parent, ignored);
      output.setParent(nullptr, ignored);
    } else if (output.isSet() && !input.isSet()) {
      input.setValue(output.value());
    }
  };
  adopt(d_position, d_vertices);
  adopt(d_triangles, d_inputTriangles);
  adopt(d_quads, d_inputQuads);
  // src="@loader" also links the loader's other elements: the grid makes its own.
  d_edges.setParent(nullptr, ignored);
  d_tetrahedra.setParent(nullptr, ignored);
  d_hexahedra.setParent(nullptr, ignored);
}

const std::vector<sparsegrid::FinerLevel>& SparseGridTopology::finerLevels() const {
  d_hexahedra.value();
  return m_finerLevels;
}

void SparseGridTopology::clearOutputs() {
  m_grid = sparsegrid::SparseGrid{};
  m_finerLevels.clear();
  d_position.setValue({});
  d_edges.setValue({});
  d_triangles.setValue({});
  d_quads.setValue({});
  d_tetrahedra.setValue({});
  d_hexahedra.setValue({});
  d_cellTypes.setValue({});
  d_volumeFractions.setValue({});
}

bool SparseGridTopology::readSurface(std::vector<Vec3d>& points, std::vector<Triangle>& triangles) {
  const bool hasFileTopology = !d_fileTopology.value().original.empty();
  const bool hasFilename = !d_filename.value().original.empty();
  if (hasFileTopology && hasFilename)
    msgWarning("both fileTopology and filename are given; filename is ignored", "filename");
  if (hasFileTopology || hasFilename) {
    const char* field = hasFileTopology ? "fileTopology" : "filename";
    const Data<FileName>& file = hasFileTopology ? d_fileTopology : d_filename;
    const std::string path = file.value().path();
    // A file name linked from a loader that could not find it: the loader said so; this is a
    // consequence, not a second problem.
    std::error_code ec;
    if (file.parent() && !std::filesystem::exists(path, ec)) {
      msgInfo("no surface: the file '" + path + "' that " + field +
                  " follows is missing (reported by its source)",
              field);
      setInvalid();
      return false;
    }
    const auto format = meshFormatFromFileName(path);
    if (!format) {
      msgError("cannot tell the format of '" + path +
                   "' from its extension: expected .obj, .stl, .vtk, .vtu, .vtp or .msh",
               field);
      return false;
    }
    MeshData mesh;
    std::string error;
    if (!readMeshFile(path, *format, mesh, error)) {
      msgError(
          "cannot read " + std::string(meshFormatName(*format)) + " file '" + path + "': " + error,
          field);
      return false;
    }
    for (const std::string& warning : mesh.warnings)
      msgWarning("file '" + path + "': " + warning, field);
    points = std::move(mesh.positions);
    triangles = std::move(mesh.triangles);
    appendQuads(mesh.quads, triangles);
    if (triangles.empty()) {
      msgError("file '" + path + "' holds no triangles or quads: a surface is needed", field);
      return false;
    }
    return true;
  }
  points = d_vertices.value();
  triangles = d_inputTriangles.value();
  appendQuads(d_inputQuads.value(), triangles);
  if (triangles.empty() || points.empty()) {
    msgError(
        "no surface to build the grid around: give fileTopology (a mesh file), or position "
        "with triangles or quads (values, links, or src=\"@loader\")",
        "fileTopology");
    return false;
  }
  return true;
}

bool SparseGridTopology::surfaceBounds(const std::vector<Vec3d>& points, Vec3d& lo, Vec3d& hi) {
  lo = d_min.value();
  hi = d_max.value();
  if (lo != hi) {
    if ((hi - lo).minCoeff() <= 0) return true;  // computeBox reports it
    // The flood starts on the box's border: a surface cut by the box loses its inside there.
    std::size_t outside = 0;
    for (const Vec3d& p : points) outside += (p - lo).minCoeff() < 0 || (hi - p).minCoeff() < 0;
    if (outside > 0)
      msgWarning(std::to_string(outside) + " of the surface's " + std::to_string(points.size()) +
                     " points are outside the box [min, max]: the grid cuts the surface, and "
                     "where the cut crosses the inside, the flood fill of the outside enters it",
                 "min");
    return true;
  }
  lo = hi = points.front();
  for (const Vec3d& p : points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const double side = (hi - lo).maxCoeff();
  if (!(side > 0) || !std::isfinite(side)) {
    msgError("the surface's points are all at one place (" + describe(lo) + "): give min and max",
             "min");
    return false;
  }
  // SOFA grows each side by 1 % of its own length; a flat side by 1 % of the largest.
  for (int a = 0; a < 3; ++a) {
    const double margin = kBoxMargin * (hi[a] > lo[a] ? hi[a] - lo[a] : side);
    lo[a] -= margin;
    hi[a] += margin;
  }
  return true;
}

bool SparseGridTopology::computeBox(Vec3d lo, Vec3d hi, const image::VolumeImage* image,
                                    GridBox& box) {
  const Vec3i n = d_n.value();
  const double width = d_cellWidth.value();
  if (width <= 0 && (n.x() < 2 || n.y() < 2 || n.z() < 2)) {
    msgError(
        "expected at least 2 grid points along each axis (n counts points, as in SOFA: "
        "n - 1 cells), got n = \"" +
            std::to_string(n.x()) + " " + std::to_string(n.y()) + " " + std::to_string(n.z()) +
            "\"",
        "n");
    return false;
  }
  // A box given in the scene (min != max) replaces the surface's or image's.
  if (d_min.value() != d_max.value()) {
    lo = d_min.value();
    hi = d_max.value();
    if ((hi - lo).minCoeff() <= 0) {
      msgError("max must be above min along each axis; got min = \"" + describe(lo) +
                   "\", max = \"" + describe(hi) + "\"",
               "max");
      return false;
    }
  }
  // Cells per axis, counted as reals first so that a huge request is refused, not wrapped.
  const int levels = d_nbVirtualFinerLevels.value();
  const double refine = std::ldexp(1.0, levels);
  std::array<double, 3> cells{};
  // cellWidth, as SOFA: n = ceil(side / cellWidth) + 1 points on the same box (cells at most
  // cellWidth wide).
  for (int a = 0; a < 3; ++a)
    cells[a] = width > 0 ? std::max(1.0, std::ceil((hi[a] - lo[a]) / width)) : double(n[a] - 1);
  const std::array<double, 3> finest{cells[0] * refine, cells[1] * refine, cells[2] * refine};
  const double bytes = image ? sparsegrid::estimateImageBuildBytes(*image, finest)
                             : sparsegrid::estimateBuildBytes(finest, d_fractionSamples.value());
  const double budget = memoryBudget();
  if (bytes > budget || finest[0] * finest[1] * finest[2] > 4e9 ||
      std::max({finest[0], finest[1], finest[2]}) > 1e9 ||
      (finest[0] + 1) * (finest[1] + 1) * (finest[2] + 1) >= double(kInvalidIndex)) {
    char size[128];
    std::snprintf(size, sizeof size, "%.0f x %.0f x %.0f", finest[0], finest[1], finest[2]);
    const char* field = levels > 0 ? "nbVirtualFinerLevels" : (width > 0 ? "cellWidth" : "n");
    msgError(std::string("a grid of ") + size + " cells" +
                 (levels > 0 ? " (" + std::to_string(levels) + " virtual finer levels)" : "") +
                 " would need about " + describeBytes(bytes) +
                 " of memory to build; the limit is half of this machine's memory (" +
                 describeBytes(budget) + ") and 4e9 cells: use fewer cells",
             field);
    return false;
  }
  for (int a = 0; a < 3; ++a) {
    box.cells[a] = int(finest[a]);
    box.spacing[a] = (hi[a] - lo[a]) / cells[a] / refine;
  }
  box.origin = lo;
  return true;
}

std::string SparseGridTopology::imageFile(const char*& field) const {
  if (!d_fileImage.value().original.empty()) {
    field = "fileImage";
    return d_fileImage.value().path();
  }
  for (const Data<FileName>* file : {&d_fileTopology, &d_filename}) {
    const std::string path = file->value().path();
    std::string ext = std::filesystem::path(path).extension().string();
    for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
    if (image::isVolumeImageFile(path) || ext == ".raw") {
      field = file == &d_fileTopology ? "fileTopology" : "filename";
      return path;
    }
  }
  return {};
}

bool SparseGridTopology::readImage(const std::string& path, const char* field,
                                   image::VolumeImage& image, std::vector<std::uint8_t>& inside) {
  std::string error;
  if (image::isVolumeImageFile(path)) {
    if (!image::readVolumeImage(path, image, error)) {
      msgError("cannot read the volume image: " + error, field);
      return false;
    }
  } else if (d_dataResolution.value().minCoeff() <= 0) {
    msgError("'" + path +
                 "' is a .raw file without a header: give dataResolution (voxels along x, y "
                 "and z, each >= 1) and voxelSize, or use a MetaImage (.mhd) or NRRD (.nrrd) "
                 "file",
             "dataResolution");
    return false;
  } else {
    const Vec3i res = d_dataResolution.value();
    const Vec3d size = d_voxelSize.value();
    if (!(size.minCoeff() > 0) || !size.allFinite()) {
      msgError("expected a voxel size > 0 along each axis, got \"" + describe(size) + "\"",
               "voxelSize");
      return false;
    }
    if (!image::readRawVoxels(path, {res.x(), res.y(), res.z()}, size, 0.5 * size, image, error)) {
      msgError("cannot read the voxels: " + error, field);
      return false;
    }
  }
  sparsegrid::VoxelSelection selection;
  selection.labels = d_labels.value();
  if (d_threshold.isSet()) selection.threshold = d_threshold.value();
  inside = sparsegrid::selectVoxels(image, selection);
  if (std::find(inside.begin(), inside.end(), std::uint8_t(1)) == inside.end()) {
    const auto [lowest, highest] = std::minmax_element(image.values.begin(), image.values.end());
    char range[96];
    std::snprintf(range, sizeof range, "%g to %g", *lowest, *highest);
    msgError("empty image: no " + selection.describe() + " in '" + path + "' (" +
                 std::to_string(image.voxelCount()) + " voxels, values from " + range + ")",
             !selection.labels.empty() ? "labels" : "threshold");
    return false;
  }
  return true;
}

void SparseGridTopology::doUpdate() {
  adoptSurface();
  // Adopting the surface re-links inputs: rebuild only when a value really changed.
  std::vector<std::uint64_t> versions;
  for (BaseData* input : m_inputs) versions.push_back(input->version());
  if (versions == m_builtVersions) return;
  m_builtVersions = versions;

  GridBox box;
  const char* imageField = nullptr;
  const std::string imagePath = imageFile(imageField);
  const bool fromFile =
      !d_fileTopology.value().original.empty() || !d_filename.value().original.empty();
  if (!imagePath.empty()) {
    // --- A volume image: the inside voxels' boxes, in the image's box ---
    if (std::string(imageField) == "fileImage" && fromFile)
      msgWarning(
          "both fileImage and a mesh file (fileTopology or filename) are given: the grid "
          "is built from the image, the mesh file is ignored",
          "fileImage");
    image::VolumeImage image;
    std::vector<std::uint8_t> inside;
    if (!readImage(imagePath, imageField, image, inside) ||
        !computeBox(image.lowerCorner(), image.upperCorner(), &image, box)) {
      clearOutputs();
      return;
    }
    std::string error;
    if (!sparsegrid::buildSparseGridFromVoxels(image, inside, box, m_grid, error)) {
      msgError(
          "'" + imagePath + "': " + error + " [min, max] = [" + describe(box.origin) + ", " +
              describe(box.origin +
                       Vec3d(box.cells[0], box.cells[1], box.cells[2]).cwiseProduct(box.spacing)) +
              "]",
          "min");
      clearOutputs();
      return;
    }
  } else {
    // --- A surface ---
    std::vector<Vec3d> points;
    std::vector<Triangle> triangles;
    Vec3d lo, hi;
    if (!readSurface(points, triangles) || !surfaceBounds(points, lo, hi) ||
        !computeBox(lo, hi, nullptr, box)) {
      clearOutputs();
      return;
    }
    std::string error;
    if (!sparsegrid::buildSparseGrid({points, triangles}, box, d_fractionSamples.value(), m_grid,
                                     error)) {
      msgError("bad surface: " + error, fromFile ? "fileTopology" : "triangles");
      clearOutputs();
      return;
    }
  }
  m_finerLevels.clear();
  // The virtual finer levels are kept, with each coarse cell's children, for the components
  // that condense from them (non-uniform elements).
  for (int level = 0; level < d_nbVirtualFinerLevels.value(); ++level) {
    m_finerLevels.push_back({std::move(m_grid), {}});
    m_grid = sparsegrid::coarsenSparseGrid(m_finerLevels.back().grid,
                                           &m_finerLevels.back().parentsChildren);
  }

  // An open surface: the flood reached every cell, and the sub-cells around the surface too.
  const double keptVolume = double(m_grid.cells.size()) * m_grid.box.spacing.prod();
  if (imagePath.empty() && m_grid.count(sparsegrid::CellType::full) == 0 &&
      m_grid.filledVolume() < kOpenSurfaceShare * keptVolume)
    msgWarning(
        "the surface encloses no volume at this resolution: it is not closed, or has a "
        "hole wider than a cell, and the flood fill of the outside reached every cell; "
        "the grid keeps only the " +
            std::to_string(m_grid.cells.size()) +
            " cells the surface crosses, almost empty (volume fractions about 0)",
        fromFile ? "fileTopology" : "triangles");

  d_position.setValue(m_grid.points);
  d_edges.setValue({});
  d_triangles.setValue({});
  d_quads.setValue({});
  d_tetrahedra.setValue({});
  d_hexahedra.setValue(m_grid.hexahedra);
  d_cellTypes.setValue(m_grid.types);
  d_volumeFractions.setValue(m_grid.fractions);
}

}  // namespace stroma
