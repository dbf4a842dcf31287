// SPDX-License-Identifier: MIT
#include "BarycentricMapping.h"

#include <algorithm>
#include <unordered_map>
#include <unordered_set>

#include "topology/Topology.h"

namespace stroma {

const Topology* BarycentricMapping::findTopology() {
  if (l_inputTopology) {
    if (auto* t = dynamic_cast<const Topology*>(l_inputTopology.get())) return t;
    if (auto* n = dynamic_cast<const Node*>(l_inputTopology.get())) return n->get<Topology>();
    msgError(l_inputTopology->path() + " is a " + l_inputTopology->className() + ", not a topology",
             "input_topology");
    return nullptr;
  }
  return input()->node() ? input()->node()->get<Topology>() : nullptr;
}

void BarycentricMapping::init() {
  if (!findStates()) return;
  m_options.warnUnsupported(*this, output() != nullptr);
  if (!output()) return;  // a visual output is embedded when first drawn (prepareVisual)
  const bool rest = d_useRestPosition.value();
  const VecId inputPoints = rest ? VecId::restPosition() : VecId::position();
  if (!embedOutput(output()->readCoord(inputPoints), inputPoints)) return;
  applyAtInit(*this, m_options.applyRestPosition.value());
}

// A visual output is embedded when first drawn, maybe after steps: in the input's points of
// the start (reset positions, those init() would have used) unless useRestPosition says rest.
bool BarycentricMapping::prepareVisual(const OutVecCoord& points) {
  const bool rest = d_useRestPosition.value() ||
                    input()->readCoord(VecId::resetPosition()).size() != input()->size();
  return embedOutput(points, rest ? VecId::restPosition() : VecId::resetPosition());
}

// The element and weights of each output point, from the input's points `inputPoints` and the
// output's; false after an error.
bool BarycentricMapping::embedOutput(const std::vector<Vec3d>& points, VecId inputPoints) {
  const Topology* topology = findTopology();
  if (!topology) {
    if (isValid())
      msgError("no topology in " + input()->node()->path() +
                   ": the input's points need tetrahedra or hexahedra (MeshTopology, "
                   "TetrahedronSetTopologyContainer, RegularGridTopology, ...)",
               "input_topology");
    return false;
  }
  const auto& tetrahedra = topology->tetrahedra();
  const auto& hexahedra = topology->hexahedra();
  if (tetrahedra.empty() && hexahedra.empty()) {
    msgError(topology->path() +
                 " has no tetrahedra nor hexahedra: mapping onto surfaces or "
                 "lines is not supported",
             "input_topology");
    return false;
  }
  const auto& nodes = input()->readCoord(inputPoints);

  // Every element must index the input's points.
  auto checkIndices = [&](const auto& elements, const char* kind) {
    for (std::size_t e = 0; e < elements.size(); ++e)
      for (Index n : elements[e])
        if (n >= nodes.size()) {
          msgError(std::string(kind) + " " + std::to_string(e) + " of " + topology->path() +
                       " uses point " + std::to_string(n) + ", out of range of the " +
                       std::to_string(nodes.size()) + " input points",
                   "input_topology");
          return false;
        }
    return true;
  };
  if (!checkIndices(tetrahedra, "tetrahedron") || !checkIndices(hexahedra, "hexahedron"))
    return false;

  std::vector<Index> degenerate;
  m_points = barycentric::embedPoints(nodes, tetrahedra, hexahedra, points, &degenerate);
  m_jacobianReady = false;
  m_topology = topology;
  m_revision = topology->revision();
  m_nodes = nodes;
  m_outputPoints = points;
  if (!degenerate.empty())
    msgWarning(std::to_string(degenerate.size()) + " elements of " + topology->path() +
                   " have no volume and receive no point (the first is element " +
                   std::to_string(degenerate.front()) + ")",
               "input_topology");
  std::size_t outside = 0, farthest = 0;
  for (std::size_t k = 0; k < m_points.size(); ++k) {
    if (m_points[k].count == 0) {
      msgError("output point " + std::to_string(k) + " could not be placed in any element of " +
                   topology->path(),
               "input_topology");
      return false;
    }
    if (m_points[k].distance > 0) {
      if (outside == 0 || m_points[k].distance > m_points[farthest].distance) farthest = k;
      ++outside;
    }
  }
  if (outside)
    msgWarning(std::to_string(outside) + " of the " + std::to_string(m_points.size()) +
                   " output points are outside the input mesh and follow their nearest "
                   "element (the farthest, point " +
                   std::to_string(farthest) + ", is at " +
                   std::to_string(m_points[farthest].distance) + ")",
               "output");
  return true;
}

void BarycentricMapping::embed(const std::vector<std::size_t>& which) {
  const auto& tetrahedra = m_topology->tetrahedra();
  const auto& hexahedra = m_topology->hexahedra();
  m_jacobianReady = false;
  if (which.empty()) {
    m_points = barycentric::embedPoints(m_nodes, tetrahedra, hexahedra, m_outputPoints);
    return;
  }
  std::vector<Vec3d> points;
  points.reserve(which.size());
  for (std::size_t k : which) points.push_back(m_outputPoints[k]);
  const auto embedded = barycentric::embedPoints(m_nodes, tetrahedra, hexahedra, points);
  for (std::size_t i = 0; i < which.size(); ++i) m_points[which[i]] = embedded[i];
}

void BarycentricMapping::refresh() {
  if (!m_topology) return;
  const std::uint64_t now = m_topology->revision();
  if (now == m_revision) return;
  const auto changes = m_topology->changesSince(m_revision);
  m_revision = now;
  if (!changes) {
    embed({});
    return;
  }
  // Follow the renumbering; collect the points whose tetrahedron went.
  std::vector<std::size_t> lost;
  std::vector<char> isLost(m_points.size(), 0);
  for (const TopologyChange& change : *changes) {
    const auto& removal = change.tetrahedra;
    if (removal.empty()) continue;
    std::unordered_map<Index, Index> moved(removal.moved.begin(), removal.moved.end());
    std::unordered_set<Index> removed(removal.removed.begin(), removal.removed.end());
    const auto shift = static_cast<Index>(removal.sizeBefore - removal.sizeAfter);
    for (std::size_t k = 0; k < m_points.size(); ++k) {
      Index& element = m_points[k].element;
      if (isLost[k] || element == kInvalidIndex) continue;
      if (element >= removal.sizeBefore) {
        element -= shift;  // a hexahedron: numbered after the tetrahedra
      } else if (removed.contains(element)) {
        isLost[k] = 1;
        lost.push_back(k);
      } else if (const auto it = moved.find(element); it != moved.end()) {
        element = it->second;
      }
    }
  }
  if (lost.empty()) return;
  m_jacobianReady = false;
  if (m_topology->tetrahedra().empty() && m_topology->hexahedra().empty()) {
    // Nothing left to follow: the points keep their last weights (on free points).
    for (std::size_t k : lost) m_points[k].element = kInvalidIndex;
  } else {
    embed(lost);
  }
  if (m_reattached == 0)
    msgWarning(std::to_string(lost.size()) +
                   " output points lost their tetrahedron (removed) "
                   "and follow the nearest remaining element; later re-attachments are counted "
                   "(reattachedCount) without a warning",
               "input_topology");
  m_reattached += lost.size();
}

void BarycentricMapping::apply(OutVecCoord& out, const InVecCoord& in) {
  refresh();
  out.resize(m_points.size());
  for (std::size_t k = 0; k < m_points.size(); ++k) {
    const auto& p = m_points[k];
    Vec3d x = Vec3d::Zero();
    for (int i = 0; i < p.count; ++i) x += p.weights[i] * in[p.nodes[i]];
    out[k] = x;
  }
}

void BarycentricMapping::applyJ(OutVecDeriv& out, const InVecDeriv& in) {
  refresh();
  out.resize(m_points.size());
  for (std::size_t k = 0; k < m_points.size(); ++k) {
    const auto& p = m_points[k];
    Vec3d v = Vec3d::Zero();
    for (int i = 0; i < p.count; ++i) v += p.weights[i] * in[p.nodes[i]];
    out[k] = v;
  }
}

void BarycentricMapping::applyJT(InVecDeriv& in, const OutVecDeriv& out) {
  refresh();
  for (std::size_t k = 0; k < m_points.size() && k < out.size(); ++k) {
    const auto& p = m_points[k];
    for (int i = 0; i < p.count; ++i) in[p.nodes[i]] += p.weights[i] * out[k];
  }
}

const Eigen::SparseMatrix<double>& BarycentricMapping::jacobian() {
  refresh();
  // Constant: built once after init.
  const auto columns = static_cast<Eigen::Index>(input()->matrixSize());
  if (m_jacobianReady && m_J.cols() == columns) return m_J;
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(m_points.size() * 3 * 8);
  for (std::size_t k = 0; k < m_points.size(); ++k) {
    const auto& p = m_points[k];
    for (int i = 0; i < p.count; ++i)
      for (int c = 0; c < 3; ++c)
        triplets.emplace_back(static_cast<int>(3 * k) + c, static_cast<int>(3 * p.nodes[i]) + c,
                              p.weights[i]);
  }
  m_J.resize(static_cast<Eigen::Index>(3 * m_points.size()), columns);
  m_J.setFromTriplets(triplets.begin(), triplets.end());
  m_jacobianReady = true;
  return m_J;
}

}  // namespace stroma
