// SPDX-License-Identifier: MIT
#pragma once

#include <vector>

#include "MultiresolutionGrid.h"
#include "topology/Topology.h"

namespace stroma {

/// The hexahedra of a box grid mixing two nested resolutions (seed 001, chapter 4 section 4): a
/// regular grid of n points per axis over [min, max] whose cells are refined into 2 x 2 x 2
/// children where asked (cells whose centre lies in one of `refineBoxes`, or listed in
/// `refineCells`). The refined region is conforming inside; on its border the fine nodes that lie
/// on an edge or a face of a kept coarse cell are T-nodes (`tNodes`), which TNodeConstraint keeps
/// interpolated from their parents. One level of refinement: a refined cell's children are not
/// refined again.
class MultiresolutionGridTopology final : public Topology {
 public:
  Data<Vec3i> d_n{this,
                  "n",
                  Vec3i(2, 2, 2),
                  "Points of the coarse grid along x, y and z (each >= 2).",
                  {.min = 2.0, .max = 1e4}};
  Data<Vec3d> d_min{this, "min", Vec3d::Zero(), "Lower corner of the grid.", {.unit = "m"}};
  Data<Vec3d> d_max{this, "max", Vec3d::Ones(), "Upper corner of the grid.", {.unit = "m"}};
  Data<std::vector<Vec6d>> d_refineBoxes{
      this,
      "refineBoxes",
      {},
      "Boxes (nbBoxes x 6: xmin ymin zmin xmax ymax zmax); a coarse cell whose centre is in one "
      "is refined into 2 x 2 x 2 cells.",
      {.unit = "m"}};
  Data<std::vector<unsigned>> d_refineCells{
      this, "refineCells", {}, "Coarse cells to refine, by index (x fastest)."};
  Data<std::vector<int>> d_cellLevels{
      this,
      "cellLevels",
      {},
      "Per hexahedron: 0 a coarse cell, 1 a refined child (output).",
      {.output = true}};
  Data<std::vector<unsigned>> d_tNodes{this,
                                       "tNodes",
                                       {},
                                       "The T-nodes, fine nodes on a coarse edge or face (output).",
                                       {.output = true}};

  void init() override;
  void reinit() override { init(); }

  /// The T-nodes with their parents and weights (after init).
  const std::vector<multiresolution::TNode>& tNodes() const { return m_tNodes; }

 private:
  std::vector<multiresolution::TNode> m_tNodes;
};

}  // namespace stroma
