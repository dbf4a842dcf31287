// SPDX-License-Identifier: MIT
#include "MeshMatrixMass.h"

#include "MeshMassSetup.h"
#include "core/Node.h"

namespace stroma {

void MeshMatrixMass::init() {
  Mass<Vec3Types>::init();
  if (!mstate()) return;
  if (d_totalMass.value() > 0 && d_massDensity.isSet())
    msgWarning("totalMass and massDensity are both given: totalMass is used", "massDensity");
  if (l_geometryState) {
    auto* geometry = dynamic_cast<MechanicalState<Vec3Types>*>(l_geometryState.get());
    if (!geometry || geometry->size() != mstate()->size()) {
      msgError(l_geometryState->path() + " must be a Vec3d state with the " +
                   std::to_string(mstate()->size()) + " points of the mass's state",
               "geometryState");
      return;
    }
  }
  m_topology = findMassTopology(*this, l_topology);
  if (!m_topology || !compute()) return;
  if (d_printMass.value())
    msgInfo("total mass " + std::to_string(density() * m_mesh.measure) + " on the " +
            m_mesh.elements + " of " + m_topology->path());
}

bool MeshMatrixMass::compute() {
  auto* state =
      l_geometryState ? dynamic_cast<MechanicalState<Vec3Types>*>(l_geometryState.get()) : mstate();
  const VecCoord& rest = state->readCoord(VecId::restPosition());
  const VecCoord& points = d_computeMassOnRest.value() && rest.size() == state->size()
                               ? rest
                               : state->readCoord(VecId::position());
  if (!computeMeshMass(*this, *m_topology, points, m_mesh)) return false;
  m_points.clear();
  if (m_mesh.elements == "tetrahedra") m_points.assign(points.begin(), points.end());
  m_topologyRevision = m_topology->revision();
  return true;
}

void MeshMatrixMass::refresh() {
  if (!m_topology) return;
  const std::uint64_t now = m_topology->revision();
  if (now == m_topologyRevision) return;
  const auto changes =
      m_points.empty() ? std::nullopt : m_topology->changesSince(m_topologyRevision);
  if (!changes) {
    compute();
    return;
  }
  for (const TopologyChange& change : *changes)
    removeTetrahedronMasses(change, m_points, &m_mesh.matrix, m_mesh.lumped, m_mesh.measure);
  m_topologyRevision = now;
}

double MeshMatrixMass::density() const {
  return massDensityOf(d_totalMass.value(), d_massDensity.value(), m_mesh.measure);
}

void MeshMatrixMass::addForce(const MechanicalParams&, VecDeriv& f, const VecCoord&,
                              const VecDeriv&) {
  refresh();
  const Vec3d weight = density() * node()->gravity();
  const auto n = std::min(f.size(), static_cast<std::size_t>(m_mesh.lumped.size()));
  for (std::size_t i = 0; i < n; ++i) f[i] += m_mesh.lumped[static_cast<Eigen::Index>(i)] * weight;
}

double MeshMatrixMass::potentialEnergy(const MechanicalParams&, const VecCoord& x) const {
  const Vec3d weight = density() * node()->gravity();
  const auto n = std::min(x.size(), static_cast<std::size_t>(m_mesh.lumped.size()));
  double e = 0;
  for (std::size_t i = 0; i < n; ++i)
    e -= m_mesh.lumped[static_cast<Eigen::Index>(i)] * weight.dot(x[i]);
  return e;
}

void MeshMatrixMass::addMDx(VecDeriv& f, const VecDeriv& dx, double factor) {
  refresh();
  const double s = factor * density();
  const auto n = std::min(f.size(), static_cast<std::size_t>(m_mesh.lumped.size()));
  if (d_lumping.value()) {
    for (std::size_t i = 0; i < n; ++i)
      f[i] += s * m_mesh.lumped[static_cast<Eigen::Index>(i)] * dx[i];
    return;
  }
  // Rows are independent: split them over the scene's threads (same result for any count).
  const auto& M = m_mesh.matrix;
  node()->threadPool().parallelFor(n, 2048, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      Vec3d sum = Vec3d::Zero();
      for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(
               M, static_cast<Eigen::Index>(i));
           it; ++it)
        sum += it.value() * dx[static_cast<std::size_t>(it.col())];
      f[i] += s * sum;
    }
  });
}

void MeshMatrixMass::accFromF(VecDeriv& a, const VecDeriv& f) {
  refresh();
  // Only exact when lumped (isDiagonal()); solvers ask for it only then. Otherwise the lumped
  // diagonal is the best diagonal stand-in, used with a warning.
  if (!d_lumping.value() && !m_reportedConsistentDivision) {
    m_reportedConsistentDivision = true;
    msgWarning(
        "dividing by a consistent mass matrix is not exact: its row sums are used (set "
        "lumping=\"1\" for explicit solvers)",
        "lumping");
  }
  const double rho = density();
  const auto n = std::min(a.size(), static_cast<std::size_t>(m_mesh.lumped.size()));
  for (std::size_t i = 0; i < n; ++i) {
    const double m = rho * m_mesh.lumped[static_cast<Eigen::Index>(i)];
    a[i] = m > 0 ? Vec3d(f[i] / m) : Vec3d::Zero();
  }
}

void MeshMatrixMass::addMToMatrix(MatrixAccumulator& matrix, std::size_t offset, double factor) {
  refresh();
  const double s = factor * density();
  if (d_lumping.value()) {
    for (Eigen::Index i = 0; i < m_mesh.lumped.size(); ++i)
      for (std::size_t k = 0; k < 3; ++k) {
        const std::size_t row = offset + 3 * static_cast<std::size_t>(i) + k;
        matrix.add(row, row, s * m_mesh.lumped[i]);
      }
    return;
  }
  const auto& M = m_mesh.matrix;
  for (Eigen::Index i = 0; i < M.outerSize(); ++i)
    for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(M, i); it; ++it)
      for (std::size_t k = 0; k < 3; ++k)
        matrix.add(offset + 3 * static_cast<std::size_t>(i) + k,
                   offset + 3 * static_cast<std::size_t>(it.col()) + k, s * it.value());
}

double MeshMatrixMass::kineticEnergy(const VecDeriv& v) const {
  const double rho = density();
  const auto n = std::min(v.size(), static_cast<std::size_t>(m_mesh.lumped.size()));
  double e = 0;
  if (d_lumping.value()) {
    for (std::size_t i = 0; i < n; ++i)
      e += m_mesh.lumped[static_cast<Eigen::Index>(i)] * v[i].squaredNorm();
  } else {
    const auto& M = m_mesh.matrix;
    for (std::size_t i = 0; i < n; ++i)
      for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(
               M, static_cast<Eigen::Index>(i));
           it; ++it)
        e += it.value() * v[i].dot(v[static_cast<std::size_t>(it.col())]);
  }
  return 0.5 * rho * e;
}

}  // namespace stroma
