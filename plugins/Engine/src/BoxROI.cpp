// SPDX-License-Identifier: MIT
#include "BoxROI.h"

#include <Eigen/LU>

#include "RoiInputs.h"
#include "core/Node.h"
#include "simulation/MechanicalState.h"
#include "topology/Topology.h"

namespace stroma {

template <class DataTypes>
BoxROI<DataTypes>::BoxROI() {
  for (BaseData* input :
       std::initializer_list<BaseData*>{&d_box, &d_position, &d_edges, &d_triangles, &d_quads,
                                        &d_tetrahedra, &d_hexahedra, &d_strict})
    addInput(input);
  for (BaseData* output : std::initializer_list<BaseData*>{
           &d_indices, &d_pointsInROI, &d_indicesOut, &d_pointsOutROI, &d_edgeIndices,
           &d_edgesInROI, &d_triangleIndices, &d_trianglesInROI, &d_quadIndices, &d_quadInROI,
           &d_tetrahedronIndices, &d_tetrahedraInROI, &d_hexahedronIndices, &d_hexahedraInROI,
           &d_nbIndices})
    addOutput(output);
}

namespace {

// Where a point is in 3D: points of 1 or 2 coordinates have the others 0.
template <int N>
Vec3d toPoint3(const Vec<N>& p) {
  Vec3d q = Vec3d::Zero();
  q.head<N>() = p;
  return q;
}

}  // namespace

// SOFA's search for the inputs not given (RoiInputs.h).
template <class DataTypes>
void BoxROI<DataTypes>::findDefaultInputs() {
  Node* here = node();
  if (!here) return;
  roi::findDefaultPosition(*this, d_position);
  if (const Topology* topology = here->get<Topology>()) {
    roi::followTopology(d_edges, d_computeEdges.value(), topology->d_edges);
    roi::followTopology(d_triangles, d_computeTriangles.value(), topology->d_triangles);
    roi::followTopology(d_quads, d_computeQuad.value(), topology->d_quads);
    roi::followTopology(d_tetrahedra, d_computeTetrahedra.value(), topology->d_tetrahedra);
    roi::followTopology(d_hexahedra, d_computeHexahedra.value(), topology->d_hexahedra);
  }
}

template <class DataTypes>
void BoxROI<DataTypes>::init() {
  if (d_box.value().empty() && d_orientedBox.value().empty()) {
    msgWarning("no box given: the unit box '0 0 0 1 1 1' is used (as SOFA)", "box");
    d_box.setValue({(Vec6d() << 0, 0, 0, 1, 1, 1).finished()});
  }
  const auto& boxes = d_box.value();
  for (std::size_t b = 0; b < boxes.size(); ++b)
    for (int k = 0; k < 3; ++k)
      if (boxes[b][k] > boxes[b][k + 3]) {
        msgWarning("box " + std::to_string(b) + " has min > max along " + "xyz"[k] +
                       ": the two bounds are swapped",
                   "box");
        break;
      }
  std::vector<OrientedBox> oriented;
  if (!computeOrientedBoxes(oriented)) return;
  findDefaultInputs();
  // Select now, so that bad element lists are errors of the scene (m_initialized false).
  setDirty();
  updateIfDirty();
  m_initialized = true;
}

template <class DataTypes>
bool BoxROI<DataTypes>::computeOrientedBoxes(std::vector<OrientedBox>& boxes) const {
  boxes.clear();
  const auto& given = d_orientedBox.value();
  for (std::size_t i = 0; i < given.size(); ++i) {
    const Vec<10>& g = given[i];
    const Vec3d p0 = g.segment<3>(0), p1 = g.segment<3>(3), p2 = g.segment<3>(6);
    const Vec3d a = p0 - p1, b = p2 - p1;
    const Vec3d normal = a.cross(b);
    const double scale = std::max(a.squaredNorm(), b.squaredNorm());
    if (!(normal.norm() > 1e-12 * scale) || !(scale > 0)) {
      const_cast<BoxROI*>(this)->msgError(
          "oriented box " + std::to_string(i) + " is degenerate: p0, p1 and p2 are aligned",
          "orientedBox");
      return false;
    }
    Mat3d frame;
    frame << a, b, normal.normalized();
    boxes.push_back({p1, frame.inverse(), 0.5 * std::abs(g[9])});
  }
  return true;
}

namespace {

// p in one of the boxes (faces included); bounds taken in order whatever the box says.
bool insideAny(const std::vector<Vec6d>& boxes, const std::vector<internal::OrientedBox>& oriented,
               const Vec3d& p) {
  for (const Vec6d& b : boxes) {
    bool inside = true;
    for (int k = 0; k < 3 && inside; ++k) {
      const double lo = std::min(b[k], b[k + 3]), hi = std::max(b[k], b[k + 3]);
      inside = p[k] >= lo && p[k] <= hi;
    }
    if (inside) return true;
  }
  constexpr double slack = 1e-12;  // faces through points stay inside despite round-off
  for (const internal::OrientedBox& o : oriented) {
    const Vec3d local = o.toLocal * (p - o.corner);
    if (local[0] >= -slack && local[0] <= 1 + slack && local[1] >= -slack &&
        local[1] <= 1 + slack && std::abs(local[2]) <= o.halfDepth * (1 + slack) + slack)
      return true;
  }
  return false;
}

}  // namespace

template <class DataTypes>
bool BoxROI<DataTypes>::isInside(const Vec3d& p) const {
  std::vector<OrientedBox> oriented;
  computeOrientedBoxes(oriented);
  return insideAny(d_box.value(), oriented, p);
}

template <class DataTypes>
template <std::size_t N>
void BoxROI<DataTypes>::select(const std::vector<std::array<Index, N>>& elements,
                               Data<std::vector<unsigned>>& indices,
                               Data<std::vector<std::array<Index, N>>>& inside,
                               const std::string& field) {
  const auto& x = d_position.value();
  const auto& boxes = d_box.value();
  const auto& oriented = m_oriented;
  const bool strict = d_strict.value();
  // Written in place: the outputs keep their storage from one update to the next (an ROI on
  // moving positions updates every step, and a warm step allocates nothing).
  std::vector<unsigned>& selected = indices.edit();
  std::vector<std::array<Index, N>>& kept = inside.edit();
  selected.clear();
  kept.clear();
  std::size_t bad = 0;
  std::string firstBad;
  for (std::size_t e = 0; e < elements.size(); ++e) {
    const auto& element = elements[e];
    bool valid = true, in = true;
    Vec3d barycentre = Vec3d::Zero();
    for (Index v : element) {
      if (v >= x.size()) {
        valid = false;
        break;
      }
      const Vec3d p = toPoint3(x[v]);
      barycentre += p;
      in = in && insideAny(boxes, oriented, p);
    }
    if (!valid) {
      if (bad++ == 0) firstBad = std::to_string(e);
      continue;
    }
    if (!strict) in = insideAny(boxes, oriented, barycentre / static_cast<double>(N));
    if (in) {
      selected.push_back(static_cast<unsigned>(e));
      kept.push_back(element);
    }
  }
  if (bad) {
    const std::string text = std::to_string(bad) + " elements use points out of range of the " +
                             std::to_string(x.size()) + " positions (the first: element " +
                             firstBad + "); they are left out";
    if (!m_initialized)
      msgError(text, field);
    else
      msgWarning(text, field);
  }
}

template <class DataTypes>
void BoxROI<DataTypes>::doUpdate() {
  if (!d_doUpdate.value() && m_computedOnce) return;
  m_computedOnce = true;
  const auto& x = d_position.value();
  const auto& boxes = d_box.value();
  if (!computeOrientedBoxes(m_oriented)) return;
  std::vector<unsigned>& in = d_indices.edit();
  std::vector<unsigned>& out = d_indicesOut.edit();
  VecCoord& pointsIn = d_pointsInROI.edit();
  VecCoord& pointsOut = d_pointsOutROI.edit();
  in.clear();
  out.clear();
  pointsIn.clear();
  pointsOut.clear();
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (insideAny(boxes, m_oriented, toPoint3(x[i]))) {
      in.push_back(static_cast<unsigned>(i));
      pointsIn.push_back(x[i]);
    } else {
      out.push_back(static_cast<unsigned>(i));
      pointsOut.push_back(x[i]);
    }
  }
  d_nbIndices.setValue(static_cast<int>(in.size()));
  select(d_edges.value(), d_edgeIndices, d_edgesInROI, "edges");
  select(d_triangles.value(), d_triangleIndices, d_trianglesInROI, "triangles");
  select(d_quads.value(), d_quadIndices, d_quadInROI, "quad");
  select(d_tetrahedra.value(), d_tetrahedronIndices, d_tetrahedraInROI, "tetrahedra");
  select(d_hexahedra.value(), d_hexahedronIndices, d_hexahedraInROI, "hexahedra");
}

template class BoxROI<Vec1Types>;
template class BoxROI<Vec2Types>;
template class BoxROI<Vec3Types>;

}  // namespace stroma
