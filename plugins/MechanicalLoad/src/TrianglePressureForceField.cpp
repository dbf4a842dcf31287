// SPDX-License-Identifier: MIT
#include "TrianglePressureForceField.h"

#include <algorithm>
#include <string>

#include "core/IndexChecks.h"

namespace stroma {

namespace {

// (b - a) x (c - a): twice the area times the unit normal of the triangle (a, b, c).
Vec3d doubleAreaNormal(const Vec3d& a, const Vec3d& b, const Vec3d& c) {
  return (b - a).cross(c - a);
}

// The gradients of the area of (a, b, c) with respect to a, b and c: with n the unit normal,
// dA = n.(da x (b - c)) / 2, so grad_a A = (b - c) x n / 2, and cyclically. Zero for a
// degenerate triangle (its area has no gradient there).
std::array<Vec3d, 3> areaGradients(const Vec3d& a, const Vec3d& b, const Vec3d& c) {
  const Vec3d N = doubleAreaNormal(a, b, c);
  const double norm = N.norm();
  if (norm == 0) return {Vec3d::Zero(), Vec3d::Zero(), Vec3d::Zero()};
  const Vec3d n = N / norm;
  return {0.5 * (b - c).cross(n), 0.5 * (c - a).cross(n), 0.5 * (a - b).cross(n)};
}

}  // namespace

void TrianglePressureForceField::init() {
  ForceField<Vec3Types>::init();
  m_topology = l_topology ? l_topology.get() : (node() ? node()->getUp<Topology>() : nullptr);
  if (!m_topology) {
    msgError(
        "needs a topology with triangles (TriangleSetTopologyContainer, MeshTopology, ...) "
        "in its node or above, or a 'topology' link",
        "topology");
    return;
  }
  if (!mstate()) return;
  m_built = false;
  update();
  if (d_triangleList.value().empty())
    msgWarning("no triangle listed: no pressure is applied", "triangleList");
}

void TrianglePressureForceField::update() {
  if (!m_topology || !mstate()) return;
  if (!m_built) return build();
  if (m_topology->revision() != m_builtTopology) dropRemovedTriangles();
}

void TrianglePressureForceField::dropRemovedTriangles() {
  m_builtTopology = m_topology->revision();
  // The list's indices were renumbered by the change; the points were not (a cut keeps them):
  // a loaded triangle is kept while the topology still has it, whatever its new index.
  auto key = [](Triangle t) {
    std::sort(t.begin(), t.end());
    return t;
  };
  std::vector<Triangle> present;
  present.reserve(m_topology->triangles().size());
  for (const Triangle& t : m_topology->triangles()) present.push_back(key(t));
  std::sort(present.begin(), present.end());
  std::size_t kept = 0;
  for (std::size_t t = 0; t < m_triangles.size(); ++t)
    if (std::binary_search(present.begin(), present.end(), key(m_triangles[t]))) {
      m_triangles[kept] = m_triangles[t];
      m_restAreas[kept++] = m_restAreas[t];
    }
  m_triangles.resize(kept);
  m_restAreas.resize(kept);
}

void TrianglePressureForceField::build() {
  m_built = true;
  m_builtTopology = m_topology->revision();
  const auto& triangles = m_topology->triangles();
  const auto& list = d_triangleList.value();
  // Checked first: the message's text allocates.
  for (unsigned t : list)
    if (t >= triangles.size()) {
      reportIndicesOutOfRange(*this, list, triangles.size(), "triangleList",
                              "triangles of " + m_topology->path());
      break;
    }
  const VecCoord& x0 = mstate()->readCoord(VecId::restPosition());
  const std::size_t n = mstate()->size();
  m_triangles.clear();
  m_restAreas.clear();
  std::size_t outside = 0;
  for (unsigned t : list) {
    if (t >= triangles.size()) continue;
    const Triangle& tri = triangles[t];
    if (tri[0] >= n || tri[1] >= n || tri[2] >= n) {
      ++outside;
      continue;
    }
    m_triangles.push_back(tri);
    m_restAreas.push_back(0.5 * doubleAreaNormal(x0[tri[0]], x0[tri[1]], x0[tri[2]]).norm());
  }
  if (outside > 0)
    msgError(std::to_string(outside) + " listed triangles of " + m_topology->path() +
                 " use points out of range of the " + std::to_string(n) + " points of " +
                 mstate()->path() + ": they are skipped",
             "topology");
}

void TrianglePressureForceField::addForce(const MechanicalParams&, VecDeriv& f, const VecCoord& x,
                                          const VecDeriv&) {
  update();
  const Vec3d& p = d_pressure.value();
  const bool constant = d_useConstantForce.value();
  for (std::size_t t = 0; t < m_triangles.size(); ++t) {
    const Triangle& tri = m_triangles[t];
    const double area =
        constant ? m_restAreas[t] : 0.5 * doubleAreaNormal(x[tri[0]], x[tri[1]], x[tri[2]]).norm();
    const Vec3d share = p * (area / 3.0);
    for (Index i : tri) f[i] += share;
  }
}

void TrianglePressureForceField::addDForce(const MechanicalParams& mp, VecDeriv& df,
                                           const VecDeriv& dx) {
  if (d_useConstantForce.value() || mp.kFactor == 0) return;
  const VecCoord& x = mstate()->readCoord(mp.x);
  const Vec3d scaled = d_pressure.value() * (mp.kFactor / 3.0);
  for (const Triangle& tri : m_triangles) {
    const auto grad = areaGradients(x[tri[0]], x[tri[1]], x[tri[2]]);
    const double dArea =
        grad[0].dot(dx[tri[0]]) + grad[1].dot(dx[tri[1]]) + grad[2].dot(dx[tri[2]]);
    for (Index i : tri) df[i] += scaled * dArea;
  }
}

void TrianglePressureForceField::addKToMatrix(const MechanicalParams& mp, MatrixAccumulator& matrix,
                                              std::size_t offset) {
  if (d_useConstantForce.value() || mp.kFactor == 0) return;
  const VecCoord& x = mstate()->readCoord(mp.x);
  const Vec3d scaled = d_pressure.value() * (mp.kFactor / 3.0);
  for (const Triangle& tri : m_triangles) {
    const auto grad = areaGradients(x[tri[0]], x[tri[1]], x[tri[2]]);
    for (Index i : tri)
      for (std::size_t j = 0; j < 3; ++j)
        matrix.addBlock(offset + 3 * std::size_t{i}, offset + 3 * std::size_t{tri[j]},
                        scaled * grad[j].transpose());
  }
}

double TrianglePressureForceField::potentialEnergy(const MechanicalParams&,
                                                   const VecCoord& x) const {
  // A constant force has the energy -f.x; a force following the current area has none.
  if (!d_useConstantForce.value()) return 0;
  const Vec3d& p = d_pressure.value();
  double energy = 0;
  for (std::size_t t = 0; t < m_triangles.size(); ++t) {
    const Triangle& tri = m_triangles[t];
    energy -= p.dot(x[tri[0]] + x[tri[1]] + x[tri[2]]) * (m_restAreas[t] / 3.0);
  }
  return energy;
}

}  // namespace stroma
