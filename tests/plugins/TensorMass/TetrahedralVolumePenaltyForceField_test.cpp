// SPDX-License-Identifier: MIT
// TetrahedralVolumePenaltyForceField: the force of seed 004 section 3.2 on a tetrahedron whose
// volume changed (direction, norm, sense), the generic force-field checks with its tangent,
// its use beside an elastic model, and bad input.
#include <gtest/gtest.h>

#include <cmath>

#include "TensorMass/kernels/VolumePenalty.h"
#include "TensorMassTestScenes.h"
#include "support/ForceFieldTest.h"

namespace stroma::test {
namespace {

const std::string kPenalty =
    "<TetrahedralVolumePenaltyForceField name=\"penalty\" stiffness=\"2000\"/>";

FemMesh oneTetrahedron() {
  FemMesh mesh;
  mesh.points = {{0, 0, 0}, {0.1, 0.01, 0}, {0.02, 0.09, 0.01}, {0.01, 0.02, 0.11}};
  mesh.tetrahedra = {{0, 1, 2, 3}};
  return mesh;
}

TEST(TetrahedralVolumePenaltyForceField, PushesEachVertexAlongTheNormalOfItsOppositeFace) {
  // Scaled about its centroid by k, the tetrahedron's volume changed by s = k^3 - 1; the
  // force on vertex p is gamma s^2 (A_p / 3) along the normal n_p of the opposite face, towards
  // the face when the volume grew, away from it when it shrank.
  const FemMesh mesh = oneTetrahedron();
  Vec3d centroid = Vec3d::Zero();
  for (const Vec3d& p : mesh.points) centroid += p / 4;
  const double gamma = 2000;
  for (double k : {1.1, 0.9}) {
    SCOPED_TRACE(k);
    std::vector<Vec3d> x;
    for (const Vec3d& p : mesh.points) x.push_back(centroid + k * (p - centroid));
    const Eigen::VectorXd f = forcesAt(tensorMassScene(mesh, kPenalty), x);
    ASSERT_EQ(f.size(), 12);
    const double s = k * k * k - 1;
    static constexpr int kOpposite[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
    for (int p = 0; p < 4; ++p) {
      const Vec3d& a = x[kOpposite[p][0]];
      const Vec3d areaNormal = 0.5 * (x[kOpposite[p][1]] - a).cross(x[kOpposite[p][2]] - a);
      // n_p points away from vertex p for SOFA's orientation: towards p is -areaNormal.
      const Vec3d towardsP = -areaNormal.normalized();
      const double area = areaNormal.norm();
      const Vec3d expected = -(s > 0 ? 1 : -1) * gamma * s * s * area / 3 * towardsP;
      EXPECT_LT((f.segment<3>(3 * p) - expected).norm(), 1e-12 * expected.norm()) << "vertex " << p;
      // Restoring: inwards when grown, outwards when shrunk.
      EXPECT_LT(s * f.segment<3>(3 * p).dot(x[p] - centroid), 0);
    }
  }
}

TEST(TetrahedralVolumePenaltyForceField, PassesTheForceFieldTest) {
  // A potential W = gamma V0 |s|^3 / 3 and its exact Hessian; rotation invariant; no force
  // at rest. The perturbation changes the volumes by tens of %.
  const ForceFieldTestReport r =
      checkForceField(tensorMassScene(makeRandomTetrahedralMesh(), kPenalty),
                      {.rotationInvariant = true, .perturbation = 0.2});
  std::printf("%s", r.describe().c_str());
}

TEST(TetrahedralVolumePenaltyForceField, HessianProductIsTheHessianMatrixTimesTheVector) {
  const FemMesh mesh = oneTetrahedron();
  fem::TetrahedronVectors x, dx;
  for (int i = 0; i < 4; ++i) x.col(i) = 1.2 * mesh.points[i];
  dx.setRandom();
  const double restVolume = 0.1 * 0.09 * 0.11 / 6;  // any, not the rest one here
  const fem::Matrix12d H = tensormass::computeVolumePenaltyHessian(x, restVolume, 5.0);
  const fem::TetrahedronVectors product =
      tensormass::computeVolumePenaltyHessianProduct(x, restVolume, 5.0, dx);
  const fem::ElementVector<4> expected = H * fem::asElementVector<4>(dx);
  EXPECT_LT((fem::asElementVector<4>(product) - expected).norm(), 1e-12 * expected.norm());
  EXPECT_LT((H - H.transpose()).norm(), 1e-12 * H.norm());
}

TEST(TetrahedralVolumePenaltyForceField, AddsToAnElasticModel) {
  // Beside the St Venant-Kirchhoff tensor-mass on the same tetrahedra: the forces add, and
  // the sum passes the checks (each field is tested alone above; here the scene's sum).
  const FemMesh mesh = makeRandomTetrahedralMesh();
  const std::string stvk =
      "<TetrahedralStVKTensorMassForceField name=\"stvk\" youngModulus=\"3000\" "
      "poissonRatio=\"0.3\"/>";
  const std::vector<Vec3d> x =
      displaced(mesh.points, randomDisplacements(mesh.points.size(), 0.03));
  const Eigen::VectorXd both = forcesAt(tensorMassScene(mesh, stvk + kPenalty), x);
  const Eigen::VectorXd elastic = forcesAt(tensorMassScene(mesh, stvk), x);
  const Eigen::VectorXd penalty = forcesAt(tensorMassScene(mesh, kPenalty), x);
  EXPECT_LT(relativeDifference(both, elastic + penalty), 1e-14);
  EXPECT_GT(penalty.norm(), 1e-3 * elastic.norm());
}

TEST(TetrahedralVolumePenaltyForceField, BadInputIsAnErrorNamingTheField) {
  struct Case {
    FemMesh mesh;
    std::string field;
    const char* name;
    const char* text;
  };
  FemMesh flat = oneTetrahedron();
  flat.points[3] = (flat.points[0] + flat.points[1] + flat.points[2]) / 3;  // in their plane
  FemMesh inverted = oneTetrahedron();
  std::swap(inverted.tetrahedra[0][2], inverted.tetrahedra[0][3]);
  for (const Case& c :
       {Case{oneTetrahedron(), "<TetrahedralVolumePenaltyForceField stiffness=\"-1\"/>",
             "stiffness", ">= 0"},
        Case{flat, kPenalty, "topology", "flat"},
        Case{inverted, kPenalty, "topology", "inverted"}}) {
    SCOPED_TRACE(c.field);
    Runtime runtime;
    Scene scene(runtime);
    scene.loadString(tensorMassScene(c.mesh, c.field));
    bool found = false;
    for (const Message& m : errors(scene.log()))
      found |= m.field == c.name && m.text.find(c.text) != std::string::npos;
    EXPECT_TRUE(found) << describe(scene.log());
    scene.step();  // no crash
  }
}

}  // namespace
}  // namespace stroma::test
