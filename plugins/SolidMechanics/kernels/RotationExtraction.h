// SPDX-License-Identifier: MIT
// Rotation extraction for corotational elements: the element rotation R that brings the rest
// shape closest to the current one, so that R^T x - X is a small displacement on which linear
// elasticity applies (Nesme thesis, seed 001, chapter 2 section 3.2.2; Muller and Gross 2004).
//
// Every function returns a proper rotation (R^T R = I, det R = +1), including for flat and
// inverted elements. They are equivariant: extracting from Q F (or Q a, Q b) gives Q R for any
// rotation Q, which makes corotational forces rotate with the element.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string_view>

namespace stroma::fem {

/// How a corotational element finds its rotation. Enumerators are the `method` keywords of
/// SOFA's TetrahedronFEMForceField and HexahedronFEMForceField.
enum class RotationMethod {
  small,  ///< no rotation, R = I: linear elasticity, valid for small displacements only
  large,  ///< orthonormal frame built on element edges by Gram-Schmidt (QR) [Nesme 2005]
  polar,  ///< rotation of the polar decomposition F = R S of the deformation gradient
  svd,    ///< rotation from the SVD of F with inversion handling [Irving et al. 2004]
};

/// The scene keyword of `method` ("small", "large", "polar", "svd").
std::string_view rotationMethodName(RotationMethod method);
/// The method named `name`, or nothing when the keyword is unknown.
std::optional<RotationMethod> parseRotationMethod(std::string_view name);

/// Orthonormal frame (columns e1, e2, e3) of two edges a and b, by Gram-Schmidt, the "QR"
/// frame of Nesme et al. 2005 (seed 001, ch. 2 sec. 3.2.2, "Decomposition QR"):
///   e1 = a / |a|,  e3 = (a x b) / |a x b|,  e2 = e3 x e1.
/// e1 follows a, e2 lies in the plane (a, b) on the side of b. For a flat pair (a x b ~ 0) e3
/// is any unit vector orthogonal to e1, and for a ~ 0 the frame is the identity: the result
/// stays a rotation but loses continuity there.
Eigen::Matrix3d computeFrameFromEdges(const Eigen::Vector3d& a, const Eigen::Vector3d& b);

/// Rotation of the polar decomposition F = R S (S symmetric positive definite) when
/// det F > 0, by Higham's scaled Newton iteration X <- (z X + X^-T / z) / 2,
/// z = (|X^-1|_F / |X|_F)^(1/2) (Higham 1986, "Computing the polar decomposition", eq. 3.2
/// and section 3), to machine precision (usually 4 to 7 iterations). When det F <= 1e-6 (|F|_F /
/// sqrt 3)^3 (inverted or nearly flat) it returns computeSvdRotation(F) instead, so R stays a
/// proper rotation.
Eigen::Matrix3d computePolarRotation(const Eigen::Matrix3d& F);

/// Rotation from the SVD F = U Sigma V^T: R = U V^T, where, when det(U V^T) < 0, the column
/// of U of the smallest singular value is negated (the "inverted" axis), as in Irving, Teran,
/// Fedkiw 2004, "Invertible finite elements for robust simulation of large deformation",
/// section 5. R^T F is then symmetric, with a negative eigenvalue along the inverted axis. It
/// equals computePolarRotation(F) when det F > 0. Non-finite F gives the identity.
Eigen::Matrix3d computeSvdRotation(const Eigen::Matrix3d& F);

}  // namespace stroma::fem
