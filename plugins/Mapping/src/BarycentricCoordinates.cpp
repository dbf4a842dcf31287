// SPDX-License-Identifier: MIT
#include "BarycentricCoordinates.h"

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>

namespace stroma::barycentric {

namespace {

constexpr double kInsideTolerance = 1e-10;
constexpr double kInfinity = std::numeric_limits<double>::infinity();

// Local corner (u_i, v_i, w_i) of hexahedron vertex i.
constexpr int kCorner[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                               {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};

// Linear factor of corner coordinate c at t, and its derivative.
double factor(int c, double t) { return c ? t : 1 - t; }
double dfactor(int c) { return c ? 1.0 : -1.0; }

Vec3d hexahedronPoint(const std::array<Vec3d, 8>& x, const Vec3d& uvw) {
  const std::array<double, 8> n = hexahedronWeights(uvw);
  Vec3d p = Vec3d::Zero();
  for (int i = 0; i < 8; ++i) p += n[i] * x[i];
  return p;
}

// The local coordinates and weights of p in one element, and how far outside it p is.
struct Candidate {
  std::array<double, 8> weights{};
  int count = 0;
  bool valid = false;  // the coordinates could be computed
  bool inside = false;
  double distance = kInfinity;  // 0 inside; else to the element's point at clamped coordinates
};

// The point of triangle (a, b, c) nearest to p: the vertex, edge or interior whose Voronoi
// region holds p (Ericson, Real-Time Collision Detection, 2005, section 5.1.5).
Vec3d nearestOnTriangle(const Vec3d& p, const Vec3d& a, const Vec3d& b, const Vec3d& c) {
  const Vec3d ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const Vec3d bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + (d1 / (d1 - d3)) * ab;
  const Vec3d cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + (d2 / (d2 - d6)) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
    return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);
  const double denominator = 1 / (va + vb + vc);
  return a + ab * (vb * denominator) + ac * (vc * denominator);
}

Candidate inTetrahedron(const std::array<Vec3d, 4>& x, const Vec3d& p) {
  Candidate c;
  std::array<double, 4> w;
  c.count = 4;
  if (!tetrahedronWeights(x, p, w)) return c;
  c.valid = true;
  std::copy(w.begin(), w.end(), c.weights.begin());
  c.inside = *std::min_element(w.begin(), w.end()) >= -kInsideTolerance;
  if (c.inside) {
    c.distance = 0;
    return c;
  }
  // Outside, the nearest point of the tetrahedron is on one of its faces.
  constexpr int kFaces[4][3] = {{1, 2, 3}, {0, 2, 3}, {0, 1, 3}, {0, 1, 2}};
  for (const auto& f : kFaces)
    c.distance = std::min(c.distance, (p - nearestOnTriangle(p, x[f[0]], x[f[1]], x[f[2]])).norm());
  return c;
}

Candidate inHexahedron(const std::array<Vec3d, 8>& x, const Vec3d& p) {
  Candidate c;
  c.count = 8;
  Vec3d uvw;
  if (!hexahedronCoordinates(x, p, uvw)) return c;
  c.valid = true;
  c.weights = hexahedronWeights(uvw);
  c.inside = uvw.minCoeff() >= -kInsideTolerance && uvw.maxCoeff() <= 1 + kInsideTolerance;
  c.distance = c.inside ? 0.0 : (p - hexahedronPoint(x, uvw.cwiseMax(0.0).cwiseMin(1.0))).norm();
  return c;
}

// A uniform grid over the nodes' bounding box; each cell lists the elements whose bounding box
// overlaps it (compressed rows).
class ElementGrid {
 public:
  void build(const std::vector<Eigen::AlignedBox3d>& boxes, const Eigen::AlignedBox3d& all) {
    m_box = all;
    const Vec3d size = all.sizes().cwiseMax(1e-300);
    // About one element per cell: n cells of volume V / n.
    const double n = std::max<double>(1.0, static_cast<double>(boxes.size()));
    const double side = std::cbrt(size.prod() / n);
    for (int a = 0; a < 3; ++a) {
      const double cells = side > 0 ? std::ceil(size[a] / side) : 1.0;
      m_dims[a] = static_cast<int>(std::clamp(cells, 1.0, 256.0));
      m_cell[a] = size[a] / m_dims[a];
    }
    const std::size_t cellCount = static_cast<std::size_t>(m_dims.prod());
    m_start.assign(cellCount + 1, 0);
    auto forCells = [&](const Eigen::AlignedBox3d& b, auto&& f) {
      const Eigen::Vector3i lo = cellOf(b.min()), hi = cellOf(b.max());
      for (int k = lo.z(); k <= hi.z(); ++k)
        for (int j = lo.y(); j <= hi.y(); ++j)
          for (int i = lo.x(); i <= hi.x(); ++i) f(index(Eigen::Vector3i(i, j, k)));
    };
    for (const auto& b : boxes) forCells(b, [&](std::size_t c) { ++m_start[c + 1]; });
    for (std::size_t c = 0; c < cellCount; ++c) m_start[c + 1] += m_start[c];
    m_items.resize(m_start.back());
    std::vector<std::size_t> fill(m_start.begin(), m_start.end() - 1);
    for (std::size_t e = 0; e < boxes.size(); ++e)
      forCells(boxes[e], [&](std::size_t c) { m_items[fill[c]++] = static_cast<Index>(e); });
  }

  /// The cell holding p (p clamped into the grid).
  Eigen::Vector3i cellOf(const Vec3d& p) const {
    Eigen::Vector3i c;
    for (int a = 0; a < 3; ++a) {
      const double t = (p[a] - m_box.min()[a]) / m_cell[a];
      c[a] = std::clamp(static_cast<int>(std::floor(t)), 0, m_dims[a] - 1);
    }
    return c;
  }
  bool contains(const Vec3d& p) const { return m_box.contains(p); }
  std::size_t index(const Eigen::Vector3i& c) const {
    return static_cast<std::size_t>(c.x() + m_dims.x() * (c.y() + m_dims.y() * c.z()));
  }
  const Index* begin(std::size_t cell) const { return m_items.data() + m_start[cell]; }
  const Index* end(std::size_t cell) const { return m_items.data() + m_start[cell + 1]; }
  const Eigen::Vector3i& dims() const { return m_dims; }

  /// A lower bound of the distance from p to the cells of the grid outside the block of cells
  /// within r of `centre` (infinity when the block covers the grid): the nearest of the slabs
  /// beyond each of the block's faces.
  double distanceBeyond(const Vec3d& p, const Eigen::Vector3i& centre, int r) const {
    const Vec3d gap = (m_box.min() - p).cwiseMax(p - m_box.max()).cwiseMax(0.0);
    double nearest = kInfinity;
    for (int a = 0; a < 3; ++a) {
      const double others = gap.squaredNorm() - gap[a] * gap[a];
      auto slab = [&](double from, double to) {
        const double d = std::max({from - p[a], p[a] - to, 0.0});
        nearest = std::min(nearest, std::sqrt(others + d * d));
      };
      if (centre[a] - r > 0) slab(m_box.min()[a], m_box.min()[a] + (centre[a] - r) * m_cell[a]);
      if (centre[a] + r < m_dims[a] - 1)
        slab(m_box.min()[a] + (centre[a] + r + 1) * m_cell[a], m_box.max()[a]);
    }
    return nearest;
  }

 private:
  Eigen::AlignedBox3d m_box;
  Eigen::Vector3i m_dims = Eigen::Vector3i::Ones();
  Vec3d m_cell = Vec3d::Ones();
  std::vector<std::size_t> m_start;
  std::vector<Index> m_items;
};

}  // namespace

bool tetrahedronWeights(const std::array<Vec3d, 4>& x, const Vec3d& p, std::array<double, 4>& w) {
  Mat3d edges;
  edges << x[1] - x[0], x[2] - x[0], x[3] - x[0];
  const double scale = std::max({edges.col(0).norm(), edges.col(1).norm(), edges.col(2).norm()});
  const double det = edges.determinant();
  if (!(std::abs(det) > 1e-12 * scale * scale * scale)) return false;
  const Vec3d l = edges.inverse() * (p - x[0]);
  w = {1 - l.sum(), l[0], l[1], l[2]};
  return true;
}

std::array<double, 8> hexahedronWeights(const Vec3d& uvw) {
  std::array<double, 8> n;
  for (int i = 0; i < 8; ++i)
    n[i] = factor(kCorner[i][0], uvw[0]) * factor(kCorner[i][1], uvw[1]) *
           factor(kCorner[i][2], uvw[2]);
  return n;
}

bool hexahedronCoordinates(const std::array<Vec3d, 8>& x, const Vec3d& p, Vec3d& uvw) {
  double scale = 0;
  for (int i = 1; i < 8; ++i) scale = std::max(scale, (x[i] - x[0]).norm());
  if (!(scale > 0)) return false;
  uvw = Vec3d::Constant(0.5);
  // Newton's method on X(u, v, w) = p; the Jacobian's columns are dX/du, dX/dv, dX/dw.
  for (int iteration = 0; iteration < 30; ++iteration) {
    Vec3d residual = -p;
    Mat3d J = Mat3d::Zero();
    for (int i = 0; i < 8; ++i) {
      const int* c = kCorner[i];
      const double fu = factor(c[0], uvw[0]), fv = factor(c[1], uvw[1]), fw = factor(c[2], uvw[2]);
      residual += fu * fv * fw * x[i];
      J.col(0) += dfactor(c[0]) * fv * fw * x[i];
      J.col(1) += fu * dfactor(c[1]) * fw * x[i];
      J.col(2) += fu * fv * dfactor(c[2]) * x[i];
    }
    if (!(std::abs(J.determinant()) > 1e-12 * scale * scale * scale)) return false;
    const Vec3d step = J.inverse() * residual;
    uvw -= step;
    if (!uvw.allFinite() || uvw.cwiseAbs().maxCoeff() > 1e6) return false;
    if (step.cwiseAbs().maxCoeff() < 1e-14 * std::max(1.0, uvw.cwiseAbs().maxCoeff())) return true;
  }
  // No convergence to round-off: accept when the residual is small.
  return (hexahedronPoint(x, uvw) - p).norm() < 1e-10 * scale;
}

std::vector<EmbeddedPoint> embedPoints(const std::vector<Vec3d>& nodes,
                                       const std::vector<Tetrahedron>& tetrahedra,
                                       const std::vector<Hexahedron>& hexahedra,
                                       const std::vector<Vec3d>& points,
                                       std::vector<Index>* degenerate) {
  const std::size_t nTetra = tetrahedra.size(), nElements = nTetra + hexahedra.size();
  std::vector<EmbeddedPoint> result(points.size());
  if (nElements == 0) return result;

  // Bounding boxes of the elements and of the whole mesh.
  std::vector<Eigen::AlignedBox3d> boxes(nElements);
  Eigen::AlignedBox3d all;
  for (std::size_t e = 0; e < nElements; ++e) {
    if (e < nTetra)
      for (Index n : tetrahedra[e]) boxes[e].extend(nodes[n]);
    else
      for (Index n : hexahedra[e - nTetra]) boxes[e].extend(nodes[n]);
    all.extend(boxes[e]);
  }
  ElementGrid grid;
  grid.build(boxes, all);

  auto evaluate = [&](std::size_t e, const Vec3d& p) {
    if (e < nTetra) {
      const Tetrahedron& t = tetrahedra[e];
      return inTetrahedron({nodes[t[0]], nodes[t[1]], nodes[t[2]], nodes[t[3]]}, p);
    }
    const Hexahedron& h = hexahedra[e - nTetra];
    std::array<Vec3d, 8> x;
    for (int i = 0; i < 8; ++i) x[i] = nodes[h[i]];
    return inHexahedron(x, p);
  };
  auto store = [&](EmbeddedPoint& out, std::size_t e, const Candidate& c) {
    out.element = static_cast<Index>(e);
    out.count = c.count;
    out.distance = c.distance;
    out.weights = c.weights;
    if (e < nTetra)
      std::copy(tetrahedra[e].begin(), tetrahedra[e].end(), out.nodes.begin());
    else
      std::copy(hexahedra[e - nTetra].begin(), hexahedra[e - nTetra].end(), out.nodes.begin());
  };

  if (degenerate) {
    degenerate->clear();
    for (std::size_t e = 0; e < nElements; ++e)
      if (!evaluate(e, boxes[e].center()).valid) degenerate->push_back(static_cast<Index>(e));
  }

  std::vector<std::uint32_t> seen(nElements, 0);  // by the point that last looked at it
  for (std::size_t k = 0; k < points.size(); ++k) {
    const Vec3d& p = points[k];
    // The element containing p, among those of its cell.
    bool found = false;
    if (grid.contains(p)) {
      const std::size_t cell = grid.index(grid.cellOf(p));
      for (const Index* e = grid.begin(cell); e != grid.end(cell) && !found; ++e) {
        if (!boxes[*e].contains(p)) continue;
        const Candidate c = evaluate(*e, p);
        if (c.valid && c.inside) store(result[k], *e, c), found = true;
      }
    }
    if (found) continue;
    // Else the nearest: shells of cells around p's (ring r: the cells r cells away), until the
    // cells beyond the rings seen are farther than the nearest element found. Elements whose
    // bounding box is already farther are skipped.
    const Eigen::Vector3i centre = grid.cellOf(p);
    double best = kInfinity;
    std::size_t bestElement = nElements;
    Candidate bestCandidate;
    const auto mark = static_cast<std::uint32_t>(k + 1);
    auto visit = [&](const Eigen::Vector3i& c) {
      const std::size_t cell = grid.index(c);
      for (const Index* e = grid.begin(cell); e != grid.end(cell); ++e) {
        if (seen[*e] == mark) continue;
        seen[*e] = mark;
        if (boxes[*e].exteriorDistance(p) >= best) continue;
        const Candidate cand = evaluate(*e, p);
        if (cand.valid && cand.distance < best)
          best = cand.distance, bestElement = *e, bestCandidate = cand;
      }
    };
    for (int r = 0;; ++r) {
      const Eigen::Vector3i lo = (centre.array() - r).max(0).matrix();
      const Eigen::Vector3i hi = (centre.array() + r).min(grid.dims().array() - 1).matrix();
      for (int z = lo.z(); z <= hi.z(); ++z)
        for (int y = lo.y(); y <= hi.y(); ++y) {
          // Rows on the shell's faces are whole; the others only have their two ends.
          const bool face = std::abs(z - centre.z()) == r || std::abs(y - centre.y()) == r;
          if (face) {
            for (int x = lo.x(); x <= hi.x(); ++x) visit(Eigen::Vector3i(x, y, z));
          } else {
            if (centre.x() - r >= 0) visit(Eigen::Vector3i(centre.x() - r, y, z));
            if (r > 0 && centre.x() + r < grid.dims().x())
              visit(Eigen::Vector3i(centre.x() + r, y, z));
          }
        }
      if (best <= grid.distanceBeyond(p, centre, r)) break;
    }
    if (bestElement < nElements) store(result[k], bestElement, bestCandidate);
  }
  return result;
}

}  // namespace stroma::barycentric
