// SPDX-License-Identifier: MIT
#pragma once

#include <Eigen/Core>
#include <Eigen/Sparse>
#include <vector>

#include "core/StateTypes.h"
#include "simulation/ProjectiveConstraint.h"

namespace stroma {

class BaseMapping;

/// Fixes or moves points of a surface embedded in a grid (seed 001, chapter 3 section 4.1,
/// "contraintes dures"): the points are not degrees of freedom, so the constraint acts on the
/// grid's nodes through the pseudo-inverse of the interpolation. With H the (m x n) weights of the
/// m constrained points in the grid's n nodes (the rows of the mapping's J, same weights on x, y
/// and z) and G = H H^T:
///
///   positions   x <- x + H^T G^+ (p(t) - H x)       the least change of the nodes that puts
///   velocities  v <- v + H^T G^+ (v_p(t) - H v)     the points where imposed (Hsu 1992)
///   increments  dx <- (I - H^T G^+ H) dx            the projector on the motions that leave the
///                                                   points in place (forces likewise)
///
/// so that CG and the implicit and static solvers keep the points exactly where imposed:
/// p(t) = p0 + displacement + m(t), p0 the points' rest positions (H x_rest), m(t) the movement
/// interpolated between keyTimes (none: 0); v_p is the mean velocity over the step. When two
/// points have dependent weights (the same point twice, or more points than nodes in a cell) G is
/// singular: G^+ is then the pseudo-inverse (least squares, as the thesis' overconstrained case),
/// with a warning.
///
/// It lives in the grid's node, on the grid's state; `mapping` is the linear mapping embedding
/// the points (BarycentricMapping; default: the first mechanical mapping from this state in the
/// child nodes), read at bwdInit after the mapping's init. G^+ is dense (m x m): meant for tens
/// to a few thousand constrained points. An assembled matrix cannot hold the projector: the
/// solve is then unconstrained and the step's end projection alone imposes the points (a warning).
class EmbeddedPointConstraint final : public ProjectiveConstraint<Vec3Types> {
 public:
  Data<std::vector<unsigned>> d_indices{this,
                                        "indices",
                                        {},
                                        "Indices of the constrained points in the mapping's "
                                        "output (the embedded surface)."};
  Data<Vec3d> d_displacement{this,
                             "displacement",
                             Vec3d::Zero(),
                             "Constant displacement imposed on the points from the first step "
                             "(0: they are fixed).",
                             {.unit = "m"}};
  Data<std::vector<double>> d_keyTimes{
      this, "keyTimes", {}, "Key times of a movement, increasing (nbKeys).", {.unit = "s"}};
  Data<std::vector<Vec3d>> d_movements{this,
                                       "movements",
                                       {},
                                       "Displacement of the points at each key time (nbKeys "
                                       "x 3), added to `displacement`; linear in between, the "
                                       "last one kept after.",
                                       {.unit = "m"}};
  Link<Base> l_mapping{this, "mapping",
                       "The mapping embedding the points in this node's state (default: the "
                       "first mapping from it in the child nodes)."};

  void init() override;
  void bwdInit() override;
  void reinit() override { bwdInit(); }

  void projectResponse(VecDeriv& dx) override;
  void projectVelocity(VecDeriv& v, double time) override;
  void projectPosition(VecCoord& x, double time) override;
  void fixedRows(std::vector<std::size_t>& rows) const override;

  /// Where the constrained points are imposed at time t (m x 3).
  Eigen::MatrixXd targetsAt(double t) const;
  /// H x: where the grid puts the constrained points (m x 3).
  Eigen::MatrixXd pointsOf(const VecCoord& x) const;

 private:
  BaseMapping* findMapping() const;
  Vec3d movementAt(double t) const;
  /// values <- values + H^T G^+ (target - H values); target: m x 3, or empty for 0.
  template <class Vector>
  void correct(Vector& values, const Eigen::MatrixXd* target) const;

  bool m_ready = false;
  Eigen::SparseMatrix<double, Eigen::RowMajor> m_H;  ///< m x n
  Eigen::MatrixXd m_Gplus;                           ///< (H H^T)^+, m x m
  Eigen::MatrixXd m_p0;                              ///< m x 3, the points at rest (H x_rest)
  mutable bool m_reportedAssembled = false;
};

}  // namespace stroma
