// SPDX-License-Identifier: MIT
#include "MultiresolutionGridTopology.h"

namespace stroma {

namespace {
constexpr double kMaxCoarseCells = 1e6;  // 8e6 fine cells at most: a scene must not exhaust memory
}

void MultiresolutionGridTopology::init() {
  m_tNodes.clear();
  const Vec3i n = d_n.value();
  const Vec3d min = d_min.value(), max = d_max.value();
  if ((n.array() < 2).any()) {
    msgError("needs at least 2 points per axis, got " + std::to_string(n.x()) + " " +
                 std::to_string(n.y()) + " " + std::to_string(n.z()),
             "n");
    return;
  }
  const double cellCount = double(n.x() - 1) * (n.y() - 1) * (n.z() - 1);
  if (cellCount > kMaxCoarseCells) {
    msgError("would make " + std::to_string(cellCount) + " coarse cells (at most " +
                 std::to_string(kMaxCoarseCells) + ", as the refined ones may be 8 times more)",
             "n");
    return;
  }
  if (!((max - min).array() > 0).all()) {
    msgError("max must be above min on every axis", "max");
    return;
  }
  const std::array<int, 3> nodes{n.x(), n.y(), n.z()};
  const auto cells = static_cast<std::size_t>(cellCount);
  std::vector<char> refined(cells, 0);

  // Which cells are refined: listed, or centred in a box.
  for (unsigned c : d_refineCells.value()) {
    if (c >= cells) {
      msgError("cell " + std::to_string(c) + " is out of range of the " + std::to_string(cells) +
                   " coarse cells",
               "refineCells");
      continue;
    }
    refined[c] = 1;
  }
  const Vec3d width = (max - min).cwiseQuotient(Vec3d(n.x() - 1, n.y() - 1, n.z() - 1));
  for (const Vec6d& box : d_refineBoxes.value()) {
    if (box[0] > box[3] || box[1] > box[4] || box[2] > box[5])
      msgWarning("a box has a min above its max: it refines nothing", "refineBoxes");
    std::size_t c = 0;
    for (int k = 0; k < n.z() - 1; ++k)
      for (int j = 0; j < n.y() - 1; ++j)
        for (int i = 0; i < n.x() - 1; ++i, ++c) {
          const Vec3d centre = min + width.cwiseProduct(Vec3d(i + 0.5, j + 0.5, k + 0.5));
          if (centre.x() >= box[0] && centre.y() >= box[1] && centre.z() >= box[2] &&
              centre.x() <= box[3] && centre.y() <= box[4] && centre.z() <= box[5])
            refined[c] = 1;
        }
  }

  multiresolution::MixedGrid grid = multiresolution::makeMixedGrid(nodes, min, max, refined);
  d_position.setValue(std::move(grid.points));
  d_hexahedra.setValue(std::move(grid.hexahedra));
  d_cellLevels.setValue(std::move(grid.cellLevels));
  std::vector<unsigned> tNodeIndices;
  for (const auto& t : grid.tNodes) tNodeIndices.push_back(t.node);
  d_tNodes.setValue(std::move(tNodeIndices));
  m_tNodes = std::move(grid.tNodes);
}

}  // namespace stroma
