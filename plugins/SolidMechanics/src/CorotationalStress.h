// SPDX-License-Identifier: MIT
// The von Mises stress of corotational elements (StressField of TetrahedronFEMForceField,
// HexahedronFEMForceField and HexahedronFEMForceFieldAndMass), computed on demand from the
// current positions, never during a step.
//
// Per element, with R its rotation at the current positions x by the field's method (the same
// as its forces use; small: R = I, linear elasticity), F the deformation gradient (constant in
// a tetrahedron, at the centre of a hexahedron, where its forces' rotation is taken too):
//
//   H = R^T F - I   (the gradient of the corotated displacement u = R^T x - X),
//   von Mises = sqrt(3/2 s : s),  s = 2 mu dev((H + H^T) / 2)   (kernels/VonMisesStress.h),
//
// with mu = E / (2 (1 + nu)) of the element's Young modulus. A rigid motion gives H = 0 for
// the rotating methods. Per point: the plain mean of the elements around it (0 for a point in
// no element).
#pragma once

#include <span>
#include <vector>

#include "CorotationalElements.h"
#include "SolidMechanics/kernels/VonMisesStress.h"

namespace stroma {

/// Von Mises stress of each element of `elements` at positions x. youngModulus: one value, or
/// one per element. Returns false (stress empty) when the sizes do not match.
template <class Element>
bool computeVonMisesPerElement(const CorotationalElements<Element>& elements,
                               fem::RotationMethod method, std::span<const Vec3d> x,
                               const std::vector<double>& youngModulus, double poissonRatio,
                               std::vector<double>& stress) {
  stress.clear();
  if (youngModulus.empty() || (youngModulus.size() != 1 && youngModulus.size() != elements.size()))
    return false;
  if (elements.size() > 0 && elements.pointCount() > x.size()) return false;
  stress.resize(elements.size());
  for (std::size_t e = 0; e < elements.size(); ++e) {
    const typename Element::Vectors xe = elements.gather(x, e);
    const Element& element = elements.constant(e);
    const Eigen::Matrix3d R = fem::computeRotation(method, element, xe);
    Eigen::Matrix3d F;
    if constexpr (Element::nodeCount == 4)
      F = fem::computeDeformationGradient(element, xe);
    else
      F = fem::computeCentreDeformationGradient(element, xe);
    const Eigen::Matrix3d H = R.transpose() * F - Eigen::Matrix3d::Identity();
    const double E = youngModulus[youngModulus.size() == 1 ? 0 : e];
    stress[e] = fem::computeVonMisesStress(H, fem::computeShearModulus(E, poissonRatio));
  }
  return true;
}

/// The mean of the per-element values around each of `pointCount` points (0 for a point in
/// no element).
template <class Element>
void averageAroundPoints(const CorotationalElements<Element>& elements,
                         std::span<const double> perElement, std::size_t pointCount,
                         std::vector<double>& perPoint) {
  perPoint.assign(pointCount, 0.0);
  std::vector<int> count(pointCount, 0);
  for (std::size_t e = 0; e < elements.size(); ++e)
    for (const auto node : elements.elements()[e]) {
      if (static_cast<std::size_t>(node) >= pointCount) continue;
      perPoint[node] += perElement[e];
      ++count[node];
    }
  for (std::size_t i = 0; i < pointCount; ++i)
    if (count[i] > 0) perPoint[i] /= count[i];
}

}  // namespace stroma
