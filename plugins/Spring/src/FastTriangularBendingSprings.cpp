// SPDX-License-Identifier: MIT
#include "FastTriangularBendingSprings.h"

#include "SpringPairs.h"
#include "core/Node.h"
#include "linalg/AssembledMatrix.h"

namespace stroma {

void FastTriangularBendingSprings::init() {
  ForceField<Vec3Types>::init();
  if (!mstate()) return;
  m_topology = findSpringTopology(*this, l_topology, "triangles");
  if (!m_topology) return;
  if (m_topology->triangles().empty()) {
    msgError("the topology " + m_topology->path() + " has no triangles", "topology");
    return;
  }
  build();
}

void FastTriangularBendingSprings::build() {
  m_topologyRevision = m_topology->revision();
  m_hinges.clear();
  const std::size_t n = mstate()->size();
  const VecCoord& rest = mstate()->readCoord(VecId::restPosition());
  const VecCoord& x0 = rest.size() == n ? rest : mstate()->readCoord(VecId::position());

  const TriangleHinges found =
      findTriangleHinges(m_topology->triangles(), m_topology->triangleEdges());
  std::size_t outOfRange = 0;
  std::vector<std::string> degenerate;
  for (const TriangleHinge& h : found.hinges) {
    if (std::max({h.a, h.b, h.c, h.d}) >= n) {
      ++outOfRange;
      continue;
    }
    LinearBendingHinge hinge;
    if (makeLinearBendingHinge(h, {x0[h.a], x0[h.b], x0[h.c], x0[h.d]}, d_bendingStiffness.value(),
                               d_minDistValidity.value(), hinge))
      m_hinges.push_back(hinge);
    else if (degenerate.size() < 5)
      degenerate.push_back(std::to_string(h.a) + "-" + std::to_string(h.c));
    else
      degenerate.back() = "...";
  }
  if (outOfRange)
    msgError("the triangles of " + m_topology->path() + " use points out of range of the " +
                 std::to_string(n) + " points of " + mstate()->path() + " (" +
                 std::to_string(outOfRange) + " pairs)",
             "topology");
  if (!degenerate.empty()) {
    std::string list;
    for (const std::string& e : degenerate) list += (list.empty() ? "" : ", ") + e;
    msgError("degenerate triangles at rest around the edges " + list +
                 ": an edge or a height is shorter than minDistValidity (" +
                 std::to_string(d_minDistValidity.value()) + ")",
             "topology");
  }
  if (outOfRange || !degenerate.empty()) {
    m_hinges.clear();
    return;
  }
  if (found.nonManifoldEdges)
    msgWarning(std::to_string(found.nonManifoldEdges) +
                   " edges have more than two triangles: each bends its first two",
               "topology");
}

void FastTriangularBendingSprings::addForce(const MechanicalParams&, VecDeriv& f, const VecCoord& x,
                                            const VecDeriv&) {
  if (m_topology && isValid() && m_topology->revision() != m_topologyRevision) build();
  for (const LinearBendingHinge& h : m_hinges) {
    const Vec3d R = bendingVector(h, x);
    for (int i = 0; i < 4; ++i) f[h.vertex[i]] -= h.lambda * h.alpha[i] * R;
  }
}

void FastTriangularBendingSprings::addDForce(const MechanicalParams& mp, VecDeriv& df,
                                             const VecDeriv& dx) {
  for (const LinearBendingHinge& h : m_hinges) {
    const Vec3d dR = bendingVector(h, dx);
    for (int i = 0; i < 4; ++i) df[h.vertex[i]] -= mp.kFactor * h.lambda * h.alpha[i] * dR;
  }
}

void FastTriangularBendingSprings::addKToMatrix(const MechanicalParams& mp,
                                                MatrixAccumulator& matrix, std::size_t offset) {
  // df_i/dx_j = -lambda alpha_i alpha_j I.
  for (const LinearBendingHinge& h : m_hinges)
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) {
        const double k = -mp.kFactor * h.lambda * h.alpha[i] * h.alpha[j];
        const std::size_t row = offset + 3 * std::size_t{h.vertex[i]};
        const std::size_t col = offset + 3 * std::size_t{h.vertex[j]};
        for (int c = 0; c < 3; ++c) matrix.add(row + c, col + c, k);
      }
}

double FastTriangularBendingSprings::potentialEnergy(const MechanicalParams&,
                                                     const VecCoord& x) const {
  double energy = 0;
  for (const LinearBendingHinge& h : m_hinges)
    energy += 0.5 * h.lambda * bendingVector(h, x).squaredNorm();
  return energy;
}

}  // namespace stroma
