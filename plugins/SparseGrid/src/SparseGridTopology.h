// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <vector>

#include "ImageGrid.h"
#include "SparseGrid.h"
#include "core/Data.h"
#include "topology/Topology.h"

namespace stroma {

/// The hexahedra of a regular grid around a triangle surface, empty cells dropped (SOFA's
/// SparseGridTopology; Nesme 2008, seed 001, ch. 3 sec. 1). The classification (boundary cells
/// crossed by the surface, the outside flood-filled from the border, full cells enclosed) and
/// the measured volume fraction of each boundary cell are those of SparseGrid.h.
///
/// The surface: `fileTopology` (or `filename`; any mesh file MeshIO reads: OBJ, STL, VTK, Gmsh),
/// else `position` with `triangles` and/or `quads` given here, by links or `src="@loader"`;
/// quads are split in two triangles. Those given values are the input: once the grid is made,
/// `position` holds the grid's points and `triangles`/`quads` are emptied.
///
/// The grid: `n` points per axis (n - 1 cells, as SOFA), or n = ceil(side / cellWidth) + 1 (as
/// SOFA: cells at most `cellWidth` wide); the box is `min`/`max` when given (min != max), else
/// the surface's bounding box grown by 1 % of each side at both ends (as SOFA), so that the
/// surface never lies on the border. `nbVirtualFinerLevels` = L classifies and measures on a grid
/// 2^L times finer, then groups the cells 2^L x 2^L x 2^L (SparseGrid.h, coarsenSparseGrid):
/// thin parts and holes are resolved at the finer size; the hexahedra are those of `n`.
///
/// Outputs, made on first read (a DataEngine): `position` (kept cells' corners, shared ones
/// once), `hexahedra` (TopologyTypes.h order, positive), and per hexahedron `cellTypes` and
/// `volumeFractions`; numbered as SOFA's SparseGridTopology (SparseGrid.h), so that scenes that
/// name points by index keep working.
///
/// From a volume image instead (`fileImage`, or `filename`/`fileTopology` ending in .mhd, .mha,
/// .nrrd, .nhdr, or SOFA's .raw with `dataResolution` and `voxelSize`): the inside voxels
/// (`labels`, else value >= `threshold`, else value > 0) fill their boxes, and each cell is empty,
/// full or boundary with its exact filled fraction (ImageGrid.h). The default box is the
/// image's (the union of its voxel boxes).
class SparseGridTopology final : public Topology, public DataEngine {
 public:
  Data<Vec3i> d_n{this, "n", Vec3i(2, 2, 2),
                  "Grid points along x, y and z (each >= 2: n - 1 cells), as SOFA's."};
  Data<Vec3d> d_min{this,
                    "min",
                    Vec3d::Zero(),
                    "Lower corner of the grid; with min == max (default) the surface's bounding "
                    "box, each side grown by 1 %.",
                    {.unit = "m"}};
  Data<Vec3d> d_max{
      this, "max", Vec3d::Zero(), "Upper corner of the grid (see min).", {.unit = "m"}};
  Data<double> d_cellWidth{
      this,
      "cellWidth",
      0.0,
      "When > 0, replaces n: ceil(side / cellWidth) cells per axis, each at most "
      "cellWidth wide (as SOFA).",
      {.unit = "m", .min = 0.0}};
  Data<int> d_nbVirtualFinerLevels{
      this,
      "nbVirtualFinerLevels",
      0,
      "Classify and measure on a grid 2^L times finer, then group 2^L x 2^L x 2^L cells.",
      {.min = 0.0, .max = 8.0}};
  Data<int> d_fractionSamples{this,
                              "fractionSamples",
                              4,
                              "Sub-cells per axis measuring each boundary cell's filled volume "
                              "fraction (not in SOFA).",
                              {.min = 1.0, .max = 16.0}};
  Data<FileName> d_fileTopology{this,
                                "fileTopology",
                                {},
                                "Surface mesh file (OBJ, STL, VTK, Gmsh): its triangles and quads.",
                                {.autoLink = false}};
  Data<FileName> d_filename{
      this, "filename", {}, "SOFA's other name for fileTopology.", {.autoLink = false}};
  Data<FileName> d_fileImage{this,
                             "fileImage",
                             {},
                             "Volume image file (MetaImage .mhd/.mha, NRRD .nrrd/.nhdr): the grid "
                             "of its inside voxels (see threshold, labels) instead of a surface.",
                             {.autoLink = false}};
  Data<double> d_threshold{this, "threshold", 0.0,
                           "Image voxels with a value >= threshold are inside; when not given, "
                           "those > 0 (ignored when labels are given)."};
  Data<std::vector<double>> d_labels{
      this, "labels", {}, "Values of the image voxels that are inside (a labelled image)."};
  Data<Vec3i> d_dataResolution{this, "dataResolution", Vec3i(0, 0, 0),
                               "Voxels along x, y and z of a .raw file of 8-bit voxels (SOFA's)."};
  Data<Vec3d> d_voxelSize{this,
                          "voxelSize",
                          Vec3d(1, 1, 1),
                          "Size of a voxel of a .raw file along x, y and z (SOFA's); the image "
                          "covers [0, dataResolution * voxelSize].",
                          {.unit = "m"}};
  Data<std::vector<Vec3d>> d_vertices{this,
                                      "vertices",
                                      {},
                                      "Input surface points (SOFA's name); position given in the "
                                      "scene fills it.",
                                      {.unit = "m", .autoLink = false}};
  Data<std::vector<Triangle>> d_inputTriangles{
      this,
      "input_triangles",
      {},
      "Input surface triangles (SOFA's name); triangles given in the scene fill it.",
      {.autoLink = false}};
  Data<std::vector<Quad>> d_inputQuads{
      this,
      "input_quads",
      {},
      "Input surface quads (SOFA's name); quads given in the scene fill it.",
      {.autoLink = false}};
  Data<std::vector<sparsegrid::CellType>> d_cellTypes{
      this,
      "cellTypes",
      {},
      "Type of each hexahedron (nbHexahedra): boundary (crossed by the surface) or full.",
      {.output = true}};
  Data<std::vector<double>> d_volumeFractions{
      this,
      "volumeFractions",
      {},
      "Filled volume fraction of each hexahedron (nbHexahedra), in [0, 1]: 1 for full cells, "
      "measured on sub-cells for boundary cells.",
      {.output = true}};
  Data<bool> d_drawHexahedra{this, "drawHexahedra", false, "Draw the hexahedra (viewers only)."};
  Data<bool> d_drawEdges{this, "drawEdges", false, "Draw the edges (viewers only)."};
  Data<bool> d_drawQuads{this, "drawQuads", false, "Draw the quads (viewers only)."};

  SparseGridTopology();

  void init() override;
  void reinit() override;

  /// The grid as built (box, kept cells, types, fractions, points, hexahedra), for the
  /// components that need more than the Topology lists (coarser levels: coarsenSparseGrid).
  const sparsegrid::SparseGrid& grid() const;
  const sparsegrid::SparseGrid* sparseGrid() const override { return &grid(); }

  /// The virtual finer levels, finest first (empty when nbVirtualFinerLevels = 0).
  const std::vector<sparsegrid::FinerLevel>& finerLevels() const;
  std::span<const sparsegrid::FinerLevel> sparseGridFinerLevels() const override {
    return finerLevels();
  }

 protected:
  void doUpdate() override;

 private:
  /// Moves the surface given through position/triangles/quads (values or links) to the input
  /// fields, so that the outputs can hold the grid.
  void adoptSurface();
  /// The surface's points and triangles (quads split); false after reporting an error.
  bool readSurface(std::vector<Vec3d>& points, std::vector<Triangle>& triangles);
  /// The box around the surface (the scene's, or the bounding box with a margin); false after
  /// reporting an error.
  bool surfaceBounds(const std::vector<Vec3d>& points, Vec3d& lo, Vec3d& hi);
  /// The box of cells on [lo, hi] (n or cellWidth, nbVirtualFinerLevels), refused when the build
  /// would need too much memory (`image`: the image it is built from, else a surface); false
  /// after reporting an error.
  bool computeBox(Vec3d lo, Vec3d hi, const image::VolumeImage* image, sparsegrid::GridBox& box);
  /// The file of a volume image given (fileImage, or filename/fileTopology with an image or
  /// .raw extension) and the field naming it; empty when the grid is built around a surface.
  std::string imageFile(const char*& field) const;
  /// Reads the image and selects its inside voxels; false after reporting an error.
  bool readImage(const std::string& path, const char* field, image::VolumeImage& image,
                 std::vector<std::uint8_t>& inside);
  void clearOutputs();

  sparsegrid::SparseGrid m_grid;
  std::vector<sparsegrid::FinerLevel> m_finerLevels;
  std::vector<BaseData*> m_inputs;
  std::vector<std::uint64_t> m_builtVersions;  ///< input versions of the last build
  bool m_adopted = false;
};

}  // namespace stroma
