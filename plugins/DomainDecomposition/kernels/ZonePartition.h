// SPDX-License-Identifier: MIT
// Element-based partitions of a tetrahedral mesh into zones (seed 000, figure 4.2 b): every
// tetrahedron belongs to exactly one zone, and the nodes that elements of several zones share
// are the interface nodes, which belong to each of those zones. Three sources: a zone index
// per element (element groups of a mesh file, or listed), boxes (the zone of the first box
// holding the element's barycentre), or METIS (METIS_PartMeshDual: zones of balanced element
// counts, cutting few faces).
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace stroma::domaindecomposition {

/// Node indices of one tetrahedron (the layout of stroma::Tetrahedron).
using TetrahedronNodes = std::array<std::uint32_t, 4>;
/// An axis-aligned box: xmin ymin zmin xmax ymax zmax (m).
using Box = Eigen::Matrix<double, 6, 1>;

/// The zone of each element (-1: none yet), from the first of `boxes` that holds the
/// element's barycentre (boundary included).
std::vector<int> partitionFromBoxes(const std::vector<Eigen::Vector3d>& points,
                                    const std::vector<TetrahedronNodes>& tetrahedra,
                                    const std::vector<Box>& boxes);

/// One zone per distinct group > 0 (the physical groups of a mesh file), numbered in increasing
/// order of the groups; an element of group 0 or below (in no group) gets -1, which
/// checkPartition reports. Sets `zoneCount`.
std::vector<int> zonesFromGroups(const std::vector<int>& groupOfElement, int& zoneCount);

/// `zoneCount` zones by METIS_PartMeshDual (elements adjacent through a face, 3 shared nodes).
/// zoneCount 1 gives one zone. Empty result and `error` when METIS fails.
std::vector<int> partitionWithMetis(const std::vector<TetrahedronNodes>& tetrahedra,
                                    std::size_t pointCount, int zoneCount, std::string& error);

/// Empty when every element has a zone in [0, zoneCount) and every zone has an element;
/// otherwise a message naming the elements in no zone (or out of range) and the empty zones.
std::string checkPartition(const std::vector<int>& zoneOfElement, std::size_t elementCount,
                           int zoneCount);

/// Nodes of each zone (sorted, global indices): those of its elements.
std::vector<std::vector<int>> computeZoneNodes(const std::vector<TetrahedronNodes>& tetrahedra,
                                               const std::vector<int>& zoneOfElement, int zoneCount,
                                               std::size_t pointCount);

/// "3, 7, 12" (at most `limit` values, then "... (n in all)").
std::string describeList(const std::vector<int>& values, std::size_t limit = 12);

}  // namespace stroma::domaindecomposition
