// SPDX-License-Identifier: MIT
#pragma once

#include "MappedOutput.h"
#include "core/StateTypes.h"
#include "simulation/Mapping.h"

namespace stroma {

/// Points attached to rigid frames (SOFA's RigidMapping, Rigid3d -> Vec3d). Point i has local
/// coordinates p_i in frame k (center c_k, rotation R_k):
///
///   x_i = c_k + R_k p_i,   v_i = v_k + w_k x (R_k p_i),
///
/// so the block of J for (i, k) is [ I  -[R_k p_i]x ] (3 x 6; [r]x is the cross-product matrix)
/// and J^T adds f_i to the frame's force and (R_k p_i) x f_i to its torque. Angular velocities
/// are in world coordinates, as the rigid state integrates them.
///
/// The frame of each point is rigidIndexPerPoint[i] when given, else `index` (counted from the
/// end with indexFromEnd). The local points are `points` when given, else the output's initial
/// positions, converted from world coordinates by the frames' initial positions when
/// globalToLocalCoords is true. J is evaluated at the input's current positions; the geometric
/// stiffness (the change of J^T f with the rotation) is not included.
class RigidMapping final : public Mapping<Rigid3Types, Vec3Types> {
 public:
  Data<std::vector<Vec3d>> d_points{this,
                                    "points",
                                    {},
                                    "Local coordinates of the mapped points in their frame "
                                    "(nbOutput x 3). Default: from the output's positions.",
                                    {.unit = "m"}};
  Data<std::vector<Vec3d>> d_initialPoints{
      this, "initialPoints", {}, "Same as points (SOFA's name of the field).", {.unit = "m"}};
  Data<unsigned> d_index{this, "index", 0,
                         "Frame of every point when rigidIndexPerPoint is empty."};
  Data<bool> d_indexFromEnd{this, "indexFromEnd", false,
                            "Count index from the last frame (0 is the last)."};
  Data<std::vector<unsigned>> d_rigidIndexPerPoint{
      this, "rigidIndexPerPoint", {}, "Frame of each mapped point (nbOutput); default: index."};
  Data<bool> d_globalToLocalCoords{this, "globalToLocalCoords", false,
                                   "The output's initial positions are in world coordinates "
                                   "(converted to the frames' local ones at init); false (SOFA's "
                                   "default): they are already local to their frames."};
  Data<bool> d_useX0{this, "useX0", false,
                     "SOFA option, accepted: the local points are kept from init."};
  Data<int> d_geometricStiffness{this,
                                 "geometricStiffness",
                                 0,
                                 "SOFA's geometric stiffness of the mapped forces (0 none, 1 "
                                 "non-symmetric, 2 symmetrized); only 0 is implemented.",
                                 {.min = 0.0, .max = 2.0}};
  SofaMappingOptions m_options{this};

  void init() override;

  void apply(OutVecCoord& out, const InVecCoord& in) override;
  void applyJ(OutVecDeriv& out, const InVecDeriv& in) override;
  void applyJT(InVecDeriv& in, const OutVecDeriv& out) override;
  /// nbOutput*3 x nbFrames*6, blocks [ I  -[R_k p_i]x ] at the current positions.
  const Eigen::SparseMatrix<double>& jacobian() override;

  /// The local coordinates of the points and the frame of each, as used (after init).
  const std::vector<Vec3d>& localPoints() const { return m_local; }
  const std::vector<unsigned>& frames() const { return m_frame; }

 protected:
  bool prepareVisual(const OutVecCoord& points) override;

 private:
  bool computeLocalPoints(const std::vector<Vec3d>& outputPoints, VecId frameId);
  std::vector<Vec3d> m_local;
  std::vector<unsigned> m_frame;
  Eigen::SparseMatrix<double> m_J;
  std::vector<Eigen::Triplet<double>> m_triplets;
};

}  // namespace stroma
