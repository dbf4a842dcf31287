// SPDX-License-Identifier: MIT
// Uniaxial tension of a block of tetrahedra, fiber-reinforced: an isotropic force field with
// the material's isotropic part (as the README says) and TetrahedralFiberReinforcementForceField
// beside it, solved by StaticSolver and SparseLDLSolver. The end face x = L carries the
// consistent nodal loads of a uniform traction sigma (each boundary triangle gives
// sigma area / 3 to each of its points); the face x = 0 slides on its plane (x held), three of
// its corners remove the rigid motions without stressing the block. Linear tetrahedra then
// reproduce the homogeneous strain of the compliance exactly, u = eps X:
//   fibers along x:  eps_xx = sigma / E_L,  eps_yy = eps_zz = -nu_LT sigma / E_L
//   fibers along y:  eps_xx = sigma / E_T,  eps_yy = -nu_LT sigma / E_L,  eps_zz = -nu_TT sigma /
//   E_T
// and likewise along z; checked to the round-off of the linear solve (1e-9 relative).
#include <gtest/gtest.h>

#include "AnisotropyTestScenes.h"
#include "plugins/SolidMechanics/FemTestScenes.h"
#include "plugins/TestPlugin/TestSupport.h"

namespace stroma::test {
namespace {

const Vec3d kSize(0.3, 0.1, 0.12);
constexpr double kStress = 500;  // Pa, about 1.7 % strain along the fibers, 10 % across

struct Block {
  FemMesh mesh;
  std::string fixedX, corner, cornerY, cornerZ, loaded, loads;
};

/// 6 x 2 x 2 cells, interior points moved by up to 20 % of the spacing, and its boundary sets.
Block makeBlock() {
  Block b;
  b.mesh = makeBoxMesh(kSize, Vec3i(6, 2, 2));
  distortInterior(b.mesh, kSize, 0.05, 0.2);
  const auto& points = b.mesh.points;
  std::vector<Vec3d> force(points.size(), Vec3d::Zero());
  for (const auto& t : b.mesh.tetrahedra)
    for (int skip = 0; skip < 4; ++skip) {
      std::vector<unsigned> face;
      for (int i = 0; i < 4; ++i)
        if (i != skip && std::abs(points[t[i]].x() - kSize.x()) < 1e-12) face.push_back(t[i]);
      if (face.size() != 3) continue;
      const double area =
          0.5 * (points[face[1]] - points[face[0]]).cross(points[face[2]] - points[face[0]]).norm();
      for (unsigned p : face) force[p].x() += kStress * area / 3;
    }
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Vec3d& p = points[i];
    const std::string id = std::to_string(i) + " ";
    if (p.x() == 0) {
      b.fixedX += id;
      if (p.y() == 0 && p.z() == 0) b.corner = id;
      if (p.y() == kSize.y() && p.z() == 0) b.cornerY = id;
      if (p.y() == 0 && p.z() == kSize.z()) b.cornerZ = id;
    }
    if (force[i].x() != 0) {
      b.loaded += id;
      b.loads += vectorText(force[i]) + "  ";
    }
  }
  return b;
}

/// The positions at equilibrium under the load, with `isotropic` (an isotropic force field's
/// XML) and the reinforcement with fibers along `fiber`.
/// (none when `fiber` is zero).
std::vector<Vec3d> solveTension(const Block& b, const std::string& isotropic, const Vec3d& fiber) {
  const std::string components =
      "<StaticSolver name=\"solver\"/><SparseLDLSolver/>" +
      (fiber == Vec3d::Zero() ? std::string() : fiberField(kTissue, fiber)) + isotropic +
      "<PartialFixedProjectiveConstraint indices=\"" + b.fixedX +
      "\" fixedDirections=\"1 0 0\"/><FixedProjectiveConstraint indices=\"" + b.corner +
      "\"/><PartialFixedProjectiveConstraint indices=\"" + b.cornerY +
      "\" fixedDirections=\"1 0 1\"/><PartialFixedProjectiveConstraint indices=\"" + b.cornerZ +
      "\" fixedDirections=\"1 1 0\"/><ConstantForceField indices=\"" + b.loaded + "\" forces=\"" +
      b.loads + "\"/>";
  Runtime runtime;
  Scene scene(runtime);
  if (!loadQuietly(scene, femScene(b.mesh, "tetrahedra", components))) return {};
  EXPECT_TRUE(scene.step()) << describe(scene.log());
  EXPECT_EQ(scene.log().count(MessageLevel::warning), 0u) << describe(scene.log());
  return objectAt<MechanicalState<Vec3Types>>(scene, "/root/body/dofs")
      ->readCoord(VecId::position());
}

/// max |x - (X + eps X)| / max |eps X|.
double strainError(const Block& b, const std::vector<Vec3d>& x, const Eigen::Matrix3d& eps) {
  if (x.size() != b.mesh.points.size()) return 1e300;
  double error = 0, scale = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const Vec3d u = eps * b.mesh.points[i];
    error = std::max(error, (x[i] - b.mesh.points[i] - u).norm());
    scale = std::max(scale, u.norm());
  }
  return error / scale;
}

const std::string kIsotropicFields[] = {
    "<TetrahedronFEMForceField method=\"small\" " + isotropicPartText(kTissue) + "/>",
    // Linked to the reinforcement's outputs (declared before it in the node).
    "<TetrahedralTensorMassForceField youngModulus=\"@fibers.isotropicYoungModulus\" "
    "poissonRatio=\"@fibers.isotropicPoissonRatio\"/>"};

TEST(FiberReinforcementValidation, TensionAlongTheFibersStretchesBySigmaOverEL) {
  const Block b = makeBlock();
  const double EL = kTissue.youngModulusL, nuLT = kTissue.poissonRatioLT;
  const Eigen::Matrix3d eps =
      Eigen::Vector3d(kStress / EL, -nuLT * kStress / EL, -nuLT * kStress / EL).asDiagonal();
  for (const std::string& isotropic : kIsotropicFields) {
    SCOPED_TRACE(isotropic);
    const double error = strainError(b, solveTension(b, isotropic, Vec3d::UnitX()), eps);
    EXPECT_LT(error, 1e-9);
    std::printf("[ tension  ] along the fibers: strain %.6g, lateral %.6g, error %.2g\n", eps(0, 0),
                eps(1, 1), error);
  }
}

TEST(FiberReinforcementValidation, TensionAcrossTheFibersStretchesBySigmaOverET) {
  const Block b = makeBlock();
  const anisotropy::EngineeringConstants& c = kTissue;
  const double along = -c.poissonRatioLT * kStress / c.youngModulusL;  // strain of the fibers
  const double across = -c.poissonRatioTT * kStress / c.youngModulusT;
  const double stretch = kStress / c.youngModulusT;
  for (const std::string& isotropic : kIsotropicFields) {
    SCOPED_TRACE(isotropic);
    const Eigen::Matrix3d alongY = Eigen::Vector3d(stretch, along, across).asDiagonal();
    EXPECT_LT(strainError(b, solveTension(b, isotropic, Vec3d::UnitY()), alongY), 1e-9);
    const Eigen::Matrix3d alongZ = Eigen::Vector3d(stretch, across, along).asDiagonal();
    EXPECT_LT(strainError(b, solveTension(b, isotropic, Vec3d(0, 0, -3)), alongZ), 1e-9);
  }
  // The isotropic field alone would give neither: the reinforcement does the work.
  const Eigen::Matrix3d alongY = Eigen::Vector3d(stretch, along, across).asDiagonal();
  const std::string alone =
      "<TetrahedronFEMForceField method=\"small\" " + isotropicPartText(kTissue) + "/>";
  EXPECT_GT(strainError(b, solveTension(b, alone, Vec3d::Zero()), alongY), 0.01);
}

}  // namespace
}  // namespace stroma::test
