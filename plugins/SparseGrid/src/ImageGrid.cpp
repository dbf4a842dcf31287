// SPDX-License-Identifier: MIT
#include "ImageGrid.h"

#include <algorithm>
#include <cmath>

#include "SparseGrid.h"
#include "core/Message.h"

namespace stroma::sparsegrid {
namespace {

// Overlaps shorter than this share of the smaller of the voxel and cell sizes are rounding
// slivers (a grid aligned with the voxels), not geometry.
constexpr double kSliver = 1e-9;

/// Along one axis: the cells each voxel overlaps and the overlap lengths (compressed rows:
/// voxel v has pieces[start[v]] to pieces[start[v + 1] - 1]).
struct AxisOverlaps {
  struct Piece {
    int cell;
    double length;
  };
  std::vector<std::size_t> start;
  std::vector<Piece> pieces;
  std::vector<char> covered;  ///< per cell: the cell lies within the image along this axis
};

AxisOverlaps overlapAxis(int voxels, double voxelLo, double voxelSize, int cells, double cellLo,
                         double cellSize) {
  AxisOverlaps o;
  o.start.reserve(std::size_t(voxels) + 1);
  const double sliver = kSliver * std::min(voxelSize, cellSize);
  std::vector<AxisOverlaps::Piece> mine;
  for (int v = 0; v < voxels; ++v) {
    o.start.push_back(o.pieces.size());
    const double lo = voxelLo + v * voxelSize, hi = lo + voxelSize;
    // Clamped as reals first: a voxel far outside the box must not overflow an int.
    const int first = int(std::clamp(std::floor((lo - cellLo) / cellSize), 0.0, double(cells)));
    const int last = int(std::clamp(std::floor((hi - cellLo) / cellSize), -1.0, double(cells - 1)));
    mine.clear();
    double lost = 0;  // sliver length waiting for a neighbouring piece of this voxel
    for (int c = first; c <= last; ++c) {
      const double cLo = cellLo + c * cellSize, cHi = cLo + cellSize;
      const double length = std::min(hi, cHi) - std::max(lo, cLo);
      if (length <= 0) continue;
      if (length <= sliver) {
        if (!mine.empty())
          mine.back().length += length;
        else
          lost += length;
        continue;
      }
      mine.push_back({c, length + lost});
      lost = 0;
    }
    o.pieces.insert(o.pieces.end(), mine.begin(), mine.end());
  }
  o.start.push_back(o.pieces.size());
  const double imageLo = voxelLo, imageHi = voxelLo + voxels * voxelSize;
  const double tolerance = kSliver * std::min(voxelSize, cellSize);
  o.covered.resize(std::size_t(cells));
  for (int c = 0; c < cells; ++c)
    o.covered[std::size_t(c)] = cellLo + c * cellSize >= imageLo - tolerance &&
                                cellLo + (c + 1) * cellSize <= imageHi + tolerance;
  return o;
}

}  // namespace

bool VoxelSelection::inside(double value) const {
  if (!labels.empty()) return std::find(labels.begin(), labels.end(), value) != labels.end();
  if (threshold) return value >= *threshold;
  return value > 0;
}

std::string VoxelSelection::describe() const {
  if (!labels.empty()) {
    std::string text = labels.size() == 1 ? "voxel with label " : "voxel with a label among ";
    for (std::size_t n = 0; n < labels.size(); ++n) {
      if (n > 0) text += ' ';
      text += formatNumber(labels[n]);
    }
    return text;
  }
  if (threshold) return "voxel >= " + formatNumber(*threshold) + " (threshold)";
  return "voxel > 0 (no threshold given)";
}

std::vector<std::uint8_t> selectVoxels(const image::VolumeImage& image,
                                       const VoxelSelection& selection) {
  std::vector<std::uint8_t> inside(image.values.size());
  for (std::size_t v = 0; v < inside.size(); ++v)
    inside[v] = selection.inside(image.values[v]) ? 1 : 0;
  return inside;
}

double estimateImageBuildBytes(const image::VolumeImage& image,
                               const std::array<double, 3>& cells) {
  const double nx = image.size[0], ny = image.size[1], nz = image.size[2];
  // Two arrays of doubles (inside and outside volume) after each axis pass, two passes alive
  // at once; the flags; the kept grid (as estimateBuildBytes counts it, without sub-cells).
  const double afterX = cells[0] * ny * nz, afterY = cells[0] * cells[1] * nz,
               afterZ = cells[0] * cells[1] * cells[2];
  return 16.0 * std::max(afterX + afterY, afterY + afterZ) + nx * ny * nz +
         estimateBuildBytes(cells, 1);
}

bool buildSparseGridFromVoxels(const image::VolumeImage& image,
                               const std::vector<std::uint8_t>& inside, const GridBox& box,
                               SparseGrid& grid, std::string& error) {
  // --- Checks ---------------------------------------------------------------------------------
  for (int a = 0; a < 3; ++a) {
    if (box.cells[a] < 1) return (error = "expected at least one cell per axis"), false;
    if (!(box.spacing[a] > 0) || !std::isfinite(box.spacing[a]))
      return (error = "expected a positive cell size along each axis"), false;
    if (image.size[a] < 1 || !(image.spacing[a] > 0))
      return (error = "the image has no voxels or a voxel size <= 0"), false;
  }
  if (inside.size() != image.voxelCount())
    return (error = "expected one inside flag per voxel"), false;

  // --- 1. Interval overlaps along each axis ---------------------------------------------------
  const Vec3d lower = image.lowerCorner();
  std::array<AxisOverlaps, 3> w;
  for (int a = 0; a < 3; ++a)
    w[a] = overlapAxis(image.size[a], lower[a], image.spacing[a], box.cells[a], box.origin[a],
                       box.spacing[a]);

  // --- 2. Inside and outside volumes per cell, one axis at a time ------------------------------
  // After the x pass, index c + cx (j + ny k); after y, c + cx (cj + cy k); after z, the cell.
  const std::size_t nx = std::size_t(image.size[0]), ny = std::size_t(image.size[1]),
                    nz = std::size_t(image.size[2]);
  const std::size_t cx = std::size_t(box.cells[0]), cy = std::size_t(box.cells[1]),
                    cz = std::size_t(box.cells[2]);
  std::vector<double> inX(cx * ny * nz, 0.0), outX(cx * ny * nz, 0.0);
  for (std::size_t k = 0; k < nz; ++k)
    for (std::size_t j = 0; j < ny; ++j) {
      const std::size_t row = nx * (j + ny * k), to = cx * (j + ny * k);
      for (std::size_t i = 0; i < nx; ++i) {
        std::vector<double>& target = inside[row + i] ? inX : outX;
        for (std::size_t p = w[0].start[i]; p < w[0].start[i + 1]; ++p)
          target[to + std::size_t(w[0].pieces[p].cell)] += w[0].pieces[p].length;
      }
    }
  std::vector<double> inY(cx * cy * nz, 0.0), outY(cx * cy * nz, 0.0);
  for (std::size_t k = 0; k < nz; ++k)
    for (std::size_t j = 0; j < ny; ++j) {
      const std::size_t from = cx * (j + ny * k);
      for (std::size_t p = w[1].start[j]; p < w[1].start[j + 1]; ++p) {
        const std::size_t to = cx * (std::size_t(w[1].pieces[p].cell) + cy * k);
        const double length = w[1].pieces[p].length;
        for (std::size_t c = 0; c < cx; ++c) {
          inY[to + c] += length * inX[from + c];
          outY[to + c] += length * outX[from + c];
        }
      }
    }
  inX = {};
  outX = {};
  std::vector<double> in(cx * cy * cz, 0.0), out(cx * cy * cz, 0.0);
  for (std::size_t k = 0; k < nz; ++k) {
    const std::size_t from = cx * cy * k;
    for (std::size_t p = w[2].start[k]; p < w[2].start[k + 1]; ++p) {
      const std::size_t to = cx * cy * std::size_t(w[2].pieces[p].cell);
      const double length = w[2].pieces[p].length;
      for (std::size_t c = 0; c < cx * cy; ++c) {
        in[to + c] += length * inY[from + c];
        out[to + c] += length * outY[from + c];
      }
    }
  }

  // --- 3. Types and fractions; boundary cells, then full ones (SOFA's order) -------------------
  const double cellVolume = box.spacing.prod();
  const auto isFull = [&](std::uint64_t cell) {
    const auto c = box.cellCoordinates(cell);
    return out[cell] == 0 && w[0].covered[std::size_t(c[0])] && w[1].covered[std::size_t(c[1])] &&
           w[2].covered[std::size_t(c[2])];
  };
  grid = SparseGrid{};
  grid.box = box;
  for (const CellType kept : {CellType::boundary, CellType::full})
    for (std::uint64_t cell = 0; cell < box.cellCount(); ++cell) {
      if (!(in[cell] > 0)) continue;
      const CellType type = isFull(cell) ? CellType::full : CellType::boundary;
      if (type != kept) continue;
      grid.cells.push_back(cell);
      grid.types.push_back(type);
      grid.fractions.push_back(
          type == CellType::full ? 1.0 : std::clamp(in[cell] / cellVolume, 0.0, 1.0));
    }
  if (grid.cells.empty()) {
    error = "no inside voxel overlaps the grid's box";
    return false;
  }
  makeGridElements(grid);
  return true;
}

}  // namespace stroma::sparsegrid
