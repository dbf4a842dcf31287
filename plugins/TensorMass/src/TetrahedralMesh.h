// SPDX-License-Identifier: MIT
// What the force fields of the TensorMass plugin share besides computing forces: finding the
// tetrahedra, checking them and the material, and noticing when they change.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "SolidMechanics/kernels/IsotropicMaterial.h"
#include "SolidMechanics/kernels/LinearTetrahedron.h"
#include "TensorMass/kernels/LinearTensorMass.h"
#include "core/Base.h"
#include "core/Link.h"
#include "core/StateTypes.h"
#include "simulation/MechanicalState.h"
#include "topology/Topology.h"

namespace stroma {

/// The tetrahedra of a topology, with their rest shapes, as read at init.
class TetrahedralMesh {
 public:
  using State = MechanicalState<Vec3Types>;

  /// Finds the topology (the link when given; else, from the owner's node up, the last
  /// topology of the first node that holds tetrahedra), checks that the tetrahedra use points
  /// of `state`, and computes their shapes from the state's rest positions. A flat tetrahedron
  /// (zero volume) or an inverted one (negative volume: vertex order not SOFA's, see
  /// topology/TopologyTypes.h) is an error. Errors go to `owner`, field "topology"; returns
  /// false after one.
  bool read(Base& owner, const Link<Topology>& link, const State& state);

  /// True when the topology's elements or the state's size changed since read().
  bool changed(const State& state) const;

  /// Follows the tetrahedra removed at run time since read() (cutting: the changes the
  /// topology logged, topology/TopologyChange.h): for each change, removes the tetrahedra from
  /// tetrahedra() and shapes() (SOFA's renumbering), then calls follow(change, shapes of the
  /// removed tetrahedra in removal order). Returns false, changing nothing, when the changes
  /// cannot be followed (not logged, or the state's size changed): read() again then.
  template <class Follow>
  bool followRemovals(const State& state, Follow&& follow);

  const Topology& topology() const { return *m_topology; }
  std::size_t pointCount() const { return m_pointCount; }
  const std::vector<Tetrahedron>& tetrahedra() const { return m_tetrahedra; }
  const std::vector<fem::TetrahedronShape>& shapes() const { return m_shapes; }
  const std::vector<Vec3d>& restPositions() const { return m_restPositions; }

  /// The mesh with the topology's edges and faces, for the tensor-mass builders.
  tensormass::TensorMassMesh tensorMassMesh() const;

 private:
  const Topology* m_topology = nullptr;
  std::uint64_t m_revision = 0;
  std::size_t m_pointCount = 0;
  std::vector<Tetrahedron> m_tetrahedra;
  std::vector<fem::TetrahedronShape> m_shapes;
  std::vector<Vec3d> m_restPositions;
};

template <class Follow>
bool TetrahedralMesh::followRemovals(const State& state, Follow&& follow) {
  if (!m_topology || state.size() != m_pointCount) return false;
  const auto changes = m_topology->changesSince(m_revision);
  if (!changes) return false;
  std::size_t count = m_tetrahedra.size();
  for (const TopologyChange& change : *changes) {
    if (change.tetrahedra.sizeBefore != count) return false;
    count = change.tetrahedra.sizeAfter;
  }
  std::vector<fem::TetrahedronShape> removedShapes;
  for (const TopologyChange& change : *changes) {
    removedShapes.clear();
    for (Index t : change.tetrahedra.removed) {
      removedShapes.push_back(m_shapes[t]);
      m_shapes[t] = m_shapes.back();
      m_shapes.pop_back();
      m_tetrahedra[t] = m_tetrahedra.back();
      m_tetrahedra.pop_back();
    }
    follow(change, std::span<const fem::TetrahedronShape>(removedShapes));
  }
  m_revision = m_topology->revision();
  return true;
}

/// The Lame parameters of youngModulus and poissonRatio, or nothing after reporting, on
/// `owner` and naming the field, a value out of range (E > 0, -1 < nu < 0.5): an error at init,
/// a warning for a change made while running (which is then not applied).
std::optional<fem::LameParameters> readIsotropicMaterial(Base& owner, double youngModulus,
                                                         double poissonRatio, bool atInit);

/// "3, 17, 42" or "3, 17, 42, ... (12 in all)": indices for messages, the first 10.
std::string describeIndices(const std::vector<Index>& indices);

}  // namespace stroma
