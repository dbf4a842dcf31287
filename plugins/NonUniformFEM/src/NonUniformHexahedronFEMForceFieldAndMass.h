// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "core/FunctionRef.h"
#include "HexahedronCondensation.h"
#include "SolidMechanics/kernels/CorotationalHexahedron.h"
#include "SolidMechanics/src/FemMethod.h"
#include "core/StateTypes.h"
#include "simulation/Mass.h"
#include "topology/Topology.h"

namespace stroma {

/// Corotational hexahedra of a sparse grid whose stiffness and mass are condensed from the
/// grid's nested finer levels (SOFA's NonUniformHexahedronFEMForceFieldAndMass; Nesme thesis,
/// seed 001, ch. 4 sec. 3). On the finest level used, each cell is a full trilinear hexahedron
/// weighted by its measured filled volume fraction (and, with an image, by its own Young's
/// modulus and density); each coarser cell gets K = sum_c L_c^T K_c L_c and M = sum_c L_c^T
/// M_c L_c from its non-empty children (HexahedronCondensation.h), up to the simulated grid
/// (Topology::sparseGrid()). The simulated hexahedra then behave as HexahedronFEMForceFieldAndMass
/// with that rest stiffness and mass:
///
///   f = -R K (R^T x - X) + m g,   df = -R K R^T dx,   M consistent (or lumped: row sums)
///
/// with R found by `method` as HexahedronFEMForceField does (large: QR frame of the averaged
/// edges; polar: polar decomposition of F at the centre).
class NonUniformHexahedronFEMForceFieldAndMass final : public Mass<Vec3Types> {
 public:
  Data<double> d_youngModulus{this,
                              "youngModulus",
                              5000.0,
                              "Young's modulus of the material (> 0), for every cell unless "
                              "imageFile and youngModulusTransfer give one per finest cell.",
                              {.unit = "Pa", .min = 0.0}};
  Data<double> d_poissonRatio{this,
                              "poissonRatio",
                              0.45,
                              "Poisson's ratio, -1 < nu < 0.5 (0.5: incompressible, refused).",
                              {.min = -1.0, .max = 0.5}};
  Data<FemMethod> d_method{
      this, "method", FemMethod::large,
      "Rotation of each simulated hexahedron: small (none), large (Gram-Schmidt frame of the "
      "averaged edges), polar (polar decomposition of F at the centre), svd; qr is large, polar2 "
      "polar."};
  Data<double> d_density{this,
                         "density",
                         1.0,
                         "Mass density (> 0), for every cell unless imageFile and densityTransfer "
                         "give one per finest cell.",
                         {.unit = "kg/m^3", .min = 0.0}};
  Data<bool> d_lumpedMass{this, "lumpedMass", false,
                          "Lump the condensed mass on the vertices (row sums): a diagonal mass; "
                          "otherwise the condensed consistent mass."};
  Data<int> d_nbVirtualFinerLevels{
      this,
      "nbVirtualFinerLevels",
      0,
      "Finer levels of the sparse grid the stiffness and mass are condensed from (at most the "
      "SparseGridTopology's nbVirtualFinerLevels; 0: each hexahedron is one full element "
      "weighted by its filled fraction).",
      {.min = 0.0, .max = 8.0}};
  Data<double> d_minimumFraction{
      this,
      "minimumFraction",
      1e-3,
      "Smallest filled fraction of a kept finest cell (the finite cell method's alpha): a cell "
      "the surface crosses but whose sample points all fell outside counts as this fraction, "
      "so that no point is left without mass and stiffness (a singular system). 0 keeps the "
      "measured fractions as they are.",
      {.min = 0.0, .max = 1.0}};
  Data<FileName> d_imageFile{this,
                             "imageFile",
                             {},
                             "Volume image (MetaImage .mhd/.mha, NRRD .nrrd/.nhdr), in the frame "
                             "of the grid, whose values give each finest cell its material "
                             "through youngModulusTransfer and densityTransfer.",
                             {.autoLink = false}};
  Data<std::vector<double>> d_youngModulusTransfer{
      this,
      "youngModulusTransfer",
      {},
      "Piecewise-linear map 'imageValue0 E0 imageValue1 E1 ...' (increasing image values, "
      "E > 0, constant beyond the ends) from the mean image value of a finest cell to its "
      "Young's modulus (Pa); empty: youngModulus everywhere."};
  Data<std::vector<double>> d_densityTransfer{
      this,
      "densityTransfer",
      {},
      "Piecewise-linear map 'imageValue0 rho0 imageValue1 rho1 ...' (rho >= 0) from the mean "
      "image value of a finest cell to its density (kg/m^3); empty: density everywhere."};
  Link<Topology> l_topology{this, "topology",
                            "The SparseGridTopology (default: the node's or above)."};
  Data<std::vector<double>> d_vertexMass{
      this,
      "vertexMass",
      {},
      "Lumped (row-sum) condensed mass of each point (nbPoints).",
      {.unit = "kg", .output = true}};
  Data<double> d_totalMass{this,
                           "totalMass",
                           0.0,
                           "Sum of the condensed masses: density x filled volume (fractions).",
                           {.unit = "kg", .output = true}};
  Data<bool> d_updateStiffnessMatrix{
      this, "updateStiffnessMatrix", false,
      "SOFA option, accepted: the condensed matrices are recomputed whenever youngModulus, "
      "poissonRatio or density change, whatever its value."};
  Data<bool> d_useMass{this, "useMass", true,
                       "SOFA option: only true (this component is the body's mass) is supported; "
                       "false is a warning and the mass is kept."};
  Data<bool> d_useMBK{this, "useMBK", true,
                      "SOFA option, accepted: the implicit solvers use M, B and K as any force "
                      "field's, whatever its value."};
  Data<bool> d_assembling{this, "assembling", false,
                          "SOFA option, accepted: K is assembled when the linear solver asks "
                          "for a matrix."};
  Data<bool> d_drawing{this, "drawing", true, "Viewers only."};
  Data<double> d_drawPercentageOffset{this, "drawPercentageOffset", 0.15, "Viewers only."};

  void init() override;
  void reinit() override { init(); }

  void addForce(const MechanicalParams& mp, VecDeriv& f, const VecCoord& x,
                const VecDeriv& v) override;
  void addDForce(const MechanicalParams& mp, VecDeriv& df, const VecDeriv& dx) override;
  void addKToMatrix(const MechanicalParams& mp, MatrixAccumulator& matrix,
                    std::size_t offset) override;
  double potentialEnergy(const MechanicalParams& mp, const VecCoord& x) const override;

  void addMDx(VecDeriv& f, const VecDeriv& dx, double factor) override;
  void accFromF(VecDeriv& a, const VecDeriv& f) override;
  void addMToMatrix(MatrixAccumulator& matrix, std::size_t offset, double factor) override;
  double kineticEnergy(const VecDeriv& v) const override;
  bool isDiagonal() const override { return d_lumpedMass.value(); }

 private:
  fem::RotationMethod rotationMethod() const { return toRotationMethod(d_method.value()); }
  /// The sparse grid's topology (link, else the node's or above); reports when there is none.
  const Topology* findSparseGrid();
  /// An error at init; while running, a warning that the change is not applied.
  void reportBadInput(const std::string& text, const std::string& field);
  /// The material of each finest cell (fraction, E, rho); false after reporting bad input.
  bool computeCellMaterials(std::span<const sparsegrid::FinerLevel> levels);
  /// Condenses every hexahedron and sets the element constants and masses; false after an error.
  bool computeConstants();
  /// Sum of the versions of the Data the constants depend on.
  std::uint64_t materialVersion() const;
  /// At the start of a step: recomputes the constants when the material Data changed.
  void refresh();
  fem::HexahedronVectors gather(std::span<const Vec3d> v, std::size_t e) const;
  /// Vertex -> corners (e * 8 + i) in increasing element order, for the deterministic sums.
  void buildVertexAdjacency(std::size_t pointCount);
  /// out += factor * sum over the hexahedra of each vertex of the corners written by
  /// perElement(e, corners): elements in parallel (each writes its own 8 corners), then each
  /// vertex sums its corners in element order, so results do not depend on the thread count.
  void accumulate(
      std::span<Vec3d> out, double factor, std::size_t grain,
      FunctionRef<void(std::size_t, Eigen::Map<fem::HexahedronVectors>)> perElement);

  const Topology* m_topology = nullptr;
  bool m_ready = false;
  std::vector<Hexahedron> m_hexahedra;
  std::vector<fem::CorotationalHexahedron> m_elements;  // stiffness = the condensed K
  std::vector<Eigen::Matrix3d> m_rotations;             // of the last addForce
  std::vector<Vec3d> m_corners;                         // (hexahedra x 8) per-element results
  std::vector<Index> m_vertexOffsets{0};                // (points + 1) into m_vertexCorners
  std::vector<Index> m_vertexCorners;                   // corners around each vertex
  std::vector<fem::Matrix8d> m_elementMasses;           // condensed consistent (I_3 implied)
  std::vector<double> m_vertexMasses;                   // lumped
  std::vector<fem::CellMaterial> m_cellMaterials;       // per finest cell
  std::uint64_t m_materialVersion = 0;                  // sum of the material Data versions
};

}  // namespace stroma
