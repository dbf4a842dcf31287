// SPDX-License-Identifier: MIT
#include "DomainDecomposition/kernels/ZonePartition.h"

#include <algorithm>

#if defined(STROMA_HAVE_METIS)
#include <metis.h>
#endif

namespace stroma::domaindecomposition {

std::vector<int> partitionFromBoxes(const std::vector<Eigen::Vector3d>& points,
                                    const std::vector<TetrahedronNodes>& tetrahedra,
                                    const std::vector<Box>& boxes) {
  std::vector<int> zone(tetrahedra.size(), -1);
  for (std::size_t e = 0; e < tetrahedra.size(); ++e) {
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    bool inRange = true;
    for (std::uint32_t p : tetrahedra[e]) {
      if (p >= points.size()) {
        inRange = false;
        break;
      }
      centre += points[p] / 4.0;
    }
    if (!inRange) continue;
    for (std::size_t b = 0; b < boxes.size(); ++b) {
      const Box& box = boxes[b];
      if ((centre.array() >= box.head<3>().array()).all() &&
          (centre.array() <= box.tail<3>().array()).all()) {
        zone[e] = static_cast<int>(b);
        break;
      }
    }
  }
  return zone;
}

std::vector<int> zonesFromGroups(const std::vector<int>& groupOfElement, int& zoneCount) {
  std::vector<int> groups;
  for (int g : groupOfElement)
    if (g > 0) groups.push_back(g);
  std::sort(groups.begin(), groups.end());
  groups.erase(std::unique(groups.begin(), groups.end()), groups.end());
  zoneCount = static_cast<int>(groups.size());
  std::vector<int> zones(groupOfElement.size(), -1);
  for (std::size_t e = 0; e < groupOfElement.size(); ++e)
    if (groupOfElement[e] > 0)
      zones[e] = static_cast<int>(std::lower_bound(groups.begin(), groups.end(), groupOfElement[e]) -
                                  groups.begin());
  return zones;
}

std::vector<int> partitionWithMetis(const std::vector<TetrahedronNodes>& tetrahedra,
                                    std::size_t pointCount, int zoneCount, std::string& error) {
  if (zoneCount < 1 || tetrahedra.empty()) {
    error = "METIS needs at least one element and one zone";
    return {};
  }
  if (zoneCount == 1) return std::vector<int>(tetrahedra.size(), 0);
#if !defined(STROMA_HAVE_METIS)
  (void)pointCount;
  error = "Stroma was built without METIS (Debian libmetis-dev): no automatic partition";
  return {};
#else
  idx_t ne = static_cast<idx_t>(tetrahedra.size());
  idx_t nn = static_cast<idx_t>(pointCount);
  std::vector<idx_t> eptr(tetrahedra.size() + 1), eind;
  eind.reserve(4 * tetrahedra.size());
  for (std::size_t e = 0; e < tetrahedra.size(); ++e) {
    eptr[e] = static_cast<idx_t>(4 * e);
    for (std::uint32_t p : tetrahedra[e]) eind.push_back(static_cast<idx_t>(p));
  }
  eptr.back() = static_cast<idx_t>(eind.size());
  idx_t ncommon = 3;  // face neighbours
  idx_t nparts = zoneCount;
  idx_t objval = 0;
  idx_t options[METIS_NOPTIONS];
  METIS_SetDefaultOptions(options);
  options[METIS_OPTION_SEED] = 1;  // the same partition at every run
  std::vector<idx_t> epart(tetrahedra.size()), npart(pointCount);
  const int status =
      METIS_PartMeshDual(&ne, &nn, eptr.data(), eind.data(), nullptr, nullptr, &ncommon, &nparts,
                         nullptr, options, &objval, epart.data(), npart.data());
  if (status != METIS_OK) {
    error = "METIS_PartMeshDual failed (status " + std::to_string(status) + ")";
    return {};
  }
  return std::vector<int>(epart.begin(), epart.end());
#endif
}

std::string checkPartition(const std::vector<int>& zoneOfElement, std::size_t elementCount,
                           int zoneCount) {
  std::string message;
  if (zoneOfElement.size() != elementCount)
    return std::to_string(zoneOfElement.size()) + " zone indices for " +
           std::to_string(elementCount) + " tetrahedra (one per tetrahedron expected)";
  std::vector<int> inNoZone;
  std::vector<int> count(static_cast<std::size_t>(std::max(zoneCount, 0)), 0);
  for (std::size_t e = 0; e < zoneOfElement.size(); ++e) {
    const int z = zoneOfElement[e];
    if (z < 0 || z >= zoneCount)
      inNoZone.push_back(static_cast<int>(e));
    else
      ++count[z];
  }
  if (!inNoZone.empty())
    message = std::to_string(inNoZone.size()) + " tetrahedra are in no zone: elements " +
              describeList(inNoZone);
  std::vector<int> empty;
  for (int z = 0; z < zoneCount; ++z)
    if (count[z] == 0) empty.push_back(z);
  if (!empty.empty())
    message +=
        std::string(message.empty() ? "" : "; ") + "zones with no element: " + describeList(empty);
  return message;
}

std::vector<std::vector<int>> computeZoneNodes(const std::vector<TetrahedronNodes>& tetrahedra,
                                               const std::vector<int>& zoneOfElement, int zoneCount,
                                               std::size_t pointCount) {
  std::vector<std::vector<char>> used(zoneCount, std::vector<char>(pointCount, 0));
  for (std::size_t e = 0; e < tetrahedra.size(); ++e)
    for (std::uint32_t p : tetrahedra[e]) used[zoneOfElement[e]][p] = 1;
  std::vector<std::vector<int>> nodes(zoneCount);
  for (int z = 0; z < zoneCount; ++z)
    for (std::size_t p = 0; p < pointCount; ++p)
      if (used[z][p]) nodes[z].push_back(static_cast<int>(p));
  return nodes;
}

std::string describeList(const std::vector<int>& values, std::size_t limit) {
  std::string text;
  for (std::size_t i = 0; i < values.size() && i < limit; ++i)
    text += (i ? ", " : "") + std::to_string(values[i]);
  if (values.size() > limit) text += ", ... (" + std::to_string(values.size()) + " in all)";
  return text;
}

}  // namespace stroma::domaindecomposition
