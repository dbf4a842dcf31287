// SPDX-License-Identifier: MIT
#include "SparseGrid.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "TriangleBoxOverlap.h"

namespace stroma::sparsegrid {

namespace {

// Cells are enlarged by this share of their size in the overlap tests, so that rounding never
// opens a gap between two triangles that meet on a cell face: the boundary cells stay a wall.
constexpr double kTouchTolerance = 1e-9;

constexpr int kDirections[6][3] = {{-1, 0, 0}, {1, 0, 0},  {0, -1, 0},
                                   {0, 1, 0},  {0, 0, -1}, {0, 0, 1}};
// Corner q of a hexahedron, TopologyTypes.h order.
constexpr int kCorners[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};

// Sample points per axis in a sub-cell that the surface crosses (fractions, step 6).
constexpr int kPointsPerSubCell = 3;

// Does segment [p, q] cross triangle (a, b, c)? (Moller and Trumbore 1997; a segment in the
// triangle's plane crosses nothing.)
bool segmentCrossesTriangle(const Vec3d& p, const Vec3d& q, const Vec3d& a, const Vec3d& b,
                            const Vec3d& c) {
  const Vec3d d = q - p, e1 = b - a, e2 = c - a;
  const Vec3d pv = d.cross(e2);
  const double det = e1.dot(pv);
  if (det == 0) return false;
  const double inv = 1 / det;
  const Vec3d tv = p - a;
  const double u = tv.dot(pv) * inv;
  if (u < 0 || u > 1) return false;
  const Vec3d qv = tv.cross(e1);
  const double v = d.dot(qv) * inv;
  if (v < 0 || u + v > 1) return false;
  const double t = e2.dot(qv) * inv;
  return t >= 0 && t <= 1;
}

// Three reals in [0, 1) drawn from `key` (splitmix64, Steele et al. 2014).
Vec3d randomOffset(std::uint64_t key) {
  Vec3d offset;
  for (int a = 0; a < 3; ++a) {
    std::uint64_t z = (key += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    z ^= z >> 31;
    offset[a] = double(z >> 11) * 0x1.0p-53;
  }
  return offset;
}

// States of a cell while classifying, and of a sub-cell while measuring fractions.
constexpr std::uint8_t kUnknown = 0, kSurface = 1, kOutside = 2, kInside = 3;

// The cells [first, last] along one axis that the interval [lo, hi] touches (first > last when
// none): `count` cells of size h from `origin`.
void touchedRange(double lo, double hi, double origin, double h, int count, int& first, int& last) {
  const double a = std::floor((lo - origin) / h - kTouchTolerance);
  const double b = std::floor((hi - origin) / h + kTouchTolerance);
  first = int(std::clamp(a, 0.0, double(count)));
  last = int(std::clamp(b, -1.0, double(count - 1)));
}

struct TriangleBounds {
  Vec3d a, b, c, lo, hi;
};

TriangleBounds bounds(const Surface& surface, const Triangle& t) {
  TriangleBounds r{surface.points[t[0]], surface.points[t[1]], surface.points[t[2]], {}, {}};
  r.lo = r.a.cwiseMin(r.b).cwiseMin(r.c);
  r.hi = r.a.cwiseMax(r.b).cwiseMax(r.c);
  return r;
}

}  // namespace

double estimateBuildBytes(const std::array<double, 3>& size, int samples) {
  const double cells = size[0] * size[1] * size[2];
  const double points = (size[0] + 1) * (size[1] + 1) * (size[2] + 1);
  // Per cell: its state, its boundary index, a flood stack entry at worst; per point: its index;
  // per boundary cell (about 16 cells^(2/3) on smooth surfaces): its sub-cells.
  const double boundary = std::min(cells, 16.0 * std::cbrt(cells) * std::cbrt(cells));
  return 13.0 * cells + 4.0 * points + boundary * (double(samples) * samples * samples + 8.0);
}

bool buildSparseGrid(const Surface& surface, const GridBox& box, int samples, SparseGrid& grid,
                     std::string& error) {
  // --- Checks ---------------------------------------------------------------------------------
  for (int a = 0; a < 3; ++a) {
    if (box.cells[a] < 1) return (error = "expected at least one cell per axis"), false;
    if (!(box.spacing[a] > 0) || !std::isfinite(box.spacing[a]))
      return (error = "expected a positive cell size along each axis"), false;
  }
  if (samples < 1 || samples > 16) return (error = "expected 1 to 16 samples per axis"), false;
  if (box.pointCount() >= kInvalidIndex)
    return (error = "the grid has more than 2^32 - 1 points"), false;
  for (std::size_t p = 0; p < surface.points.size(); ++p)
    if (!surface.points[p].allFinite())
      return (error = "point " + std::to_string(p) + " has a coordinate that is not finite"), false;
  for (std::size_t t = 0; t < surface.triangles.size(); ++t)
    for (Index v : surface.triangles[t])
      if (v >= surface.points.size())
        return (error = "triangle " + std::to_string(t) + " uses point " + std::to_string(v) +
                        ", out of range of the " + std::to_string(surface.points.size()) +
                        " points"),
               false;

  const int cx = box.cells[0], cy = box.cells[1], cz = box.cells[2];
  const Vec3d& h = box.spacing;
  const std::uint64_t cellCount = box.cellCount();
  std::vector<std::uint8_t> state(cellCount, kUnknown);

  // --- 1. Boundary cells: those a triangle overlaps; remember each (cell, triangle) pair -------
  std::vector<std::pair<std::uint64_t, Index>> hits;
  const Vec3d half = 0.5 * h * (1 + kTouchTolerance);
  for (std::size_t t = 0; t < surface.triangles.size(); ++t) {
    const TriangleBounds tb = bounds(surface, surface.triangles[t]);
    int first[3], last[3];
    for (int a = 0; a < 3; ++a)
      touchedRange(tb.lo[a], tb.hi[a], box.origin[a], h[a], box.cells[a], first[a], last[a]);
    for (int k = first[2]; k <= last[2]; ++k)
      for (int j = first[1]; j <= last[1]; ++j)
        for (int i = first[0]; i <= last[0]; ++i) {
          const Vec3d centre = box.origin + Vec3d(i + 0.5, j + 0.5, k + 0.5).cwiseProduct(h);
          if (!triangleOverlapsBox(centre, half, tb.a, tb.b, tb.c)) continue;
          const std::uint64_t cell = box.cellIndex(i, j, k);
          state[cell] = kSurface;
          hits.emplace_back(cell, Index(t));
        }
  }

  // --- 2. Flood fill of the outside from the border, through the faces of non-boundary cells --
  std::vector<std::uint64_t> stack;
  auto reach = [&](std::uint64_t cell) {
    if (state[cell] != kUnknown) return;
    state[cell] = kOutside;
    stack.push_back(cell);
  };
  for (int k = 0; k < cz; ++k)
    for (int j = 0; j < cy; ++j) {
      reach(box.cellIndex(0, j, k));
      reach(box.cellIndex(cx - 1, j, k));
    }
  for (int k = 0; k < cz; ++k)
    for (int i = 0; i < cx; ++i) {
      reach(box.cellIndex(i, 0, k));
      reach(box.cellIndex(i, cy - 1, k));
    }
  for (int j = 0; j < cy; ++j)
    for (int i = 0; i < cx; ++i) {
      reach(box.cellIndex(i, j, 0));
      reach(box.cellIndex(i, j, cz - 1));
    }
  while (!stack.empty()) {
    const std::uint64_t cell = stack.back();
    stack.pop_back();
    const auto c = box.cellCoordinates(cell);
    for (const auto& d : kDirections) {
      const int i = c[0] + d[0], j = c[1] + d[1], k = c[2] + d[2];
      if (i < 0 || j < 0 || k < 0 || i >= cx || j >= cy || k >= cz) continue;
      reach(box.cellIndex(i, j, k));
    }
  }
  // --- 3. What the flood did not reach is enclosed: full ----------------------------------------
  std::vector<std::uint64_t> boundaryCells;
  std::vector<Index> boundaryIndex(cellCount, kInvalidIndex);
  for (std::uint64_t cell = 0; cell < cellCount; ++cell) {
    if (state[cell] == kUnknown) state[cell] = kInside;
    if (state[cell] == kSurface) {
      boundaryIndex[cell] = Index(boundaryCells.size());
      boundaryCells.push_back(cell);
    }
  }

  // --- 4. Fractions: the sub-cells of the boundary cells overlapping the surface ---------------
  const int s = samples, s3 = s * s * s;
  std::vector<std::uint8_t> sub(boundaryCells.size() * std::size_t(s3), kUnknown);
  const Vec3d hs = h / s;
  const Vec3d subHalf = 0.5 * hs * (1 + kTouchTolerance);
  // Remember each (sub-cell, triangle) pair: the triangles that can cross a segment inside it.
  std::vector<std::pair<std::uint64_t, Index>> subHits;
  for (const auto& [cell, t] : hits) {
    const std::size_t b = boundaryIndex[cell];
    const auto c = box.cellCoordinates(cell);
    const Vec3d corner = box.origin + Vec3d(c[0], c[1], c[2]).cwiseProduct(h);
    const TriangleBounds tb = bounds(surface, surface.triangles[t]);
    int first[3], last[3];
    for (int a = 0; a < 3; ++a)
      touchedRange(tb.lo[a], tb.hi[a], corner[a], hs[a], s, first[a], last[a]);
    for (int k = first[2]; k <= last[2]; ++k)
      for (int j = first[1]; j <= last[1]; ++j)
        for (int i = first[0]; i <= last[0]; ++i) {
          const Vec3d centre = corner + Vec3d(i + 0.5, j + 0.5, k + 0.5).cwiseProduct(hs);
          if (!triangleOverlapsBox(centre, subHalf, tb.a, tb.b, tb.c)) continue;
          const std::uint64_t at = b * s3 + i + s * (j + s * k);
          sub[at] = kSurface;
          subHits.emplace_back(at, t);
        }
  }
  std::sort(subHits.begin(), subHits.end());

  // The neighbour of sub-cell (b, l) in direction d: a sub-cell (state pointer) or the state of a
  // whole cell (outside the box counts as outside).
  struct Neighbour {
    std::uint8_t* sub = nullptr;  // set when the neighbour is a sub-cell of a boundary cell
    std::uint8_t cellState = kOutside;
  };
  auto neighbour = [&](std::size_t b, int l, const int* d) {
    int a[3] = {l % s, (l / s) % s, l / (s * s)};
    const auto c = box.cellCoordinates(boundaryCells[b]);
    int cell[3] = {c[0], c[1], c[2]};
    for (int axis = 0; axis < 3; ++axis) {
      a[axis] += d[axis];
      if (a[axis] < 0) {
        a[axis] += s;
        --cell[axis];
      } else if (a[axis] >= s) {
        a[axis] -= s;
        ++cell[axis];
      }
    }
    Neighbour n;
    if (cell[0] < 0 || cell[1] < 0 || cell[2] < 0 || cell[0] >= cx || cell[1] >= cy ||
        cell[2] >= cz)
      return n;
    const std::uint64_t index = box.cellIndex(cell[0], cell[1], cell[2]);
    n.cellState = state[index];
    if (n.cellState == kSurface)
      n.sub = &sub[std::size_t(boundaryIndex[index]) * s3 + a[0] + s * (a[1] + s * a[2])];
    return n;
  };

  // --- 5. Flood of the sub-cells, from those facing an empty cell or the border of the box ----
  std::vector<std::uint64_t> subStack;
  for (std::size_t b = 0; b < boundaryCells.size(); ++b)
    for (int l = 0; l < s3; ++l) {
      std::uint8_t& st = sub[b * s3 + l];
      if (st != kUnknown) continue;
      for (const auto& d : kDirections) {
        const Neighbour n = neighbour(b, l, d);
        if (!n.sub && n.cellState == kOutside) {
          st = kOutside;
          subStack.push_back(b * s3 + l);
          break;
        }
      }
    }
  while (!subStack.empty()) {
    const std::uint64_t at = subStack.back();
    subStack.pop_back();
    const std::size_t b = at / s3;
    const int l = int(at % s3);
    for (const auto& d : kDirections) {
      const Neighbour n = neighbour(b, l, d);
      if (n.sub && *n.sub == kUnknown) {
        *n.sub = kOutside;
        subStack.push_back(std::uint64_t(n.sub - sub.data()));
      }
    }
  }

  // --- 6. Fraction of each boundary cell: its inside sub-cells, and the inside share of the
  // sample points of its surface sub-cells. A sample point takes the state of a neighbour
  // sub-cell of known state (not on the surface) that the segment to its centre reaches without
  // crossing the sub-cell's triangles; when every such segment crosses the surface, the parity of
  // the crossings to the first neighbour flips its state or not. Only the sub-cell's triangles
  // can cross these segments: a neighbour off the surface touches none. Preferring the
  // unobstructed neighbour keeps walls inside the volume filled and sheets outside it empty
  // (non-manifold and open surfaces), where parity alone would fill half their sub-cells.
  std::vector<double> boundaryFraction(boundaryCells.size());
  constexpr int m = kPointsPerSubCell;
  std::size_t nextHit = 0;
  for (std::size_t b = 0; b < boundaryCells.size(); ++b) {
    const auto c = box.cellCoordinates(boundaryCells[b]);
    const Vec3d corner = box.origin + Vec3d(c[0], c[1], c[2]).cwiseProduct(h);
    double filled = 0;
    for (int l = 0; l < s3; ++l) {
      const std::uint64_t at = b * s3 + l;
      const std::uint8_t st = sub[at];
      if (st == kUnknown) {
        filled += 1;
        continue;
      }
      if (st != kSurface) continue;
      // This sub-cell's triangles (subHits is sorted like the sub-cells).
      while (nextHit < subHits.size() && subHits[nextHit].first < at) ++nextHit;
      std::size_t end = nextHit;
      while (end < subHits.size() && subHits[end].first == at) ++end;
      // The neighbours of known state: reference points and their states.
      const Vec3d lo = corner + Vec3d(l % s, (l / s) % s, l / (s * s)).cwiseProduct(hs);
      Vec3d references[6];
      bool referenceInside[6];
      int count = 0;
      for (const auto& d : kDirections) {
        const Neighbour n = neighbour(b, l, d);
        std::uint8_t other = n.sub ? *n.sub : n.cellState;
        if (n.sub && other == kUnknown) other = kInside;
        if (other == kSurface) continue;
        references[count] = lo + (Vec3d(d[0], d[1], d[2]) + Vec3d::Constant(0.5)).cwiseProduct(hs);
        referenceInside[count++] = other == kInside;
      }
      if (count == 0) {
        filled += 0.5;  // surrounded by the surface: nothing to compare with
        continue;
      }
      // Stratified sampling: one point per cell of an m x m x m split of the sub-cell, at the
      // same pseudo-random offset in each (drawn from the sub-cell's place, so deterministic).
      // The estimate is unbiased: a plane parallel to the grid no longer makes the same error in
      // every sub-cell it crosses.
      const Vec3d offset = randomOffset(boundaryCells[b] * s3 + l);
      int inside = 0;
      for (int pk = 0; pk < m; ++pk)
        for (int pj = 0; pj < m; ++pj)
          for (int pi = 0; pi < m; ++pi) {
            const Vec3d p = lo + (Vec3d(pi, pj, pk) + offset).cwiseProduct(hs) / m;
            // The first reference reached without crossing the surface decides; without
            // one, the parity of the crossings to the first reference does.
            int verdict = -1;
            bool parityVerdict = false;
            for (int r = 0; r < count && verdict < 0; ++r) {
              int crossings = 0;
              for (std::size_t e = nextHit; e < end; ++e) {
                const Triangle& t = surface.triangles[subHits[e].second];
                crossings += segmentCrossesTriangle(p, references[r], surface.points[t[0]],
                                                    surface.points[t[1]], surface.points[t[2]]);
              }
              if (crossings == 0) verdict = referenceInside[r];
              if (r == 0) parityVerdict = referenceInside[0] != (crossings % 2 == 1);
            }
            inside += verdict < 0 ? parityVerdict : verdict;
          }
      filled += double(inside) / (m * m * m);
    }
    boundaryFraction[b] = filled / s3;
  }

  // --- 7. Keep the boundary cells, then the full ones (SOFA's order) ---------------------------
  grid = SparseGrid{};
  grid.box = box;
  for (const std::uint8_t kept : {kSurface, kInside})
    for (std::uint64_t cell = 0; cell < cellCount; ++cell) {
      if (state[cell] != kept) continue;
      grid.cells.push_back(cell);
      const bool onSurface = kept == kSurface;
      grid.types.push_back(onSurface ? CellType::boundary : CellType::full);
      grid.fractions.push_back(onSurface ? boundaryFraction[boundaryIndex[cell]] : 1.0);
    }
  makeGridElements(grid);
  return true;
}

void makeGridElements(SparseGrid& grid) {
  const GridBox& box = grid.box;
  const std::uint64_t px = box.cells[0] + 1, py = box.cells[1] + 1;
  auto pointIndex = [&](const std::array<int, 3>& c, const int* q) {
    return (c[0] + q[0]) + px * ((c[1] + q[1]) + py * std::uint64_t(c[2] + q[2]));
  };
  // Mark the corners of the kept cells, then number them by increasing (x, y, z): x slowest,
  // z fastest, as SOFA's map from corner positions to indices does.
  std::vector<Index> id(box.pointCount(), kInvalidIndex);
  for (std::uint64_t cell : grid.cells) {
    const auto c = box.cellCoordinates(cell);
    for (const auto& q : kCorners) id[pointIndex(c, q)] = 0;
  }
  grid.points.clear();
  const int pz = box.cells[2] + 1;
  for (int i = 0; i < int(px); ++i)
    for (int j = 0; j < int(py); ++j)
      for (int k = 0; k < pz; ++k) {
        Index& p = id[i + px * (j + py * std::uint64_t(k))];
        if (p == kInvalidIndex) continue;
        p = Index(grid.points.size());
        grid.points.push_back(box.origin + Vec3d(i, j, k).cwiseProduct(box.spacing));
      }
  grid.hexahedra.resize(grid.cells.size());
  for (std::size_t e = 0; e < grid.cells.size(); ++e) {
    const auto c = box.cellCoordinates(grid.cells[e]);
    for (int q = 0; q < 8; ++q) grid.hexahedra[e][q] = id[pointIndex(c, kCorners[q])];
  }
}

SparseGrid coarsenSparseGrid(const SparseGrid& fine, std::vector<std::array<Index, 8>>* children) {
  SparseGrid coarse;
  for (int a = 0; a < 3; ++a) coarse.box.cells[a] = (fine.box.cells[a] + 1) / 2;
  coarse.box.origin = fine.box.origin;
  coarse.box.spacing = 2 * fine.box.spacing;

  // Each fine cell's parent and its corner in the parent, sorted by parent.
  std::vector<std::pair<std::uint64_t, Index>> byParent(fine.cells.size());
  std::vector<std::uint8_t> corner(fine.cells.size());
  for (std::size_t f = 0; f < fine.cells.size(); ++f) {
    const auto c = fine.box.cellCoordinates(fine.cells[f]);
    // Sorted as SOFA orders a coarser level: x slowest, z fastest.
    const std::uint64_t pi = c[0] / 2, pj = c[1] / 2, pk = c[2] / 2;
    byParent[f] = {pk + std::uint64_t(coarse.box.cells[2]) * (pj + coarse.box.cells[1] * pi),
                   Index(f)};
    const int dx = c[0] % 2, dy = c[1] % 2, dz = c[2] % 2;
    // kCorners order: (0,0) 0, (1,0) 1, (1,1) 2, (0,1) 3 in x, y; +4 at z = 1.
    corner[f] = std::uint8_t((dy ? (dx ? 2 : 3) : dx) + 4 * dz);
  }
  std::sort(byParent.begin(), byParent.end());

  if (children) children->clear();
  for (std::size_t g = 0; g < byParent.size();) {
    const std::uint64_t key = byParent[g].first;
    std::array<Index, 8> kids;
    kids.fill(kInvalidIndex);
    int fullChildren = 0;
    double fraction = 0;
    for (; g < byParent.size() && byParent[g].first == key; ++g) {
      const Index f = byParent[g].second;
      kids[corner[f]] = f;
      fullChildren += fine.types[f] == CellType::full;
      fraction += fine.fractions[f];
    }
    const auto c = fine.box.cellCoordinates(fine.cells[byParent[g - 1].second]);
    coarse.cells.push_back(coarse.box.cellIndex(c[0] / 2, c[1] / 2, c[2] / 2));
    coarse.types.push_back(fullChildren == 8 ? CellType::full : CellType::boundary);
    coarse.fractions.push_back(fraction / 8);
    if (children) children->push_back(kids);
  }
  makeGridElements(coarse);
  return coarse;
}

}  // namespace stroma::sparsegrid
