// SPDX-License-Identifier: MIT
// Shared by the sparse-grid validation tests: closed surfaces written in the test (a box, a
// cylinder), the grid that SparseGridTopology or RegularGridTopology builds around them, the
// trilinear embedding of points in that grid, and the static solve of the grid.
//
// The solve puts the grid's hexahedra in a MeshTopology with one Young's modulus per cell,
// E times the cell's filled volume fraction (the zeroth level of seed 001's non-uniform
// elements, chapter 4 section 3: a boundary cell is as stiff as the matter it holds, spread
// over the cell), and loads its nodes with the same fraction of the cell's weight.
#pragma once

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "../SolidMechanics/FemTestScenes.h"
#include "topology/Topology.h"

namespace stroma::test {

/// A closed triangle surface.
struct Surface {
  std::vector<Vec3d> points;
  std::vector<std::array<unsigned, 3>> triangles;
};

/// The surface of the box [lo, hi]: 8 corners, each face in two triangles.
inline Surface boxSurface(const Vec3d& lo, const Vec3d& hi) {
  Surface s;
  for (int i = 0; i < 8; ++i)
    s.points.emplace_back(i & 1 ? hi.x() : lo.x(), i & 2 ? hi.y() : lo.y(),
                          i & 4 ? hi.z() : lo.z());
  static constexpr std::array<std::array<unsigned, 4>, 6> kFaces{
      {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}}};
  for (const auto& q : kFaces) {
    s.triangles.push_back({q[0], q[1], q[2]});
    s.triangles.push_back({q[0], q[2], q[3]});
  }
  return s;
}

/// A cylinder of axis z from z = 0 to `height`, centred on x = y = 0: `rings` + 1 circles of
/// `segments` points (ring k at height k / rings), closed by a fan on each end.
inline Surface cylinderSurface(double radius, double height, int segments, int rings) {
  Surface s;
  for (int k = 0; k <= rings; ++k)
    for (int i = 0; i < segments; ++i) {
      const double a = 2 * M_PI * i / segments;
      s.points.emplace_back(radius * std::cos(a), radius * std::sin(a), height * k / rings);
    }
  auto id = [&](int k, int i) { return unsigned(k * segments + (i % segments)); };
  for (int k = 0; k < rings; ++k)
    for (int i = 0; i < segments; ++i) {
      s.triangles.push_back({id(k, i), id(k, i + 1), id(k + 1, i + 1)});
      s.triangles.push_back({id(k, i), id(k + 1, i + 1), id(k + 1, i)});
    }
  const auto bottom = unsigned(s.points.size());
  s.points.emplace_back(0, 0, 0);
  s.points.emplace_back(0, 0, height);
  for (int i = 0; i < segments; ++i) {
    s.triangles.push_back({bottom, id(0, i + 1), id(0, i)});
    s.triangles.push_back({bottom + 1, id(rings, i), id(rings, i + 1)});
  }
  return s;
}

/// The surface moved by p -> R p + t.
inline Surface transformed(Surface s, const Mat3d& R, const Vec3d& t) {
  for (Vec3d& p : s.points) p = R * p + t;
  return s;
}

/// The attributes `position="..." triangles="..."` that give a surface to a SparseGridTopology.
inline std::string surfaceAttributes(const Surface& s) {
  return "position=\"" + pointsText(s.points) + "\" triangles=\"" + elementsText(s.triangles) +
         "\"";
}

inline std::string vecText(const Vec3d& v) {
  std::ostringstream out;
  out.precision(17);
  out << v.x() << ' ' << v.y() << ' ' << v.z();
  return out.str();
}

/// A grid's points, hexahedra and each hexahedron's filled volume fraction.
struct GridMesh {
  std::vector<Vec3d> points;
  std::vector<std::array<unsigned, 8>> hexahedra;
  std::vector<double> fractions;
};

/// The grid that `topologyXml` (one component named "grid": a SparseGridTopology or a
/// RegularGridTopology) builds in a scene of its own; fractions 1 when it has none. Empty, with
/// a test failure, when the scene did not load quietly.
inline GridMesh buildGrid(const std::string& topologyXml) {
  Runtime runtime;
  Scene scene(runtime);
  GridMesh mesh;
  if (!loadQuietly(scene,
                   "<Node name=\"root\" gravity=\"0 0 0\" dt=\"1\">\n<Node name=\"body\">\n" +
                       topologyXml + "\n</Node>\n</Node>\n"))
    return mesh;
  auto* topology = objectAt<Topology>(scene, "@/body/grid");
  if (topology == nullptr) return mesh;
  mesh.points = topology->positions();
  for (const auto& h : topology->hexahedra()) {
    std::array<unsigned, 8> cell{};
    for (int c = 0; c < 8; ++c) cell[c] = static_cast<unsigned>(h[c]);
    mesh.hexahedra.push_back(cell);
  }
  if (const BaseData* d = topology->findData("volumeFractions")) {
    std::istringstream in(d->valueText());
    for (double f; in >> f;) mesh.fractions.push_back(f);
  } else {
    mesh.fractions.assign(mesh.hexahedra.size(), 1.0);
  }
  EXPECT_EQ(mesh.fractions.size(), mesh.hexahedra.size());
  return mesh;
}

/// The cells holding at least `minFraction` of matter, with the points they use renumbered.
/// A cell whose face lies on the surface is kept by the grid with a fraction of about 0: it
/// holds no matter, and its outer nodes would have no stiffness.
inline GridMesh keepFilled(const GridMesh& mesh, double minFraction) {
  GridMesh out;
  std::vector<int> newIndex(mesh.points.size(), -1);
  for (std::size_t e = 0; e < mesh.hexahedra.size(); ++e) {
    if (mesh.fractions[e] < minFraction) continue;
    std::array<unsigned, 8> cell{};
    for (int c = 0; c < 8; ++c) {
      int& id = newIndex[mesh.hexahedra[e][c]];
      if (id < 0) {
        id = static_cast<int>(out.points.size());
        out.points.push_back(mesh.points[mesh.hexahedra[e][c]]);
      }
      cell[c] = static_cast<unsigned>(id);
    }
    out.hexahedra.push_back(cell);
    out.fractions.push_back(mesh.fractions[e]);
  }
  return out;
}

/// A point embedded in an axis-aligned grid cell: the cell's nodes and trilinear weights.
struct Embedded {
  std::array<unsigned, 8> nodes{};
  std::array<double, 8> weights{};
};

/// The cell of `mesh` (axis-aligned, corners 0 and 6 opposite) that contains `p`, if any.
inline std::optional<Embedded> locate(const GridMesh& mesh, const Vec3d& p) {
  for (const auto& h : mesh.hexahedra) {
    const Vec3d lo = mesh.points[h[0]], hi = mesh.points[h[6]];
    const Vec3d t = (p - lo).cwiseQuotient(hi - lo);
    if ((t.array() < -1e-9).any() || (t.array() > 1 + 1e-9).any()) continue;
    const double u = t.x(), v = t.y(), w = t.z();
    Embedded e;
    e.nodes = h;
    e.weights = {
        (1 - u) * (1 - v) * (1 - w), u * (1 - v) * (1 - w), u * v * (1 - w), (1 - u) * v * (1 - w),
        (1 - u) * (1 - v) * w,       u * (1 - v) * w,       u * v * w,       (1 - u) * v * w};
    return e;
  }
  return std::nullopt;
}

inline Vec3d interpolate(const Embedded& e, const std::vector<Vec3d>& x) {
  Vec3d p = Vec3d::Zero();
  for (int c = 0; c < 8; ++c) p += e.weights[c] * x[e.nodes[c]];
  return p;
}

/// A static problem on a grid: the corotational FEM with E x fraction per cell, nodal loads,
/// fixed nodes, and nodes fixed along some directions only; the solution starts from
/// `initial` (the rest positions when empty), where imposed displacements are written.
struct StaticProblem {
  GridMesh mesh;
  std::string forceField = "HexahedronFEMForceField";
  std::string method = "large";
  double youngModulus = 1;
  double poissonRatio = 0;
  std::vector<unsigned> loaded;
  std::vector<Vec3d> loads;
  std::vector<unsigned> fixed;
  struct Partial {
    std::vector<unsigned> indices;
    std::array<int, 3> directions{};
  };
  std::vector<Partial> partial;
  std::vector<Vec3d> initial;
  int newtonIterations = 50;
  /// Newton stops when |R| / |R_0| or |du| / |U| falls below this.
  double tolerance = 1e-8;
};

struct StaticResult {
  std::vector<Vec3d> positions;  // empty when the scene did not load
  bool converged = false;
  int iterations = 0;  // Newton iterations
};

template <class T>
std::string listText(const std::vector<T>& values) {
  std::ostringstream out;
  out.precision(17);
  for (const T& v : values) out << v << ' ';
  return out.str();
}

/// Solves the problem with StaticSolver (Newton, line search) and SparseLDLSolver, in one
/// step (one load increment).
inline StaticResult solveStatic(const StaticProblem& p) {
  std::vector<double> moduli;
  bool uniform = true;
  for (double f : p.mesh.fractions) {
    moduli.push_back(p.youngModulus * f);
    uniform &= f == 1.0;
  }
  std::ostringstream xml;
  xml.precision(17);
  xml << "<Node name=\"root\" gravity=\"0 0 0\" dt=\"1\">\n<Node name=\"body\">\n"
      << "<StaticSolver name=\"solver\" newton_iterations=\"" << p.newtonIterations
      << "\" absolute_correction_tolerance_threshold=\"0\" "
         "relative_correction_tolerance_threshold=\""
      << p.tolerance << "\" absolute_residual_tolerance_threshold=\"0\" "
      << "relative_residual_tolerance_threshold=\"" << p.tolerance << "\"/>\n"
      << "<SparseLDLSolver/>\n"
      << "<MeshTopology name=\"mesh\" hexahedra=\"" << elementsText(p.mesh.hexahedra) << "\"/>\n"
      << "<MechanicalObject name=\"dofs\" rest_position=\"" << pointsText(p.mesh.points)
      << "\" position=\"" << pointsText(p.initial.empty() ? p.mesh.points : p.initial) << "\"/>\n"
      << "<" << p.forceField << " method=\"" << p.method << "\" poissonRatio=\"" << p.poissonRatio
      << "\" youngModulus=\""
      << (uniform ? listText(std::vector<double>{p.youngModulus}) : listText(moduli)) << "\"/>\n";
  if (!p.loaded.empty())
    xml << "<ConstantForceField name=\"load\" indices=\"" << listText(p.loaded) << "\" forces=\""
        << pointsText(p.loads) << "\"/>\n";
  if (!p.fixed.empty())
    xml << "<FixedProjectiveConstraint indices=\"" << listText(p.fixed) << "\"/>\n";
  for (const auto& partial : p.partial)
    xml << "<PartialFixedProjectiveConstraint indices=\"" << listText(partial.indices)
        << "\" fixedDirections=\"" << partial.directions[0] << ' ' << partial.directions[1] << ' '
        << partial.directions[2] << "\"/>\n";
  xml << "</Node>\n</Node>\n";

  StaticResult result;
  Runtime runtime;
  Scene scene(runtime);
  if (!loadQuietly(scene, xml.str())) return result;
  auto* solver = objectAt<Base>(scene, "@/body/solver");
  EXPECT_TRUE(scene.step());
  const std::string converged = solver->findData("lastConverged")->valueText();
  result.converged = converged == "1" || converged == "true";
  result.iterations = std::stoi(solver->findData("lastIterations")->valueText());
  result.positions =
      objectAt<MechanicalState<Vec3Types>>(scene, "@/body/dofs")->readCoord(VecId::position());
  return result;
}

/// Nodal loads of a uniform body force `density` x `acceleration` on the grid: each cell's
/// share (fraction x volume) spread equally on its 8 nodes, the consistent load of a trilinear
/// cell under a uniform force.
inline void addBodyForce(StaticProblem& p, double density, const Vec3d& acceleration) {
  std::vector<Vec3d> nodal(p.mesh.points.size(), Vec3d::Zero());
  for (std::size_t e = 0; e < p.mesh.hexahedra.size(); ++e) {
    const auto& h = p.mesh.hexahedra[e];
    const Vec3d d = p.mesh.points[h[6]] - p.mesh.points[h[0]];
    const double volume = std::abs(d.x() * d.y() * d.z());
    for (unsigned n : h) nodal[n] += p.mesh.fractions[e] * volume * density / 8 * acceleration;
  }
  for (std::size_t i = 0; i < nodal.size(); ++i) {
    p.loaded.push_back(static_cast<unsigned>(i));
    p.loads.push_back(nodal[i]);
  }
}

}  // namespace stroma::test
