// SPDX-License-Identifier: MIT
// What the FEM force fields share about their mesh: finding the topology that holds their
// elements, checking the elements against the state, and naming bad elements in messages.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "core/Base.h"
#include "core/Link.h"
#include "topology/Topology.h"

namespace stroma {

/// The kind of elements a force field computes on.
enum class FemElementKind { tetrahedra, hexahedra };

/// The topology of `link` when given; else, from the owner's node up to the root, the last
/// topology of the first node that has one holding elements of `kind` (a node may hold a grid
/// and, after a Hexa2TetraTopologicalMapping, a tetrahedron container: the tetrahedra are in
/// the latter). For tetrahedra, a topology holding only hexahedra is taken too (the caller
/// splits them), as SOFA's TetrahedronFEMForceField does. Reports an error on `owner` (field
/// "topology") and returns nullptr when there is none.
const Topology* findFemTopology(Base& owner, const Link<Topology>& link, FemElementKind kind);

/// The six positive tetrahedra of each hexahedron around its 0-6 diagonal (Freudenthal-Kuhn
/// split): conforming across hexahedra that share faces with the same vertex order, as the
/// hexahedra of a RegularGridTopology do.
std::vector<Tetrahedron> splitHexahedraIntoTetrahedra(std::span<const Hexahedron> hexahedra);

/// Reports (error, field "topology") the elements that use a point >= pointCount: how many,
/// the first few with their indices. Returns false when there is one.
template <std::size_t N>
bool checkElementIndices(Base& owner, const std::string& what,
                         std::span<const std::array<Index, N>> elements, std::size_t pointCount);

/// "3, 17, 42" or "3, 17, 42, ... (12 in all)": element indices for messages, the first 10.
std::string describeIndices(std::span<const Index> indices);

}  // namespace stroma
