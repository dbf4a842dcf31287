// SPDX-License-Identifier: MIT
// What the force fields of the TensorMass plugin share besides computing forces: finding the
// tetrahedra, checking them and the material, and noticing when they change.
#pragma once

#include <cstdint>
#include <optional>
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

/// The Lame parameters of youngModulus and poissonRatio, or nothing after reporting, on
/// `owner` and naming the field, a value out of range (E > 0, -1 < nu < 0.5): an error at init,
/// a warning for a change made while running (which is then not applied).
std::optional<fem::LameParameters> readIsotropicMaterial(Base& owner, double youngModulus,
                                                         double poissonRatio, bool atInit);

/// "3, 17, 42" or "3, 17, 42, ... (12 in all)": indices for messages, the first 10.
std::string describeIndices(const std::vector<Index>& indices);

}  // namespace stroma
