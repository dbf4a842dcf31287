// SPDX-License-Identifier: MIT
#include "NonUniformHexahedronFEMForceFieldAndMass.h"

#include <algorithm>
#include <cmath>

#include "ImageMaterial.h"
#include "SolidMechanics/kernels/CorotationalElement.h"
#include "SolidMechanics/kernels/IsotropicMaterial.h"
#include "TransferFunction.h"
#include "core/Message.h"
#include "core/Node.h"
#include "core/ThreadPool.h"

namespace stroma {

namespace {

// Work per task of the parallel loops (a task should last 10 to 100 us; shorter loops stay on
// the calling thread): condensing a hexahedron from 2 levels takes about 0.1 ms, a corotational
// force about 0.3 us, a product -R K R^T dx about 0.3 us, a vertex sum about 30 ns.
constexpr std::size_t kCondensationGrain = 4;
constexpr std::size_t kForceGrain = 128;
constexpr std::size_t kProductGrain = 256;
constexpr std::size_t kVertexGrain = 2048;

}  // namespace

const Topology* NonUniformHexahedronFEMForceFieldAndMass::findSparseGrid() {
  if (l_topology) {
    if (!l_topology->sparseGrid()) {
      msgError("the topology " + l_topology->path() +
                   " is not a sparse grid: the non-uniform hexahedra are condensed from the "
                   "levels of a SparseGridTopology",
               "topology");
      return nullptr;
    }
    return l_topology.get();
  }
  for (const Node* n = node(); n; n = n->parent())
    for (const Topology* topology : n->getAll<Topology>())
      if (topology->sparseGrid()) return topology;
  msgError(
      "needs a SparseGridTopology in its node or above, or a 'topology' link to one: the "
      "non-uniform hexahedra are condensed from the levels of a sparse grid",
      "topology");
  return nullptr;
}

void NonUniformHexahedronFEMForceFieldAndMass::reportBadInput(const std::string& text,
                                                              const std::string& field) {
  // At init, bad input stops the component; while running, the change is refused and the
  // matrices of the last valid material stay (as HexahedronFEMForceField does).
  if (m_ready)
    msgWarning(text + "; the change is not applied", field);
  else
    msgError(text, field);
}

void NonUniformHexahedronFEMForceFieldAndMass::init() {
  Mass<Vec3Types>::init();
  m_ready = false;
  if (!mstate()) return;  // Mass::init reported it
  m_topology = findSparseGrid();
  if (!m_topology) {
    setInvalid();
    return;
  }
  const sparsegrid::SparseGrid& grid = *m_topology->sparseGrid();
  m_hexahedra.assign(m_topology->hexahedra().begin(), m_topology->hexahedra().end());
  if (m_hexahedra.size() != grid.cells.size()) {
    msgError("the topology " + m_topology->path() + " has " + std::to_string(m_hexahedra.size()) +
                 " hexahedra for " + std::to_string(grid.cells.size()) + " grid cells",
             "topology");
    setInvalid();
    return;
  }
  const std::size_t points = mstate()->size();
  for (std::size_t e = 0; e < m_hexahedra.size(); ++e)
    for (Index v : m_hexahedra[e])
      if (v >= points) {
        msgError("hexahedron " + std::to_string(e) + " uses point " + std::to_string(v) +
                     " but the mechanical state has " + std::to_string(points) + " points",
                 "topology");
        setInvalid();
        return;
      }
  if (!d_useMass.value())
    msgWarning(
        "useMass=\"false\" (a separate mass) is not supported: this component keeps the "
        "condensed mass and gravity",
        "useMass");
  buildVertexAdjacency(points);
  if (!computeConstants()) {
    setInvalid();
    return;
  }
  const auto& x = mstate()->readCoord(VecId::position());
  m_rotations.resize(m_elements.size());
  for (std::size_t e = 0; e < m_elements.size(); ++e)
    m_rotations[e] = fem::computeRotation(rotationMethod(), m_elements[e], gather(x, e));
  m_ready = true;
}

bool NonUniformHexahedronFEMForceFieldAndMass::computeCellMaterials(
    std::span<const sparsegrid::FinerLevel> levels) {
  const sparsegrid::SparseGrid& finest =
      levels.empty() ? *m_topology->sparseGrid() : levels.front().grid;
  const std::size_t count = finest.cells.size();
  m_cellMaterials.assign(count, fem::CellMaterial{1, d_youngModulus.value(), d_density.value()});
  // A kept cell holds material even where the sampling found none (the surface crosses it):
  // flooring its fraction keeps every point of the grid with some mass and stiffness.
  const double floor = d_minimumFraction.value();
  for (std::size_t c = 0; c < count; ++c)
    m_cellMaterials[c].fraction = std::max(finest.fractions[c], floor);

  const bool hasImage = !d_imageFile.value().original.empty();
  const bool hasTransfer =
      !d_youngModulusTransfer.value().empty() || !d_densityTransfer.value().empty();
  if (!hasImage) {
    if (hasTransfer)
      msgWarning(
          "a transfer function is given without an image: youngModulus and density "
          "apply everywhere",
          d_youngModulusTransfer.value().empty() ? "densityTransfer" : "youngModulusTransfer");
    return true;
  }
  std::optional<nonuniform::TransferFunction> toYoung, toDensity;
  std::string why;
  if (!d_youngModulusTransfer.value().empty()) {
    toYoung = nonuniform::TransferFunction::parse(d_youngModulusTransfer.value(), 0.0, true, why);
    if (!toYoung) {
      reportBadInput("Young's modulus transfer function: " + why, "youngModulusTransfer");
      return false;
    }
  }
  if (!d_densityTransfer.value().empty()) {
    toDensity = nonuniform::TransferFunction::parse(d_densityTransfer.value(), 0.0, false, why);
    if (!toDensity) {
      reportBadInput("density transfer function: " + why, "densityTransfer");
      return false;
    }
  }
  if (!toYoung && !toDensity)
    msgWarning(
        "an image is given without youngModulusTransfer or densityTransfer: it is not "
        "used",
        "imageFile");
  image::VolumeImage volume;
  if (!image::readVolumeImage(d_imageFile.value().path(), volume, why)) {
    reportBadInput("cannot read the image: " + why, "imageFile");
    return false;
  }
  // Each finest cell: the transfer of the mean image value over the cell (in the grid's frame).
  for (std::size_t c = 0; c < count; ++c) {
    const auto ijk = finest.box.cellCoordinates(finest.cells[c]);
    const Vec3d lower =
        finest.box.origin + Vec3d(ijk[0], ijk[1], ijk[2]).cwiseProduct(finest.box.spacing);
    const double value = nonuniform::meanImageValue(volume, lower, lower + finest.box.spacing);
    if (toYoung) m_cellMaterials[c].youngModulus = (*toYoung)(value);
    if (toDensity) m_cellMaterials[c].density = (*toDensity)(value);
  }
  return true;
}

bool NonUniformHexahedronFEMForceFieldAndMass::computeConstants() {
  const double E = d_youngModulus.value(), nu = d_poissonRatio.value(), rho = d_density.value();
  if (!(E > 0) || !std::isfinite(E)) {
    reportBadInput("expected a Young's modulus > 0, got " + formatNumber(E), "youngModulus");
    return false;
  }
  if (!fem::isValidIsotropicMaterial(E, nu)) {
    reportBadInput("expected -1 < poissonRatio < 0.5 (0.5 is incompressible), got " + formatNumber(nu),
                   "poissonRatio");
    return false;
  }
  if (!(rho > 0) || !std::isfinite(rho)) {
    reportBadInput("expected a density > 0, got " + formatNumber(rho), "density");
    return false;
  }
  const auto available = m_topology->sparseGridFinerLevels();
  const int used = d_nbVirtualFinerLevels.value();
  if (used < 0 || std::size_t(used) > available.size()) {
    reportBadInput("asks for " + std::to_string(used) + " finer levels but the topology " +
                       m_topology->path() + " keeps " + std::to_string(available.size()) +
                       ": set nbVirtualFinerLevels=\"" + std::to_string(used) +
                       "\" on the SparseGridTopology too",
                   "nbVirtualFinerLevels");
    return false;
  }
  // The coarsest `used` levels: the last one's parents are the simulated cells.
  const auto levels = available.last(std::size_t(used));
  if (!levels.empty() && levels.back().parentsChildren.size() != m_hexahedra.size()) {
    reportBadInput("the finer levels of " + m_topology->path() + " have children for " +
                       std::to_string(levels.back().parentsChildren.size()) +
                       " cells, not for its " + std::to_string(m_hexahedra.size()) + " hexahedra",
                   "topology");
    return false;
  }
  if (!computeCellMaterials(levels)) return false;

  const auto& rest = mstate()->readCoord(VecId::restPosition());
  const std::size_t count = m_hexahedra.size();
  m_elements.assign(count, fem::CorotationalHexahedron{});
  m_elementMasses.assign(count, fem::Matrix8d::Zero());
  m_vertexMasses.assign(mstate()->size(), 0.0);
  const fem::Matrix6d unitC = fem::computeElasticityMatrix(fem::computeLameParameters(1.0, nu));
  const auto material = [this](Index cell) { return m_cellMaterials[cell]; };
  std::vector<char> failed(count, 0);
  node()->threadPool().parallelFor(
      count, kCondensationGrain, [&](std::size_t begin, std::size_t end) {
        for (std::size_t e = begin; e < end; ++e) {
          const fem::HexahedronVectors X = gather(rest, e);
          fem::CondensedHexahedron condensed;
          // The rest frame and centre gradients of the simulated hexahedron; its Ke is replaced.
          if (fem::computeCorotationalHexahedron(X, unitC, m_elements[e]) !=
                  fem::ElementStatus::ok ||
              fem::condenseHexahedron(X, Index(e), levels, material, nu, condensed) !=
                  fem::ElementStatus::ok) {
            failed[e] = 1;
            continue;
          }
          m_elements[e].stiffness = condensed.stiffness;
          m_elementMasses[e] = condensed.mass;
        }
      });
  std::vector<std::size_t> degenerate;
  for (std::size_t e = 0; e < count; ++e) {
    if (failed[e]) {
      degenerate.push_back(e);
      continue;
    }
    const fem::Vector8d rowSums = m_elementMasses[e].rowwise().sum();
    for (int i = 0; i < 8; ++i) m_vertexMasses[m_hexahedra[e][i]] += rowSums[i];
  }
  if (!degenerate.empty()) {
    std::string list;
    for (std::size_t k = 0; k < degenerate.size() && k < 10; ++k)
      list += (k ? ", " : "") + std::to_string(degenerate[k]);
    reportBadInput("degenerate rest shape (zero volume) of hexahedra " + list +
                       (degenerate.size() > 10 ? ", ..." : ""),
                   "topology");
    return false;
  }
  double total = 0;
  for (double m : m_vertexMasses) total += m;
  d_vertexMass.setValue(m_vertexMasses);
  d_totalMass.setValue(total);
  m_materialVersion = materialVersion();
  return true;
}

std::uint64_t NonUniformHexahedronFEMForceFieldAndMass::materialVersion() const {
  return d_youngModulus.version() + d_poissonRatio.version() + d_density.version() +
         d_nbVirtualFinerLevels.version() + d_minimumFraction.version() +
         d_youngModulusTransfer.version() + d_densityTransfer.version() + d_imageFile.version();
}

void NonUniformHexahedronFEMForceFieldAndMass::refresh() {
  const std::uint64_t version = materialVersion();
  if (version == m_materialVersion) return;
  // Keep the previous constants when the new material is refused (reported by computeConstants).
  auto elements = m_elements;
  auto masses = m_elementMasses;
  auto vertexMasses = m_vertexMasses;
  if (!computeConstants()) {
    m_elements = std::move(elements);
    m_elementMasses = std::move(masses);
    m_vertexMasses = std::move(vertexMasses);
    m_materialVersion = version;
  }
}

fem::HexahedronVectors NonUniformHexahedronFEMForceFieldAndMass::gather(std::span<const Vec3d> v,
                                                                        std::size_t e) const {
  fem::HexahedronVectors result;
  for (int i = 0; i < 8; ++i) result.col(i) = v[m_hexahedra[e][i]];
  return result;
}

void NonUniformHexahedronFEMForceFieldAndMass::buildVertexAdjacency(std::size_t pointCount) {
  // A counting sort of the corners by vertex: increasing element order around each vertex.
  m_vertexOffsets.assign(pointCount + 1, 0);
  for (const Hexahedron& h : m_hexahedra)
    for (Index v : h) ++m_vertexOffsets[v + 1];
  for (std::size_t v = 0; v < pointCount; ++v) m_vertexOffsets[v + 1] += m_vertexOffsets[v];
  m_vertexCorners.resize(m_vertexOffsets[pointCount]);
  std::vector<Index> next(m_vertexOffsets.begin(), m_vertexOffsets.end() - 1);
  for (std::size_t e = 0; e < m_hexahedra.size(); ++e)
    for (int i = 0; i < 8; ++i) m_vertexCorners[next[m_hexahedra[e][i]]++] = Index(8 * e + i);
  m_corners.assign(8 * m_hexahedra.size(), Vec3d::Zero());
}

void NonUniformHexahedronFEMForceFieldAndMass::accumulate(
    std::span<Vec3d> out, double factor, std::size_t grain,
    FunctionRef<void(std::size_t, Eigen::Map<fem::HexahedronVectors>)> perElement) {
  const ThreadPool& pool = node()->threadPool();
  pool.parallelFor(m_hexahedra.size(), grain, [&](std::size_t begin, std::size_t end) {
    for (std::size_t e = begin; e < end; ++e)
      perElement(e, Eigen::Map<fem::HexahedronVectors>(m_corners[8 * e].data()));
  });
  const std::size_t n = std::min(out.size(), m_vertexOffsets.size() - 1);
  pool.parallelFor(n, kVertexGrain, [&](std::size_t begin, std::size_t end) {
    for (std::size_t v = begin; v < end; ++v) {
      const Index first = m_vertexOffsets[v], last = m_vertexOffsets[v + 1];
      if (first == last) continue;
      Vec3d sum = m_corners[m_vertexCorners[first]];
      for (Index c = first + 1; c < last; ++c) sum += m_corners[m_vertexCorners[c]];
      out[v] += factor * sum;
    }
  });
}

void NonUniformHexahedronFEMForceFieldAndMass::addForce(const MechanicalParams&, VecDeriv& f,
                                                        const VecCoord& x, const VecDeriv&) {
  if (!m_ready) return;
  refresh();
  const fem::RotationMethod method = rotationMethod();
  accumulate(f, 1.0, kForceGrain, [&](std::size_t e, Eigen::Map<fem::HexahedronVectors> corner) {
    const fem::HexahedronVectors xe = gather(x, e);
    m_rotations[e] = fem::computeRotation(method, m_elements[e], xe);
    corner = fem::computeForce(m_elements[e], m_rotations[e], xe);
  });
  const Vec3d g = node()->gravity();
  for (std::size_t i = 0; i < m_vertexMasses.size() && i < f.size(); ++i)
    f[i] += m_vertexMasses[i] * g;
}

void NonUniformHexahedronFEMForceFieldAndMass::addDForce(const MechanicalParams& mp, VecDeriv& df,
                                                         const VecDeriv& dx) {
  if (!m_ready || mp.kFactor == 0) return;
  accumulate(df, mp.kFactor, kProductGrain,
             [&](std::size_t e, Eigen::Map<fem::HexahedronVectors> corner) {
               corner = fem::computeDForce(m_elements[e], m_rotations[e], gather(dx, e));
             });
}

void NonUniformHexahedronFEMForceFieldAndMass::addKToMatrix(const MechanicalParams& mp,
                                                            MatrixAccumulator& matrix,
                                                            std::size_t offset) {
  if (!m_ready || mp.kFactor == 0) return;
  for (std::size_t e = 0; e < m_elements.size(); ++e) {
    const fem::Matrix24d K = fem::computeStiffness(m_elements[e], m_rotations[e]);
    const Hexahedron& nodes = m_hexahedra[e];
    for (int i = 0; i < 8; ++i)
      for (int j = 0; j < 8; ++j)
        matrix.addBlock(offset + 3 * std::size_t{nodes[i]}, offset + 3 * std::size_t{nodes[j]},
                        -mp.kFactor * K.block<3, 3>(3 * i, 3 * j));
  }
}

double NonUniformHexahedronFEMForceFieldAndMass::potentialEnergy(const MechanicalParams&,
                                                                 const VecCoord& x) const {
  if (!m_ready) return 0;
  double energy = 0;
  for (std::size_t e = 0; e < m_elements.size(); ++e) {
    const fem::HexahedronVectors xe = gather(x, e);
    energy += fem::computeEnergy(m_elements[e],
                                 fem::computeRotation(rotationMethod(), m_elements[e], xe), xe);
  }
  const Vec3d g = node()->gravity();
  for (std::size_t i = 0; i < m_vertexMasses.size() && i < x.size(); ++i)
    energy -= m_vertexMasses[i] * g.dot(x[i]);
  return energy;
}

void NonUniformHexahedronFEMForceFieldAndMass::addMDx(VecDeriv& f, const VecDeriv& dx,
                                                      double factor) {
  if (!m_ready || factor == 0) return;
  if (d_lumpedMass.value()) {
    for (std::size_t i = 0; i < m_vertexMasses.size() && i < f.size(); ++i)
      f[i] += (factor * m_vertexMasses[i]) * dx[i];
    return;
  }
  accumulate(f, factor, kProductGrain,
             [&](std::size_t e, Eigen::Map<fem::HexahedronVectors> corner) {
               // (M (x) I_3) dx, node-major: column i = sum_j M_ij dx_j (M symmetric).
               corner.noalias() = gather(dx, e) * m_elementMasses[e];
             });
}

void NonUniformHexahedronFEMForceFieldAndMass::accFromF(VecDeriv& a, const VecDeriv& f) {
  // Exact for the lumped mass (isDiagonal()); the lumped inverse otherwise.
  for (std::size_t i = 0; i < m_vertexMasses.size() && i < a.size(); ++i)
    a[i] = m_vertexMasses[i] > 0 ? Vec3d(f[i] / m_vertexMasses[i]) : Vec3d::Zero();
}

void NonUniformHexahedronFEMForceFieldAndMass::addMToMatrix(MatrixAccumulator& matrix,
                                                            std::size_t offset, double factor) {
  if (!m_ready || factor == 0) return;
  if (d_lumpedMass.value()) {
    for (std::size_t i = 0; i < m_vertexMasses.size(); ++i)
      for (std::size_t k = 0; k < 3; ++k)
        matrix.add(offset + 3 * i + k, offset + 3 * i + k, factor * m_vertexMasses[i]);
    return;
  }
  for (std::size_t e = 0; e < m_elements.size(); ++e) {
    const Hexahedron& nodes = m_hexahedra[e];
    for (int i = 0; i < 8; ++i)
      for (int j = 0; j < 8; ++j) {
        const double value = factor * m_elementMasses[e](i, j);
        for (std::size_t k = 0; k < 3; ++k)
          matrix.add(offset + 3 * std::size_t{nodes[i]} + k, offset + 3 * std::size_t{nodes[j]} + k,
                     value);
      }
  }
}

double NonUniformHexahedronFEMForceFieldAndMass::kineticEnergy(const VecDeriv& v) const {
  if (!m_ready) return 0;
  double e = 0;
  if (d_lumpedMass.value()) {
    for (std::size_t i = 0; i < m_vertexMasses.size() && i < v.size(); ++i)
      e += m_vertexMasses[i] * v[i].squaredNorm();
  } else {
    for (std::size_t k = 0; k < m_elements.size(); ++k) {
      const fem::HexahedronVectors ve = gather(v, k);
      e += (ve * m_elementMasses[k]).cwiseProduct(ve).sum();
    }
  }
  return 0.5 * e;
}

}  // namespace stroma
