// SPDX-License-Identifier: MIT
// What the TensorMass tests share: a random tetrahedral mesh (a grid of tetrahedra with its
// interior points moved), scenes holding one force field on it, positions set from outside, and
// the forces of a scene. Builds on the FEM tests' meshes (FemTestScenes.h).
#pragma once

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <random>
#include <string>
#include <vector>

#include "plugins/SolidMechanics/FemTestScenes.h"
#include "plugins/TestPlugin/TestSupport.h"

namespace stroma::test {

/// 3 x 2 x 2 cells of a 0.3 x 0.2 x 0.2 m box, every point moved by up to 15 % of the
/// spacing, 72 tetrahedra: a mesh with tetrahedra of many shapes.
inline FemMesh makeRandomTetrahedralMesh() {
  FemMesh mesh = makeBoxMesh(Vec3d(0.3, 0.2, 0.2), Vec3i(3, 2, 2));
  // The boundary points too: every tetrahedron is then irregular.
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> uniform(-0.015, 0.015);
  for (Vec3d& p : mesh.points) p += Vec3d(uniform(rng), uniform(rng), uniform(rng));
  return mesh;
}

/// `field` (XML of one force field) on the mesh, in node /root/body with state "dofs".
inline std::string tensorMassScene(const FemMesh& mesh, const std::string& field) {
  return femScene(mesh, "tetrahedra", field);
}

/// Random displacements of size up to `amplitude` (m), reproducibly.
inline std::vector<Vec3d> randomDisplacements(std::size_t count, double amplitude,
                                              unsigned seed = 3) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> uniform(-amplitude, amplitude);
  std::vector<Vec3d> u(count);
  for (Vec3d& v : u) v = Vec3d(uniform(rng), uniform(rng), uniform(rng));
  return u;
}

/// The state of a scene made by femScene.
inline MechanicalState<Vec3Types>* bodyState(Scene& scene) {
  return objectAt<MechanicalState<Vec3Types>>(scene, "/root/body/dofs");
}

/// Sets the positions of the body to `positions`.
inline void setPositions(Scene& scene, const std::vector<Vec3d>& positions) {
  bodyState(scene)->writeCoord(VecId::position()) = positions;
}

/// The forces of the scene's fields at `positions` (3N vector).
inline Eigen::VectorXd forcesAt(const std::string& xml, const std::vector<Vec3d>& positions) {
  Runtime runtime;
  Scene scene(runtime);
  if (!loadQuietly(scene, xml)) return {};
  setPositions(scene, positions);
  return computeForces(scene);
}

/// Rest points moved by u.
inline std::vector<Vec3d> displaced(const std::vector<Vec3d>& rest, const std::vector<Vec3d>& u) {
  std::vector<Vec3d> x(rest.size());
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = rest[i] + u[i];
  return x;
}

/// The rest points rotated by R about the origin.
inline std::vector<Vec3d> rotated(const std::vector<Vec3d>& rest, const Eigen::Matrix3d& R) {
  std::vector<Vec3d> x(rest.size());
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = R * rest[i];
  return x;
}

/// max_i |a_i - b_i| / max_i |b_i| over the 3-vectors of two force vectors.
inline double relativeDifference(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  EXPECT_EQ(a.size(), b.size());
  if (a.size() != b.size() || b.size() == 0) return 1e300;
  double difference = 0, scale = 0;
  for (Eigen::Index i = 0; i < b.size(); i += 3) {
    difference = std::max(difference, (a.segment<3>(i) - b.segment<3>(i)).norm());
    scale = std::max(scale, b.segment<3>(i).norm());
  }
  return difference / scale;
}

/// The total volume of the tetrahedra of a mesh (m^3).
inline double meshVolume(const FemMesh& mesh) {
  double volume = 0;
  for (const auto& t : mesh.tetrahedra) {
    const Vec3d a = mesh.points[t[0]];
    volume += (mesh.points[t[1]] - a).dot((mesh.points[t[2]] - a).cross(mesh.points[t[3]] - a)) / 6;
  }
  return volume;
}

}  // namespace stroma::test
