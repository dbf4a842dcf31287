// SPDX-License-Identifier: MIT
#include "SphereROI.h"

#include <cmath>
#include <numbers>

#include "RoiInputs.h"

namespace stroma {

SphereROI::SphereROI() {
  for (BaseData* input : std::initializer_list<BaseData*>{
           &d_centers, &d_radii, &d_direction, &d_normal, &d_edgeAngle, &d_triAngle, &d_position,
           &d_edges, &d_triangles, &d_quads, &d_tetrahedra})
    addInput(input);
  for (BaseData* output : std::initializer_list<BaseData*>{
           &d_indices, &d_pointsInROI, &d_edgeIndices, &d_edgesInROI, &d_triangleIndices,
           &d_trianglesInROI, &d_quadIndices, &d_quadsInROI, &d_tetrahedronIndices,
           &d_tetrahedraInROI, &d_nbIndices})
    addOutput(output);
}

void SphereROI::init() {
  const std::size_t centers = d_centers.value().size(), radii = d_radii.value().size();
  if (centers == 0) {
    msgError("no sphere given: set centers (and radii)", "centers");
    return;
  }
  if (radii != centers && radii != 1) {
    msgError(std::to_string(centers) + " centers and " + std::to_string(radii) +
                 " radii: give one radius per center, or one for all",
             "radii");
    return;
  }
  roi::findDefaultPosition(*this, d_position);
  if (const Topology* topology = node() ? node()->get<Topology>() : nullptr) {
    roi::followTopology(d_edges, d_computeEdges.value(), topology->d_edges);
    roi::followTopology(d_triangles, d_computeTriangles.value(), topology->d_triangles);
    roi::followTopology(d_quads, d_computeQuads.value(), topology->d_quads);
    roi::followTopology(d_tetrahedra, d_computeTetrahedra.value(), topology->d_tetrahedra);
  }
  setDirty();
  updateIfDirty();
}

template <class Element>
int SphereROI::sphereHolding(const Element& element) const {
  const auto& x = d_position.value();
  const auto& c = d_centers.value();
  for (Index v : element)
    if (v >= x.size()) return -1;
  for (std::size_t j = 0; j < c.size(); ++j) {
    bool all = true;
    for (Index v : element) all = all && (x[v] - c[j]).norm() <= m_radii[j];
    if (all) return static_cast<int>(j);
  }
  return -1;
}

template <class Element>
void SphereROI::select(const std::vector<Element>& elements, Data<std::vector<unsigned>>& indices,
                       Data<std::vector<Element>>& inside, const char* field) {
  const auto& x = d_position.value();
  // Written in place: a selection that follows moving points allocates nothing once warm.
  std::vector<unsigned>& selected = indices.edit();
  std::vector<Element>& kept = inside.edit();
  selected.clear();
  kept.clear();
  std::size_t bad = 0;
  const double edgeCos = std::cos(d_edgeAngle.value() * std::numbers::pi / 180);
  const double triangleCos = std::cos(d_triAngle.value() * std::numbers::pi / 180);
  for (std::size_t e = 0; e < elements.size(); ++e) {
    const Element& element = elements[e];
    bool valid = true;
    for (Index v : element) valid = valid && v < x.size();
    if (!valid) {
      ++bad;
      continue;
    }
    if (sphereHolding(element) < 0) continue;
    if constexpr (std::tuple_size_v<Element> == 2) {
      if (d_edgeAngle.value() > 0) {
        const Vec3d u = (x[element[1]] - x[element[0]]).normalized();
        if (std::abs(u.dot(d_direction.value().normalized())) < std::abs(edgeCos)) continue;
      }
    }
    if constexpr (std::tuple_size_v<Element> == 3) {
      if (d_triAngle.value() > 0) {
        const Vec3d n = (x[element[2]] - x[element[0]])
                            .cross(x[element[1]] - x[element[0]])
                            .normalized();
        if (n.dot(d_normal.value().normalized()) < triangleCos) continue;
      }
    }
    selected.push_back(static_cast<unsigned>(e));
    kept.push_back(element);
  }
  if (bad)
    msgWarning(std::to_string(bad) + " elements use points out of range of the " +
                   std::to_string(x.size()) + " positions; they are left out",
               field);
}

void SphereROI::doUpdate() {
  const auto& c = d_centers.value();
  const auto& r = d_radii.value();
  // One radius per center; a count that init() refused selects nothing (radius -1).
  m_radii.resize(c.size());
  for (std::size_t j = 0; j < c.size(); ++j)
    m_radii[j] = r.size() == c.size() ? r[j] : r.size() == 1 ? r[0] : -1.0;
  const auto& x = d_position.value();
  std::vector<unsigned>& in = d_indices.edit();
  std::vector<Vec3d>& points = d_pointsInROI.edit();
  in.clear();
  points.clear();
  for (std::size_t i = 0; i < x.size(); ++i)
    if (sphereHolding(std::array<Index, 1>{static_cast<Index>(i)}) >= 0) {
      in.push_back(static_cast<unsigned>(i));
      points.push_back(x[i]);
    }
  d_nbIndices.setValue(static_cast<int>(in.size()));
  select(d_edges.value(), d_edgeIndices, d_edgesInROI, "edges");
  select(d_triangles.value(), d_triangleIndices, d_trianglesInROI, "triangles");
  select(d_quads.value(), d_quadIndices, d_quadsInROI, "quads");
  select(d_tetrahedra.value(), d_tetrahedronIndices, d_tetrahedraInROI, "tetrahedra");
}

}  // namespace stroma
