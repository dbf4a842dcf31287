// SPDX-License-Identifier: MIT
// Splitting hexahedra into tetrahedra so that neighbours share their faces' diagonals (a
// conforming tetrahedral mesh). Vertex orders of TopologyTypes.h; every tetrahedron made from a
// positive hexahedron is positive.
//
// Six tetrahedra (the Kuhn/Freudenthal split): the paths from vertex 0 to the opposite vertex 6
// along three edges, (0,1,2,6) (0,2,3,6) (0,3,7,6) (0,7,4,6) (0,4,5,6) (0,5,1,6). Each face is
// cut by its diagonal through vertex 0 or 6, so identical neighbours match. With `mirrors`, a
// hexahedron is first mirrored across its middle planes (bit 1: u, 2: v, 4: w), which moves the
// main diagonal; mirroring every other hexahedron of a grid along each axis (alternatingMirrors)
// keeps the faces matched and removes the split's directional bias (SOFA's `swapping`).
//
// Five tetrahedra: a central tetrahedron and four corners. The two variants use opposite face
// diagonals, so neighbours must alternate; splitHexahedraInFive chooses each variant from a
// neighbour already split, across shared faces.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "RegularGrid.h"
#include "topology/TopologyTypes.h"

namespace stroma {

/// Six tetrahedra per hexahedron, in order. `mirrors` (one per hexahedron, or empty) selects
/// the mirrored splits.
std::vector<Tetrahedron> splitHexahedraInSix(std::span<const Hexahedron> hexahedra,
                                             std::span<const std::uint8_t> mirrors = {});

/// The mirror bits that alternate along each axis of a grid of `cells` hexahedra (x fastest):
/// u when i is odd, v when j is odd, w when k is odd.
std::vector<std::uint8_t> alternatingMirrors(const GridSize& cells);

/// The cells per axis when `hexahedra` are exactly those of a regular grid of points in
/// SOFA's numbering (RegularGrid.h), whatever container holds them; nullopt otherwise.
std::optional<GridSize> findGridCells(std::span<const Hexahedron> hexahedra);

struct FiveSplit {
  std::vector<Tetrahedron> tetrahedra;  ///< five per hexahedron, in order
  /// Shared faces where the neighbours' diagonals could not be matched (a mesh whose hexahedra
  /// cannot alternate, such as three around an edge): the result is not conforming there.
  std::size_t mismatchedFaces = 0;
};
FiveSplit splitHexahedraInFive(std::span<const Hexahedron> hexahedra);

}  // namespace stroma
