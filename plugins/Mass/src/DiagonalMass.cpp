// SPDX-License-Identifier: MIT
#include "DiagonalMass.h"

#include "MeshMassSetup.h"
#include "core/Node.h"

namespace stroma {

void DiagonalMass::init() {
  Mass<Vec3Types>::init();
  if (!mstate()) return;
  if (!d_filename.value().original.empty())
    msgError("mass files (" + d_filename.value().original +
                 ") are not supported: give massDensity, totalMass or vertexMass",
             "filename");
  const std::size_t n = mstate()->size();
  const auto& given = d_vertexMass.value();
  if (!given.empty() && given.size() != n)
    msgWarning("has " + std::to_string(given.size()) + " values for the " + std::to_string(n) +
                   " points: ignored (as SOFA), the mass is computed from the elements",
               "vertexMass");
  if (d_totalMass.value() > 0 && d_massDensity.isSet())
    msgWarning("totalMass and massDensity are both given: totalMass is used", "massDensity");
  m_topology = findMassTopology(*this, l_topology);
  if (!m_topology || !compute()) return;
  if (d_printMass.value())
    msgInfo("total mass " + std::to_string(totalMass()) + " on " + std::to_string(n) + " points");
}

bool DiagonalMass::compute(bool again) {
  // Again after a topology change: on the points of the first computation, as an update
  // would (the remaining elements keep their masses), when the state kept its size.
  if (!again || m_points.size() != mstate()->size()) {
    const VecCoord& rest = mstate()->readCoord(VecId::restPosition());
    const VecCoord& points = d_computeMassOnRest.value() && rest.size() == mstate()->size()
                                 ? rest
                                 : mstate()->readCoord(VecId::position());
    m_points.assign(points.begin(), points.end());
  }
  // Every element removed at run time: no mass left (SOFA deletes the points then).
  const Topology& t = *m_topology;
  if (again && t.edges().empty() && t.triangles().empty() && t.quads().empty() &&
      t.tetrahedra().empty() && t.hexahedra().empty()) {
    m_lumped = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(m_points.size()));
    m_measure = 0;
    m_topologyRevision = t.revision();
    return true;
  }
  MeshMassMatrix mesh;
  if (!computeMeshMass(*this, *m_topology, m_points, mesh)) return false;
  m_lumped = mesh.lumped;
  m_measure = mesh.measure;
  m_onTetrahedra = mesh.elements == "tetrahedra";
  m_topologyRevision = m_topology->revision();
  return true;
}

void DiagonalMass::refresh() {
  if (!m_topology) return;
  const std::uint64_t now = m_topology->revision();
  if (now == m_topologyRevision) return;
  const auto changes = m_onTetrahedra ? m_topology->changesSince(m_topologyRevision) : std::nullopt;
  if (!changes) {
    compute(true);
    return;
  }
  for (const TopologyChange& change : *changes)
    removeTetrahedronMasses(change, m_points, nullptr, m_lumped, m_measure);
  m_topologyRevision = now;
}

template <class F>
void DiagonalMass::forEachMass(std::size_t n, F&& f) const {
  const auto& given = d_vertexMass.value();
  if (given.size() == mstate()->size()) {
    for (std::size_t i = 0; i < n && i < given.size(); ++i) f(i, given[i]);
    return;
  }
  const double density = massDensityOf(d_totalMass.value(), d_massDensity.value(), m_measure);
  const std::size_t count = std::min(n, static_cast<std::size_t>(m_lumped.size()));
  for (std::size_t i = 0; i < count; ++i) f(i, density * m_lumped[static_cast<Eigen::Index>(i)]);
}

double DiagonalMass::pointMass(std::size_t i) const {
  const auto& given = d_vertexMass.value();
  if (given.size() == mstate()->size()) return i < given.size() ? given[i] : 0.0;
  if (static_cast<Eigen::Index>(i) >= m_lumped.size()) return 0;
  return massDensityOf(d_totalMass.value(), d_massDensity.value(), m_measure) *
         m_lumped[static_cast<Eigen::Index>(i)];
}

double DiagonalMass::totalMass() const {
  double total = 0;
  forEachMass(mstate()->size(), [&](std::size_t, double m) { total += m; });
  return total;
}

void DiagonalMass::addForce(const MechanicalParams&, VecDeriv& f, const VecCoord&,
                            const VecDeriv&) {
  refresh();
  const Vec3d g = node()->gravity();
  forEachMass(f.size(), [&](std::size_t i, double m) { f[i] += m * g; });
}

double DiagonalMass::potentialEnergy(const MechanicalParams&, const VecCoord& x) const {
  const Vec3d g = node()->gravity();
  double e = 0;
  forEachMass(x.size(), [&](std::size_t i, double m) { e -= m * g.dot(x[i]); });
  return e;
}

void DiagonalMass::addMDx(VecDeriv& f, const VecDeriv& dx, double factor) {
  refresh();
  forEachMass(f.size(), [&](std::size_t i, double m) { f[i] += factor * m * dx[i]; });
}

void DiagonalMass::accFromF(VecDeriv& a, const VecDeriv& f) {
  refresh();
  forEachMass(a.size(),
              [&](std::size_t i, double m) { a[i] = m > 0 ? Vec3d(f[i] / m) : Vec3d::Zero(); });
}

void DiagonalMass::addMToMatrix(MatrixAccumulator& matrix, std::size_t offset, double factor) {
  refresh();
  forEachMass(mstate()->size(), [&](std::size_t i, double m) {
    for (std::size_t k = 0; k < 3; ++k)
      matrix.add(offset + 3 * i + k, offset + 3 * i + k, factor * m);
  });
}

double DiagonalMass::kineticEnergy(const VecDeriv& v) const {
  double e = 0;
  forEachMass(v.size(), [&](std::size_t i, double m) { e += m * v[i].squaredNorm(); });
  return 0.5 * e;
}

}  // namespace stroma
