// SPDX-License-Identifier: MIT
// PrecomputedConstraintCorrection (plugins/Lagrangian): its compliance equals H A^-1 H^T of the
// assembled system (LinearSolverConstraintCorrection beside it, same node, same rows) at rest
// and after a rigid rotation of the body; in a PrecomputedLinearModel's node it is the model's
// own K^-1 (against a static FEM solve, and a held point against the model's imposed
// displacement); the cache file: written then read gives the same numbers, a changed input gives
// another key and a stale file is refused, a corrupt or foreign file is refused; bad input
// names the component and field; a warm compliance and correction allocate nothing.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <new>

#include "plugins/SolidMechanics/FemTestScenes.h"
#include "plugins/TestPlugin/TestSupport.h"
#include "simulation/Constraints.h"
#include "simulation/Solvers.h"
#include "support/TestNames.h"

#include "support/AllocationCounter.h"

namespace stroma::test {
namespace {

using RowMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;

// A 0.4 x 0.1 x 0.1 m beam of 6 x 2 x 2 cells cut into tetrahedra (63 nodes), clamped at x = 0.
const FemMesh& beam() {
  static const FemMesh mesh = makeBoxMesh(Vec3d(0.4, 0.1, 0.1), Vec3i(6, 2, 2));
  return mesh;
}

std::string clamped(int extra = -1) {
  std::string text;
  for (size_t i = 0; i < beam().points.size(); ++i)
    if (beam().points[i].x() == 0 || int(i) == extra) text += std::to_string(i) + ' ';
  return text;
}

// The inputs a compliance depends on, each one changeable.
struct BodyInputs {
  double youngModulus = 2e5;
  double density = 1000;
  double dt = 0.01;
  int extraFixed = -1;            ///< one more clamped node
  Vec3d movedRestPoint{0, 0, 0};  ///< added to node 20's rest position
  bool free = false;              ///< no clamped node: the mass alone makes A invertible
};

// The dynamic body: corotational FEM, diagonal mass, implicit Euler with SparseLDL, and both
// corrections (the assembled one and the precomputed one, `attributes`).
std::string dynamicBody(const std::string& attributes, const BodyInputs& in = {}) {
  FemMesh mesh = beam();
  mesh.points[20] += in.movedRestPoint;
  char root[96];
  std::snprintf(root, sizeof root, "gravity=\"0 0 0\" dt=\"%.17g\"", in.dt);
  const std::string fixed =
      in.free ? "" : "<FixedProjectiveConstraint indices=\"" + clamped(in.extraFixed) + "\"/>";
  return femScene(mesh, "tetrahedra",
                  "<EulerImplicitSolver rayleighStiffness=\"0.02\" rayleighMass=\"0.5\"/>"
                  "<SparseLDLSolver/><DiagonalMass massDensity=\"" +
                      std::to_string(in.density) +
                      "\"/><TetrahedronFEMForceField method=\"large\" youngModulus=\"" +
                      std::to_string(in.youngModulus) + "\" poissonRatio=\"0.3\"/>" + fixed +
                      "<LinearSolverConstraintCorrection name=\"assembled\"/>"
                      "<PrecomputedConstraintCorrection name=\"precomputed\" " +
                      attributes + "/>",
                  root);
}

// Rows on free surface nodes (the precomputed model's basis is the surface): the three axes of
// nodes 62 (the tip corner), 41 and 19, a slanted row on node 27 and one coupling nodes 62 and
// 48 (a distance between them).
RowMatrix probeRows() {
  const Eigen::Index dofs = 3 * Eigen::Index(beam().points.size());
  std::vector<Eigen::Triplet<double>> t;
  int row = 0;
  for (int node : {62, 41, 19})
    for (int c = 0; c < 3; ++c) t.emplace_back(row++, 3 * node + c, 1.0);
  const Vec3d n = Vec3d(1, -2, 0.5).normalized();
  for (int c = 0; c < 3; ++c) t.emplace_back(row, 3 * 27 + c, n[c]);
  ++row;
  for (int c = 0; c < 3; ++c) {
    t.emplace_back(row, 3 * 62 + c, n[c]);
    t.emplace_back(row, 3 * 48 + c, -n[c]);
  }
  ++row;
  RowMatrix H(row, dofs);
  H.setFromTriplets(t.begin(), t.end());
  return H;
}

// W = H C H^T by the correction at `path`, with the body's solver response.
Eigen::MatrixXd complianceOf(Scene& scene, const std::string& path, const RowMatrix& H) {
  Node& body = *scene.root().findChild("body");
  MechanicalOperations mop(body, scene.timing(), body.dt());
  ConstraintResponse response;
  EXPECT_TRUE(body.get<OdeSolver>()->constraintResponse(body.dt(), response));
  Eigen::MatrixXd W = Eigen::MatrixXd::Zero(H.rows(), H.rows());
  if (auto* c = objectAt<BaseConstraintCorrection>(scene, path))
    c->addCompliance(mop, response, H, W);
  return W;
}

double relativeDifference(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  return (a - b).cwiseAbs().maxCoeff() / b.cwiseAbs().maxCoeff();
}

std::string dataText(Scene& scene, const std::string& path, const std::string& field) {
  Base* o = objectAt<Base>(scene, path);
  const BaseData* d = o ? o->findData(field) : nullptr;
  return d ? d->valueText() : "";
}

// The warnings of `scene` on `field` containing `text`.
int warningsWith(Scene& scene, const std::string& field, const std::string& text) {
  int count = 0;
  for (const Message& m : scene.log().messages())
    count += m.level == MessageLevel::warning && m.field == field &&
             m.text.find(text) != std::string::npos;
  return count;
}

class PrecomputedCorrection : public ::testing::Test {
 protected:
  std::string file(const std::string& name) { return (m_dir.path() / name).string(); }
  TempDir m_dir;
};

TEST_F(PrecomputedCorrection, EqualsTheAssembledComplianceAtRest) {
  // One implicit step at rest (no load: the body stays there) gives SparseLDL its matrix
  // A = (1 + h rm) M - h (h + rs) K; W = h^2 H A^-1 H^T either way. Both factorise the same
  // matrix (Eigen's LDL^T, different orderings): they agree to round-off times the condition
  // number of A, 1e-10 relative. Clamped, and free (no fixed dof: the mass makes A definite).
  for (const bool free : {false, true}) {
    BodyInputs inputs;
    inputs.free = free;
    Runtime runtime;
    Scene scene(runtime);
    ASSERT_TRUE(loadQuietly(
        scene, dynamicBody("fileCompliance=\"" + file(free ? "free" : "c") + "\"", inputs)));
    ASSERT_TRUE(scene.step());
    const RowMatrix H = probeRows();
    const Eigen::MatrixXd exact = complianceOf(scene, "/body/assembled", H);
    const Eigen::MatrixXd precomputed = complianceOf(scene, "/body/precomputed", H);
    ASSERT_GT(exact.norm(), 0);
    EXPECT_LT(relativeDifference(precomputed, exact), 1e-10) << (free ? "free" : "clamped");
    EXPECT_LT(relativeDifference(precomputed, precomputed.transpose()), 1e-12) << "symmetric";
  }
}

TEST_F(PrecomputedCorrection, TurnsWithTheBodyRotatedRigidly) {
  // The whole body (its clamped nodes too, which then stay there) turned by 40 degrees about a
  // slanted axis and moved: a corotational body has A = R A_0 R^T, which the per-node rotations
  // recover (a rigid ring gives its rotation exactly): equal to 1e-10 relative. The compliance
  // left unrotated is more than 10 % off, so the test sees the rotations.
  Runtime runtime;
  Scene scene(runtime);
  ASSERT_TRUE(loadQuietly(scene, dynamicBody("fileCompliance=\"" + file("c") + "\"")));
  auto* dofs = objectAt<MechanicalState<Vec3Types>>(scene, "/body/dofs");
  ASSERT_NE(dofs, nullptr);
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.7, Vec3d(1, 2, 3).normalized()).toRotationMatrix();
  const Vec3d shift(0.1, -0.2, 0.3);
  auto& x = dofs->writeCoord(VecId::position());
  for (size_t i = 0; i < x.size(); ++i) x[i] = R * beam().points[i] + shift;
  ASSERT_TRUE(scene.step());
  const RowMatrix H = probeRows();
  const Eigen::MatrixXd exact = complianceOf(scene, "/body/assembled", H);
  const Eigen::MatrixXd rotated = complianceOf(scene, "/body/precomputed", H);
  EXPECT_LT(relativeDifference(rotated, exact), 1e-10);

  Runtime runtime2;
  Scene unrotated(runtime2);
  ASSERT_TRUE(loadQuietly(unrotated,
                          dynamicBody("rotations=\"false\" fileCompliance=\"" + file("c") + "\"")));
  EXPECT_EQ(dataText(unrotated, "/body/precomputed", "loadedFromCache"), "1");
  EXPECT_GT(relativeDifference(complianceOf(unrotated, "/body/precomputed", H), exact), 0.1);
}

TEST_F(PrecomputedCorrection, ApproximatesTheComplianceOfABentBody) {
  // The beam bent in the x-z plane round a circle of radius rho (x = 0 stays; the tip turns by
  // 0.4 / rho rad): the elements are rotated and a little strained, and the body is curved, so
  // the compliance at rest turned per node is a first-order approximation, its error about
  // proportional to the curvature. Measured (largest entry, relative to the largest of W):
  // rho = 1.2 m (tip 19 degrees) 2.9 % rotated, 12.7 % unrotated; rho = 0.3 m (76 degrees)
  // 16.3 % and 47 %.
  struct Bend {
    double rho, rotatedBelow, unrotatedAbove;
  };
  for (const Bend bend : {Bend{1.2, 0.035, 0.1}, Bend{0.3, 0.2, 0.4}}) {
    Runtime runtime;
    Scene scene(runtime);
    ASSERT_TRUE(loadQuietly(scene, dynamicBody("fileCompliance=\"" + file("c") + "\"")));
    auto& x =
        objectAt<MechanicalState<Vec3Types>>(scene, "/body/dofs")->writeCoord(VecId::position());
    for (size_t i = 0; i < x.size(); ++i) {
      const Vec3d& p = beam().points[i];
      const double theta = p.x() / bend.rho, r = bend.rho - p.z();
      x[i] = Vec3d(r * std::sin(theta), p.y(), bend.rho - r * std::cos(theta));
    }
    ASSERT_TRUE(scene.step());
    const RowMatrix H = probeRows();
    const Eigen::MatrixXd exact = complianceOf(scene, "/body/assembled", H);
    const double rotatedError =
        relativeDifference(complianceOf(scene, "/body/precomputed", H), exact);
    std::string error;
    ASSERT_TRUE(
        objectAt<Base>(scene, "/body/precomputed")->findData("rotations")->read("0", error));
    const double unrotatedError =
        relativeDifference(complianceOf(scene, "/body/precomputed", H), exact);
    EXPECT_LT(rotatedError, bend.rotatedBelow) << "rho " << bend.rho;
    EXPECT_GT(unrotatedError, bend.unrotatedAbove) << "rho " << bend.rho;
  }
}

TEST_F(PrecomputedCorrection, CacheWrittenThenReadGivesTheSameNumbers) {
  const RowMatrix H = probeRows();
  Eigen::MatrixXd first;
  std::string key;
  for (int run = 0; run < 2; ++run) {
    Runtime runtime;
    Scene scene(runtime);
    ASSERT_TRUE(scene.loadString(dynamicBody("fileCompliance=\"" + file("c") + "\"")))
        << describe(scene.log());
    EXPECT_EQ(dataText(scene, "/body/precomputed", "loadedFromCache"), run == 0 ? "0" : "1");
    const Eigen::MatrixXd W = complianceOf(scene, "/body/precomputed", H);
    if (run == 0) {
      first = W;
      key = dataText(scene, "/body/precomputed", "complianceKey");
      EXPECT_EQ(key.size(), 16u);
      EXPECT_GT(std::stod(dataText(scene, "/body/precomputed", "precomputationTime")), 0);
    } else {
      EXPECT_EQ(dataText(scene, "/body/precomputed", "complianceKey"), key);
      EXPECT_EQ((W - first).cwiseAbs().maxCoeff(), 0.0) << "bit for bit";
    }
    EXPECT_EQ(scene.log().count(MessageLevel::warning), 0u) << describe(scene.log());
  }
  {  // recompute="true" does not read it, and gives the same numbers again
    Runtime runtime;
    Scene scene(runtime);
    ASSERT_TRUE(
        loadQuietly(scene, dynamicBody("recompute=\"1\" fileCompliance=\"" + file("c") + "\"")));
    EXPECT_EQ(dataText(scene, "/body/precomputed", "loadedFromCache"), "0");
    EXPECT_EQ((complianceOf(scene, "/body/precomputed", H) - first).cwiseAbs().maxCoeff(), 0.0);
  }
}

TEST_F(PrecomputedCorrection, AcceptsSofasAttributes) {
  // As SOFA's scenes write it (DeformableOnRigidFrameMappingConstraints.scn: recompute="true"),
  // with its drawing and rest-deformation options accepted without effect.
  Runtime runtime;
  Scene scene(runtime);
  ASSERT_TRUE(loadQuietly(
      scene, dynamicBody("recompute=\"true\" rotations=\"true\" debugViewFrameScale=\"0.5\" "
                         "restDeformations=\"false\" fileCompliance=\"" +
                         file("c") + "\"")));
  EXPECT_EQ(dataText(scene, "/body/precomputed", "loadedFromCache"), "0");
}

struct ChangedInput {
  const char* what;
  BodyInputs inputs;
};
void PrintTo(const ChangedInput& c, std::ostream* out) { *out << c.what; }

class StaleCache : public PrecomputedCorrection,
                   public ::testing::WithParamInterface<ChangedInput> {};

TEST_P(StaleCache, GivesAnotherKeyAndTheOldFileIsRefused) {
  // The cache of the default inputs, then one input changed with the same file: another key,
  // the file refused with a warning naming fileCompliance and why, the compliance recomputed
  // (it differs) and rewritten (the next load reads it). By default the file is named after
  // the key, so the two never meet.
  const RowMatrix H = probeRows();
  std::string oldKey;
  Eigen::MatrixXd oldW;
  {
    Runtime runtime;
    Scene scene(runtime);
    ASSERT_TRUE(loadQuietly(scene, dynamicBody("fileCompliance=\"" + file("c") + "\"")));
    oldKey = dataText(scene, "/body/precomputed", "complianceKey");
    oldW = complianceOf(scene, "/body/precomputed", H);
  }
  for (int run = 0; run < 2; ++run) {
    Runtime runtime;
    Scene scene(runtime);
    ASSERT_TRUE(
        scene.loadString(dynamicBody("fileCompliance=\"" + file("c") + "\"", GetParam().inputs)))
        << describe(scene.log());
    EXPECT_NE(dataText(scene, "/body/precomputed", "complianceKey"), oldKey);
    EXPECT_EQ(dataText(scene, "/body/precomputed", "loadedFromCache"), run == 0 ? "0" : "1");
    EXPECT_EQ(warningsWith(scene, "fileCompliance", "key differs"), run == 0 ? 1 : 0)
        << describe(scene.log());
    EXPECT_GT(relativeDifference(complianceOf(scene, "/body/precomputed", H), oldW), 1e-6);
  }
  {  // default names: <fileDir>/<key>.compliance, one file per set of inputs
    Runtime runtime;
    Scene scene(runtime);
    ASSERT_TRUE(loadQuietly(scene, dynamicBody("fileDir=\"" + file("dir") + "\"")));
    Runtime runtime2;
    Scene changed(runtime2);
    ASSERT_TRUE(
        loadQuietly(changed, dynamicBody("fileDir=\"" + file("dir") + "\"", GetParam().inputs)));
    EXPECT_EQ(dataText(changed, "/body/precomputed", "loadedFromCache"), "0");
    EXPECT_TRUE(std::filesystem::exists(file("dir/" + oldKey + ".compliance")));
    EXPECT_TRUE(std::filesystem::exists(
        file("dir/" + dataText(changed, "/body/precomputed", "complianceKey") + ".compliance")));
  }
}

BodyInputs with(void (*change)(BodyInputs&)) {
  BodyInputs in;
  change(in);
  return in;
}

INSTANTIATE_TEST_SUITE_P(
    Lagrangian, StaleCache,
    ::testing::Values(
        ChangedInput{"Young's modulus", with([](BodyInputs& in) { in.youngModulus = 2.2e5; })},
        ChangedInput{"mass density", with([](BodyInputs& in) { in.density = 1100; })},
        ChangedInput{"time step", with([](BodyInputs& in) { in.dt = 0.02; })},
        ChangedInput{"a fixed index", with([](BodyInputs& in) { in.extraFixed = 22; })},
        ChangedInput{"a rest position",
                     with([](BodyInputs& in) { in.movedRestPoint = Vec3d(0.003, 0, 0); })}),
    NameFromWhat());

TEST_F(PrecomputedCorrection, CorruptTruncatedAndForeignFilesAreRefused) {
  const RowMatrix H = probeRows();
  Eigen::MatrixXd reference;
  {
    Runtime runtime;
    Scene scene(runtime);
    ASSERT_TRUE(loadQuietly(scene, dynamicBody("fileCompliance=\"" + file("c") + "\"")));
    reference = complianceOf(scene, "/body/precomputed", H);
  }
  const auto size = std::filesystem::file_size(file("c"));
  struct Damage {
    const char* what;
    const char* reason;
    bool rewritten;  ///< a foreign file is left alone
  };
  for (const Damage& damage :
       {Damage{"a flipped byte", "corrupt", true}, Damage{"cut short", "truncated", true},
        Damage{"SOFA's file", "not a Stroma compliance cache", false}}) {
    const std::string what = damage.what;
    if (what == "a flipped byte") {
      std::fstream f(file("c"), std::ios::in | std::ios::out | std::ios::binary);
      f.seekp(std::streamoff(size - 100));
      f.put('\x5a');
    } else if (what == "cut short") {
      std::filesystem::resize_file(file("c"), size - 8);
    } else {
      std::ofstream(file("c"), std::ios::binary) << "0.1 0.2 0.3\n";  // not ours
    }
    Runtime runtime;
    Scene scene(runtime);
    ASSERT_TRUE(scene.loadString(dynamicBody("fileCompliance=\"" + file("c") + "\"")))
        << describe(scene.log());
    EXPECT_EQ(dataText(scene, "/body/precomputed", "loadedFromCache"), "0") << what;
    EXPECT_EQ(warningsWith(scene, "fileCompliance", damage.reason), 1) << what << "\n"
                                                                       << describe(scene.log());
    EXPECT_EQ((complianceOf(scene, "/body/precomputed", H) - reference).cwiseAbs().maxCoeff(), 0)
        << what << ": computed again, the same";
    if (damage.rewritten)
      EXPECT_EQ(std::filesystem::file_size(file("c")), size) << what;
    else
      EXPECT_LT(std::filesystem::file_size(file("c")), 100u) << what << ": left alone";
  }
}

// The body as the precomputed linear model (static, small strain), clamped at x = 0.
std::string modelBody(const std::string& model, const std::string& extra) {
  return "<MeshTopology name=\"mesh\" tetrahedra=\"" + elementsText(beam().tetrahedra) +
         "\"/><MechanicalObject name=\"dofs\" position=\"" + pointsText(beam().points) + "\"/>" +
         "<PrecomputedLinearModel name=\"model\" youngModulus=\"2e5\" poissonRatio=\"0.3\" " +
         model + "/><FixedProjectiveConstraint indices=\"" + clamped() + "\"/>" + extra;
}

TEST_F(PrecomputedCorrection, IsThePrecomputedModelsOwnStaticCompliance) {
  // In the model's node the compliance is its basis, K^-1 on the surface nodes, with the
  // static response (positions by K^-1 f, no velocity): against a static FEM solve of the same
  // small-strain tetrahedra with the assembled correction, H K^-1 H^T to 1e-9 relative.
  const RowMatrix H = probeRows();
  Runtime runtime;
  Scene model(runtime);
  ASSERT_TRUE(
      loadQuietly(model, "<Node name=\"root\" gravity=\"0 0 0\" dt=\"0.01\"><Node name=\"body\">" +
                             modelBody("cacheFile=\"" + file("basis") + "\"",
                                       "<PrecomputedConstraintCorrection name=\"correction\"/>") +
                             "</Node></Node>"));
  ASSERT_TRUE(model.step());
  Runtime runtime2;
  Scene fem(runtime2);
  ASSERT_TRUE(loadQuietly(
      fem, femScene(beam(), "tetrahedra",
                    "<StaticSolver newton_iterations=\"1\"/><SparseLDLSolver/>"
                    "<TetrahedronFEMForceField method=\"small\" youngModulus=\"2e5\" "
                    "poissonRatio=\"0.3\"/><FixedProjectiveConstraint indices=\"" +
                        clamped() + "\"/><LinearSolverConstraintCorrection name=\"assembled\"/>")));
  ASSERT_TRUE(fem.step());
  const Eigen::MatrixXd exact = complianceOf(fem, "/body/assembled", H);
  ASSERT_GT(exact.norm(), 0);
  EXPECT_LT(relativeDifference(complianceOf(model, "/body/correction", H), exact), 1e-9);
  EXPECT_EQ(model.log().count(MessageLevel::warning), 0u) << describe(model.log());
  EXPECT_EQ(dataText(model, "/body/correction", "precomputationTime"), "0") << "nothing computed";
}

TEST_F(PrecomputedCorrection, HoldsAPointOfThePrecomputedModelAsAnImposedDisplacement) {
  // The tip corner (node 62) held by a bilateral constraint to a point 1 cm below and 4 mm
  // aside of its rest position: the multiplier is the force the node needs, and every position
  // that of the model with the same displacement imposed on the node (its reactionForces), to
  // 1e-9 relative; velocities stay zero.
  const Vec3d d(0.004, 0, -0.01), target = beam().points[62] + d;
  char anchor[96];
  std::snprintf(anchor, sizeof anchor, "%.17g %.17g %.17g", target.x(), target.y(), target.z());
  Runtime runtime;
  Scene held(runtime);
  ASSERT_TRUE(loadQuietly(
      held,
      std::string("<Node name=\"root\" gravity=\"0 0 0\" dt=\"0.01\">"
                  "<FreeMotionAnimationLoop/><GenericConstraintSolver tolerance=\"1e-15\" "
                  "maxIterations=\"100\"/><Node name=\"anchor\"><MechanicalObject "
                  "position=\"") +
          anchor + "\"/></Node><Node name=\"body\">" +
          modelBody("cacheFile=\"" + file("basis") + "\"", "<PrecomputedConstraintCorrection/>") +
          "</Node><BilateralLagrangianConstraint name=\"hold\" object1=\"@anchor\" "
          "object2=\"@body\" first_point=\"0\" second_point=\"62\"/></Node>"));
  Runtime runtime2;
  Scene imposed(runtime2);
  ASSERT_TRUE(loadQuietly(imposed,
                          "<Node name=\"root\" gravity=\"0 0 0\" dt=\"0.01\"><Node name=\"body\">" +
                              modelBody("cacheFile=\"" + file("basis") +
                                            "\" imposedIndices=\"62\" "
                                            "imposedDisplacements=\"0.004 0 -0.01\"",
                                        "") +
                              "</Node></Node>"));
  for (int step = 0; step < 3; ++step) {
    ASSERT_TRUE(held.step()) << describe(held.log());
    ASSERT_TRUE(imposed.step());
  }
  const auto& x =
      objectAt<MechanicalState<Vec3Types>>(held, "/body/dofs")->readCoord(VecId::position());
  const auto& reference =
      objectAt<MechanicalState<Vec3Types>>(imposed, "/body/dofs")->readCoord(VecId::position());
  double error = 0, scale = 0;
  for (size_t i = 0; i < x.size(); ++i) {
    error = std::max(error, (x[i] - reference[i]).norm());
    scale = std::max(scale, (reference[i] - beam().points[i]).norm());
  }
  EXPECT_LT(error, 1e-9 * scale);
  EXPECT_LT((x[62] - target).norm(), 1e-12);
  for (const Vec3d& v :
       objectAt<MechanicalState<Vec3Types>>(held, "/body/dofs")->readDeriv(VecId::velocity()))
    EXPECT_EQ(v.norm(), 0.0);
  const auto* forces = dynamic_cast<const Data<std::vector<Vec3d>>*>(
      objectAt<Base>(held, "/hold")->findData("forces"));
  const auto* reactions = dynamic_cast<const Data<std::vector<Vec3d>>*>(
      objectAt<Base>(imposed, "/body/model")->findData("reactionForces"));
  ASSERT_TRUE(forces && reactions);
  ASSERT_EQ(forces->value().size(), 1u);
  ASSERT_EQ(reactions->value().size(), 1u);
  EXPECT_LT((forces->value()[0] - reactions->value()[0]).norm(),
            1e-9 * reactions->value()[0].norm())
      << forces->value()[0].transpose() << " / " << reactions->value()[0].transpose();
}

TEST_F(PrecomputedCorrection, WarmComplianceAndCorrectionAllocateNothing) {
  Runtime runtime;
  Scene scene(runtime);
  ASSERT_TRUE(loadQuietly(scene, dynamicBody("fileCompliance=\"" + file("c") + "\"")));
  ASSERT_TRUE(scene.step());
  Node& body = *scene.root().findChild("body");
  MechanicalOperations mop(body, scene.timing(), body.dt());
  ConstraintResponse response;
  ASSERT_TRUE(body.get<OdeSolver>()->constraintResponse(body.dt(), response));
  auto* correction = objectAt<BaseConstraintCorrection>(scene, "/body/precomputed");
  ASSERT_NE(correction, nullptr);
  const RowMatrix H = probeRows();
  Eigen::MatrixXd W = Eigen::MatrixXd::Zero(H.rows(), H.rows());
  const Eigen::VectorXd lambda = Eigen::VectorXd::LinSpaced(H.rows(), -0.1, 0.1);
  long allocations = 0;
  for (int round = 0; round < 3; ++round) {
    g_allocations = 0;
    g_counting = round == 2;
    W.setZero();
    correction->addCompliance(mop, response, H, W);
    correction->applyCorrection(mop, response, H, lambda);
    g_counting = false;
    allocations = g_allocations;
  }
  EXPECT_EQ(allocations, 0);
}

struct BadInput {
  const char* what;
  std::string xml;
  const char* path;
  const char* field;
  const char* text;
};
void PrintTo(const BadInput& c, std::ostream* out) { *out << c.what; }

class PrecomputedCorrectionBadInput : public ::testing::TestWithParam<BadInput> {};

TEST_P(PrecomputedCorrectionBadInput, IsAnErrorNamingTheComponentAndField) {
  const BadInput& c = GetParam();
  Runtime runtime;
  Scene scene(runtime);
  EXPECT_FALSE(scene.loadString(c.xml)) << c.what;
  EXPECT_TRUE(hasError(scene.log(), c.path, c.field, c.text))
      << c.what << ":\n" << describe(scene.log());
}

std::string pointBody(const std::string& solver, const std::string& state,
                      const std::string& correction) {
  return "<Node name=\"root\" gravity=\"0 0 0\"><Node name=\"body\">" + solver + state +
         "<UniformMass vertexMass=\"1\"/><PrecomputedConstraintCorrection name=\"c\" " +
         correction + "/></Node></Node>";
}

INSTANTIATE_TEST_SUITE_P(
    Lagrangian, PrecomputedCorrectionBadInput,
    ::testing::Values(
        BadInput{"no ODE solver", pointBody("", "<MechanicalObject position=\"0 0 0\"/>", ""),
                 "/root/body/c", "", "needs an ODE solver"},
        BadInput{"basis indices out of range", dynamicBody("basisIndices=\"3 63 70\""),
                 "/root/body/precomputed", "basisIndices",
                 "2 indices out of range of the 63 points: 63 70"},
        BadInput{"rotations without a mesh",
                 pointBody("<EulerImplicitSolver/><SparseLDLSolver/>",
                           "<MechanicalObject position=\"0 0 0  1 0 0\"/>", ""),
                 "/root/body/c", "rotations", "set rotations=\"false\""},
        BadInput{"a negative regularization",
                 pointBody("<EulerImplicitSolver/><SparseLDLSolver/>",
                           "<MechanicalObject position=\"0 0 0\"/>",
                           "rotations=\"false\" regularizationTerm=\"-1\""),
                 "/root/body/c", "regularizationTerm", "-1"},
        BadInput{"a Rigid3d state",
                 pointBody("<EulerImplicitSolver/><SparseLDLSolver/>",
                           "<MechanicalObject template=\"Rigid3d\" position=\"0 0 0 0 0 0 1\"/>",
                           "rotations=\"false\""),
                 "/root/body/c", "", "works on one Vec3d state"},
        BadInput{"forward Euler",
                 pointBody("<EulerExplicitSolver symplectic=\"false\"/>",
                           "<MechanicalObject position=\"0 0 0\"/>", "rotations=\"false\""),
                 "/root/body/c", "", "cannot answer constraint forces"}),
    NameFromWhat());

}  // namespace
}  // namespace stroma::test
