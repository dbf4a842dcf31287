// SPDX-License-Identifier: MIT
// AveragedNodalPressure: the volumetric part of linear elasticity on tetrahedra, integrated at
// the vertices (Bonet and Burton 1998, "A simple average nodal pressure tetrahedral element",
// Commun. Numer. Meth. Engng 14; the linearized, corotational form). With it, the elements
// keep only the deviatoric stiffness (fem::VolumetricStiffness::deviatoric) and linear
// tetrahedra stop locking as nu -> 1/2 (VolumetricSplit.h).
//
// Per tetrahedron e (rest volume V_e, rest gradients g_i, rotation R_e of the last addForce),
// per vertex a (the tetrahedra around it):
//
//   d_e     = sum_i g_i . (R_e^T x_i - X_i)          corotated divergence tr(eps_e)
//   V_a     = sum_{e around a} V_e / 4                nodal volume (m^3)
//   theta_a = sum_{e around a} (V_e / 4) d_e / V_a    averaged volumetric strain
//   kappa_a = sum_{e around a} (V_e / 4) kappa_e / V_a
//   p_a     = kappa_a theta_a                         nodal pressure (Pa)
//   E       = sum_a 1/2 kappa_a V_a theta_a^2          energy (J)
//   f_e,i   = -V_e pbar_e R_e g_i,  pbar_e = (1/4) sum_{a of e} p_a     force (N) = -dE/dx
//   K       = -sum_a (kappa_a / V_a) w_a w_a^T,  w_a = sum_{e around a} (V_e / 4) R_e g_e
//             (dR/dx ignored, as the elements' tangent; the stencil is the vertices within two
//             edges of each other)
//
// Why it does not lock: one volumetric constraint per vertex (about a sixth of the number of
// tetrahedra) instead of one per tetrahedron, against three unknowns per vertex. A linear
// displacement field has the same divergence in every element, so theta_a = d_e and the patch
// test holds. With small, polar and svd, R^T F is symmetric and the force is exactly -dE/dx;
// a rigid motion gives d_e = 0 and no force.
//
// Approximation (corotational): the divergence is that of each element's own corotated
// frame; averaging them at a vertex mixes frames that differ by the elements' relative
// rotations, an error O(rotation differences x strain) that vanishes for rigid motions and in
// the small-strain limit.
//
// Cost of a force or a product: an element pass (the divergence, with the rotated gradients
// R_e g_i kept from addForce) and a vertex pass (the nodal pressures), then the forces by
// CorotationalElements' element-then-vertex sums. Every vertex sum runs in increasing element
// order: the same bits for any thread count. The assembled K has a wider stencil than the
// elements' (vertex pairs within two edges): about (3 r)^2 entries per vertex, r the vertices
// around it.
#pragma once

#include <span>
#include <vector>

#include "CorotationalElements.h"

namespace stroma {

class AveragedNodalPressure {
 public:
  using Elements = CorotationalElements<fem::CorotationalTetrahedron>;

  /// Computes the nodal volumes, bulk moduli and the vertex -> tetrahedra adjacency from the
  /// elements' constants (computed with VolumetricStiffness::deviatoric), the Young modulus
  /// (one value, or one per element) and Poisson's ratio (valid: checked by the caller).
  /// Degenerate elements (zero constants) count for nothing. Allocates; call from init and
  /// after the elements or the material changed.
  void setup(const Elements& elements, std::span<const double> youngModulus, double poissonRatio);

  /// f += volumetric forces at x (N), with the rotations of the elements' last addForce.
  void addForce(Elements& elements, std::span<const Vec3d> x, std::span<Vec3d> f,
                const ThreadPool& pool);
  /// df += kFactor K dx (K = -sum_a (kappa_a / V_a) w_a w_a^T), the same rotations.
  void addDForce(Elements& elements, std::span<const Vec3d> dx, std::span<Vec3d> df, double kFactor,
                 const ThreadPool& pool);
  /// Adds kFactor K, this state's first row at `offset`, vertex by vertex.
  void addKToMatrix(const Elements& elements, MatrixAccumulator& matrix, std::size_t offset,
                    double kFactor);
  /// Volumetric energy sum_a 1/2 kappa_a V_a theta_a^2 (J) at x, the rotations computed at x
  /// by `method` (not kept). Allocates its scratch.
  double energy(const Elements& elements, fem::RotationMethod method,
                std::span<const Vec3d> x) const;

  /// The nodal pressures p_a (Pa) of the last addForce (for tests and outputs).
  std::span<const double> nodalPressure() const { return m_pressure; }

 private:
  /// pressure_a = kappa_a theta_a of the divergences d_e = divergence(e).
  template <class Divergence>
  void averagePressure(std::span<double> pressure, const ThreadPool& pool, Divergence&& divergence);
  /// out += factor * (forces -V_e pbar_e R_e g_i of the nodal pressures).
  void scatterPressure(Elements& elements, std::span<const double> pressure, std::span<Vec3d> out,
                       double factor, const ThreadPool& pool);

  std::vector<fem::TetrahedronVectors> m_gradients;  // (elements) g_i = grad N_i at rest (1/m)
  std::vector<fem::TetrahedronVectors> m_rotatedGradients;  // (elements) R_e g_i (1/m), R_e
                                                            // of the last addForce
  std::vector<double> m_volume;                             // (elements) |V_e| (m^3)
  std::vector<double> m_bulkModulus;                        // (elements) kappa_e (Pa)
  std::vector<double> m_nodalVolume;                        // (points) V_a (m^3)
  std::vector<double> m_nodalBulkModulus;                   // (points) kappa_a (Pa)
  std::vector<double> m_share;            // (elements) (V_e / 4) d_e of the last pass
  std::vector<double> m_pressure;         // (points) p_a of the last addForce (Pa)
  std::vector<double> m_dPressure;        // (points) dp_a of the last addDForce (Pa)
  std::vector<Index> m_vertexOffsets{0};  // (points + 1) into m_vertexElements
  std::vector<Index> m_vertexElements;    // tetrahedra around each vertex, increasing
  std::vector<Index> m_ringNodes;         // scratch of addKToMatrix: vertices near a
  std::vector<Vec3d> m_ringWeights;       // scratch of addKToMatrix: w_a at them
};

}  // namespace stroma
