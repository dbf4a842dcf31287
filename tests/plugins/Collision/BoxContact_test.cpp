// SPDX-License-Identifier: MIT
// Oriented boxes on rigid frames (OBBCollisionModel) in contact through the penalty response:
// a box resting on a triangulated floor (the kept gap, its weight, no turn), a box dropped on a
// corner tipping flat (the contact's moment), two free boxes colliding (momentum and angular
// momentum kept), the generic force-field test on rigid sides with lever arms, and bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <sstream>

#include "CollisionTestScenes.h"
#include "collision/CollisionPipeline.h"
#include "core/Runtime.h"
#include "core/StateTypes.h"
#include "plugins/TestPlugin/TestSupport.h"
#include "simulation/ForceField.h"
#include "simulation/MechanicalState.h"
#include "simulation/Scene.h"
#include "support/ForceFieldTest.h"
#include "support/TestNames.h"

namespace stroma::test {
namespace {

constexpr double kGravity = 9.81;

std::string text(double x) {
  std::ostringstream out;
  out.precision(17);
  out << x;
  return out.str();
}

std::string text(const Vec3d& v) { return text(v.x()) + " " + text(v.y()) + " " + text(v.z()); }

// "x y z qx qy qz qw".
std::string frame(const Vec3d& x, const Quat& q) {
  return text(x) + " " + text(q.x()) + " " + text(q.y()) + " " + text(q.z()) + " " + text(q.w());
}

// A cube of half side h and mass m on a Rigid3d frame: its inertia per unit mass is
// (2h)^2 / 6 on every axis (isotropic).
std::string cube(const std::string& name, const std::string& position, double m, double h,
                 const std::string& velocity = "0 0 0 0 0 0", double stiffness = 10) {
  const double j = (2 * h) * (2 * h) / 6;
  return "<Node name=\"" + name + "\"><MechanicalObject template=\"Rigid3d\" position=\"" +
         position + "\" velocity=\"" + velocity + "\"/><UniformMass vertexMass=\"" + text(m) +
         " 1 " + text(j) + " 0 0 0 " + text(j) + " 0 0 0 " + text(j) +
         "\"/><OBBCollisionModel extents=\"" + text(h) + " " + text(h) + " " + text(h) +
         "\" contactStiffness=\"" + text(stiffness) + "\"/></Node>";
}

// The floor of PenaltyContact_test: a 2 x 2 m square of two triangles at y = 0, normal +y, split
// along its diagonal x + z = 0.
const std::string kFloor = R"(<Node name="Floor">
    <MechanicalObject name="dofs" position="-1 0 -1  1 0 -1  1 0 1  -1 0 1"/>
    <MeshTopology name="mesh" triangles="0 3 1  1 3 2"/>
    <TriangleCollisionModel simulated="0" moving="0" contactStiffness="10"/>
  </Node>)";

// One large triangle at y = 0, normal +y.
const std::string kWideFloor = R"(<Node name="Floor">
    <MechanicalObject name="dofs" position="-5 0 5  5 0 5  0 0 -5"/>
    <MeshTopology name="mesh" triangles="0 1 2"/>
    <TriangleCollisionModel simulated="0" moving="0" contactStiffness="10"/>
  </Node>)";

const std::string kProximity =
    collisionPipeline(R"(<MinProximityIntersection alarmDistance="0.03" contactDistance="0.01"/>)");

Node* findNode(Node& n, const std::string& name) {
  if (n.name() == name) return &n;
  for (const auto& c : n.children())
    if (Node* f = findNode(*c, name)) return f;
  return nullptr;
}

MechanicalState<Rigid3Types>& frameAt(Scene& scene, const std::string& node) {
  return *findNode(scene.root(), node)->get<MechanicalState<Rigid3Types>>();
}

BaseForceField* penaltyField(Scene& scene) {
  for (const auto& o : scene.root().objects())
    if (auto* ff = dynamic_cast<BaseForceField*>(o.get()))
      if (ff->className() == "PenalityContactForceField") return ff;
  return nullptr;
}

// The contact force (linear part) of the scene's penalty response on frame 0 of `state`.
Vec3d contactForceOn(Scene& scene, MechanicalState<Rigid3Types>& state) {
  BaseForceField* ff = penaltyField(scene);
  if (!ff) return Vec3d::Constant(std::nan(""));
  const VecId f = VecId::externalForce();
  for (BaseMechanicalState* s : ff->states()) {
    if (auto* r = dynamic_cast<MechanicalState<Rigid3Types>*>(s))
      for (RigidDeriv3& v : r->writeDeriv(f)) v = {};
    if (auto* v = dynamic_cast<MechanicalState<Vec3Types>*>(s))
      for (Vec3d& x : v->writeDeriv(f)) x.setZero();
  }
  ff->accumulateForce(MechanicalParams{}, f);
  return state.readDeriv(f)[0].linear;
}

std::size_t contactCount(Scene& scene) {
  std::size_t n = 0;
  for (const ModelPairContacts& pair : scene.root().get<CollisionPhase>()->lastContacts())
    n += pair.contacts.size();
  return n;
}

struct RestCase {
  const char* what;
  Vec3d position;
};
void PrintTo(const RestCase& c, std::ostream* out) { *out << c.what; }

class BoxRestsOnAFloor : public ::testing::TestWithParam<RestCase> {};

TEST_P(BoxRestsOnAFloor, AtTheKeptGapWithItsWeightAndWithoutTurning) {
  // A 20 cm cube of 1 kg under gravity, implicit Euler with damping, settles on its face. Each
  // corner is a contact of stiffness k = 10 x 10 / d0 = 10^4 N/m (d0 = the intersection's
  // contactDistance, 1 cm), so the four carry m g / 4 each and the face rests m g / (4 k) =
  // 0.245 mm below the kept gap d0. Over the floor's diagonal the two corners on it are kept
  // once (by the triangle that owns the edge): the same four contacts.
  const double m = 1, h = 0.1, d0 = 0.01, k = 10.0 * 10.0 / d0;
  Runtime runtime;
  Scene scene(runtime);
  const Vec3d start = GetParam().position + Vec3d(0, h + 0.015, 0);
  const std::string xml = "<Node name=\"root\" dt=\"0.01\" gravity=\"0 -9.81 0\">" + kProximity +
                          kFloor + "<Node name=\"Body\"><EulerImplicitSolver rayleighMass=\"2\"/>" +
                          "<SparseLDLSolver/>" + cube("Box", frame(start, Quat::Identity()), m, h) +
                          "</Node></Node>";
  ASSERT_TRUE(scene.loadString(xml)) << describe(scene.log());
  for (int n = 0; n < 600; ++n) ASSERT_TRUE(scene.step()) << describe(scene.log());
  auto& box = frameAt(scene, "Box");
  const RigidCoord3& x = box.readCoord(VecId::position())[0];
  const RigidDeriv3& v = box.readDeriv(VecId::velocity())[0];
  EXPECT_EQ(contactCount(scene), 4u);
  EXPECT_NEAR(x.center.y() - h, d0 - m * kGravity / (4 * k), 1e-10) << x.center.transpose();
  EXPECT_NEAR(x.center.x(), start.x(), 1e-12);
  EXPECT_NEAR(x.center.z(), start.z(), 1e-12);
  EXPECT_LT(x.orientation.angularDistance(Quat::Identity()), 1e-12) << "the box turned";
  EXPECT_LT(v.linear.norm(), 1e-10);
  EXPECT_LT(v.angular.norm(), 1e-10);
  const Vec3d force = contactForceOn(scene, box);
  EXPECT_NEAR(force.y(), m * kGravity, 1e-9 * m * kGravity);
  EXPECT_NEAR(force.x(), 0, 1e-12);
  EXPECT_NEAR(force.z(), 0, 1e-12);
}

INSTANTIATE_TEST_SUITE_P(Collision, BoxRestsOnAFloor,
                         ::testing::Values(RestCase{"inside_one_triangle", Vec3d(0.5, 0, 0.4)},
                                           RestCase{"over_the_diagonal", Vec3d(0.3, 0, -0.3)}),
                         NameFromWhat());

TEST(BoxContact, ABoxDroppedOnACornerTipsFlat) {
  // The cube's corner (-h, -h, -h) points 10 degrees off straight down, 2 cm above a floor.
  // Only the moment of the corner's contact force about the centre can turn it: it falls onto
  // an edge, then a face, and comes to rest flat at the kept gap (damped implicit Euler).
  const double m = 1, h = 0.1, d0 = 0.01, k = 1e4;
  const Vec3d down =
      Eigen::AngleAxisd(10 * M_PI / 180, Vec3d(1, 0, 2).normalized()) * Vec3d(0, -1, 0);
  const Quat q = Quat::FromTwoVectors(Vec3d(-1, -1, -1).normalized(), down);
  const Vec3d start(0.2, 0.02 + h * std::sqrt(3.0), -0.1);
  Runtime runtime;
  Scene scene(runtime);
  const std::string xml = "<Node name=\"root\" dt=\"0.005\" gravity=\"0 -9.81 0\">" + kProximity +
                          kWideFloor +
                          "<Node name=\"Body\"><EulerImplicitSolver rayleighMass=\"1\"/>"
                          "<SparseLDLSolver/>" +
                          cube("Box", frame(start, q), m, h) + "</Node></Node>";
  ASSERT_TRUE(scene.loadString(xml)) << describe(scene.log());
  auto& box = frameAt(scene, "Box");
  double highest = 0;  // of the centre, after the first contact
  for (int n = 0; n < 4000; ++n) {
    ASSERT_TRUE(scene.step()) << describe(scene.log());
    highest = std::max(highest, box.readCoord(VecId::position())[0].center.y());
  }
  const RigidCoord3& x = box.readCoord(VecId::position())[0];
  const RigidDeriv3& v = box.readDeriv(VecId::velocity())[0];
  // One of its axes is vertical: it lies on a face.
  const Mat3d R = x.orientation.toRotationMatrix();
  const double vertical = (R.transpose() * Vec3d::UnitY()).cwiseAbs().maxCoeff();
  EXPECT_GT(vertical, 1 - 1e-9) << "the box did not tip flat:\n" << R;
  EXPECT_NEAR(x.center.y() - h, d0 - m * kGravity / (4 * k), 1e-7);
  EXPECT_LT(v.linear.norm(), 1e-6);
  EXPECT_LT(v.angular.norm(), 1e-6);
  EXPECT_EQ(contactCount(scene), 4u);
  EXPECT_LT(highest, start.y() + 1e-3) << "it jumped";
}

TEST(BoxContact, TwoFreeBoxesCollidingKeepMomentumAndAngularMomentum) {
  // Two cubes (1 kg with half side 5 cm, 3 kg with 8 cm), spinning, turned, meet off centre
  // without gravity under one explicit (symplectic Euler) solver. The contact forces are equal
  // and opposite at points whose difference is along the force, so the total momentum and the
  // total angular momentum about the origin, sum m c x v + I w (isotropic inertias, so I w is
  // kept by a free body), stay to round-off; the spins change (the contacts' moments).
  const double ma = 1, ha = 0.05, mb = 3, hb = 0.08;
  const double ja = ma * (2 * ha) * (2 * ha) / 6, jb = mb * (2 * hb) * (2 * hb) / 6;
  const Quat qa(Eigen::AngleAxisd(0.4, Vec3d(1, 2, 3).normalized()));
  const Quat qb(Eigen::AngleAxisd(1.1, Vec3d(-2, 1, 1).normalized()));
  Runtime runtime;
  Scene scene(runtime);
  const std::string xml =
      "<Node name=\"root\" dt=\"1e-4\" gravity=\"0 0 0\">" +
      collisionPipeline(
          R"(<MinProximityIntersection alarmDistance="0.01" contactDistance="0.005"/>)") +
      "<Node name=\"Bodies\"><EulerExplicitSolver/>" +
      cube("A", frame(Vec3d(-0.2, 0, 0), qa), ma, ha, "2 0 0  0 0 5", 30) +
      cube("B", frame(Vec3d(0.2, 0.04, 0.02), qb), mb, hb, "-1 0 0  3 0 0", 30) + "</Node></Node>";
  ASSERT_TRUE(scene.loadString(xml)) << describe(scene.log());
  auto& a = frameAt(scene, "A");
  auto& b = frameAt(scene, "B");
  auto momentum = [&] {
    return Vec3d(ma * a.readDeriv(VecId::velocity())[0].linear +
                 mb * b.readDeriv(VecId::velocity())[0].linear);
  };
  auto angularMomentum = [&] {
    const RigidCoord3 &xa = a.readCoord(VecId::position())[0],
                      &xb = b.readCoord(VecId::position())[0];
    const RigidDeriv3 &va = a.readDeriv(VecId::velocity())[0],
                      &vb = b.readDeriv(VecId::velocity())[0];
    return Vec3d(ma * xa.center.cross(va.linear) + ja * va.angular +
                 mb * xb.center.cross(vb.linear) + jb * vb.angular);
  };
  const Vec3d p0 = momentum(), l0 = angularMomentum();
  const Vec3d wa0 = a.readDeriv(VecId::velocity())[0].angular;
  std::size_t contactSteps = 0;
  double pError = 0, lError = 0;
  for (int n = 0; n < 3000; ++n) {
    ASSERT_TRUE(scene.step()) << describe(scene.log());
    if (contactCount(scene) > 0) ++contactSteps;
    pError = std::max(pError, (momentum() - p0).norm());
    lError = std::max(lError, (angularMomentum() - l0).norm());
  }
  EXPECT_GT(contactSteps, 10u) << "they did not meet";
  EXPECT_LT(pError, 1e-12) << "momentum";
  EXPECT_LT(lError, 1e-12) << "angular momentum";
  EXPECT_GT((a.readDeriv(VecId::velocity())[0].angular - wa0).norm(), 0.1)
      << "the contact did not turn A";
  // They parted: the distance of their centres grows.
  const Vec3d apart =
      b.readCoord(VecId::position())[0].center - a.readCoord(VecId::position())[0].center;
  const Vec3d away =
      b.readDeriv(VecId::velocity())[0].linear - a.readDeriv(VecId::velocity())[0].linear;
  EXPECT_GT(apart.dot(away), 0) << "they still approach each other";
  std::printf(
      "momentum kept to %.2e kg m/s, angular momentum to %.2e kg m^2/s over %zu steps "
      "in contact\n",
      pError, lError, contactSteps);
}

// --- The generic force-field test on rigid sides with lever arms ------------------------------

// A scene whose only force field is the penalty response of a box pressed into something, with
// the response's geometric stiffness set as asked.
SceneFactory pressedScene(const std::string& others, bool geometricStiffness) {
  return [others, geometricStiffness](Scene& scene) {
    const std::string xml =
        "<Node name=\"root\" dt=\"0.01\" gravity=\"0 0 0\">" +
        collisionPipeline(
            R"(<MinProximityIntersection alarmDistance="0.03" contactDistance="0.01"/>)") +
        others + "</Node>";
    if (!scene.loadString(xml) || !scene.step()) return false;  // detection: the response
    BaseForceField* ff = penaltyField(scene);
    if (!ff) return false;
    std::string error;
    return ff->findData("geometricStiffness")->read(geometricStiffness ? "1" : "0", error);
  };
}

// A box (half 0.1) turned a little, pressed 2 cm into the floor.
std::string boxOnFloor() {
  const Quat q(Eigen::AngleAxisd(0.05, Vec3d(1, 0, 2).normalized()));
  return kFloor + "<Node name=\"Box\"><MechanicalObject template=\"Rigid3d\" position=\"" +
         frame(Vec3d(0.4, 0.08, 0.3), q) +
         "\"/><OBBCollisionModel extents=\"0.1 0.12 0.08\" contactStiffness=\"10\"/></Node>";
}

// Two boxes, the upper turned by 0.3 rad about the vertical and a little about x, pressed 2 cm
// into each other face to face (an octagon of contacts).
std::string boxOnBox() {
  const Quat q(Eigen::AngleAxisd(0.3, Vec3d::UnitY()) * Eigen::AngleAxisd(0.02, Vec3d::UnitX()));
  return "<Node name=\"Lower\"><MechanicalObject template=\"Rigid3d\" position=\"0 0 0 0 0 0 1\"/>"
         "<OBBCollisionModel extents=\"0.2 0.1 0.2\" contactStiffness=\"10\"/></Node>"
         "<Node name=\"Upper\"><MechanicalObject template=\"Rigid3d\" position=\"" +
         frame(Vec3d(0.03, 0.1 + 0.1 - 0.02, -0.02), q) +
         "\"/><OBBCollisionModel extents=\"0.15 0.1 0.15\" contactStiffness=\"10\"/></Node>";
}

struct ForceFieldCase {
  const char* what;
  std::function<std::string()> scene;
};
void PrintTo(const ForceFieldCase& c, std::ostream* out) { *out << c.what; }

class BoxPenalty : public ::testing::TestWithParam<ForceFieldCase> {};

TEST_P(BoxPenalty, PassesTheForceFieldTestWithTheExactTangent) {
  // With the arms' turn in the stiffness (geometricStiffness) the tangent is exact for the fixed
  // normals: force = -grad(energy), addDForce = the finite difference of the force (in the
  // frames' world rotation vectors), addKToMatrix = addDForce. Not symmetric (the turn of an
  // arm under a force), so the symmetry check is off.
  ForceFieldTestOptions options;
  options.zeroAtRest = false;
  options.rotationInvariant = false;  // the normals are fixed at detection
  options.conservative = false;
  options.perturbation = 1e-3;
  const auto report = measureForceField(pressedScene(GetParam().scene(), true), options);
  ASSERT_TRUE(report.failure.empty()) << report.failure << report.describe();
  EXPECT_GT(report.forceNorm, 0) << report.describe();
  EXPECT_LT(report.energyError, 1e-6) << report.describe();
  EXPECT_LT(report.dForceError, 1e-6) << report.describe();
  EXPECT_LT(report.fieldMatrixError, 1e-9) << report.describe();
  EXPECT_LT(report.systemMatrixError, 1e-9) << report.describe();
}

TEST_P(BoxPenalty, TheSymmetricTangentLeavesOutOnlyTheArmsTurn) {
  // The default stiffness, J^T (k n n^T) J with J = [I, -[r]x] (what the symmetric solvers
  // take): the force is still -grad(energy) and the matrix symmetric and equal to addDForce;
  // against the finite difference it misses the arms' turn, whose relative size is about the
  // penetration over the arm (3 cm / 10 cm here): present, and bounded by that.
  ForceFieldTestOptions options;
  options.zeroAtRest = false;
  options.rotationInvariant = false;
  options.perturbation = 1e-3;
  const auto report = measureForceField(pressedScene(GetParam().scene(), false), options);
  ASSERT_TRUE(report.failure.empty()) << report.failure << report.describe();
  EXPECT_LT(report.energyError, 1e-6) << report.describe();
  EXPECT_LT(report.fieldMatrixError, 1e-9) << report.describe();
  EXPECT_LT(report.systemMatrixError, 1e-9) << report.describe();
  EXPECT_LT(report.asymmetry, 1e-12) << report.describe();
  EXPECT_GT(report.dForceError, 1e-4) << report.describe();
  EXPECT_LT(report.dForceError, 0.3) << report.describe();
  std::printf("%s: addDForce against the finite difference without the arms' turn: %.3g\n",
              GetParam().what, report.dForceError);
}

INSTANTIATE_TEST_SUITE_P(Collision, BoxPenalty,
                         ::testing::Values(ForceFieldCase{"box_pressed_into_a_floor", boxOnFloor},
                                           ForceFieldCase{"two_boxes_pressed_together", boxOnBox}),
                         NameFromWhat());

// --- Bad input ---------------------------------------------------------------------------------

struct BadBoxInput {
  const char* what;
  std::string xml;    ///< inside the root node
  const char* field;  ///< the field the error names ("" for none)
  const char* text;   ///< part of the error
};
void PrintTo(const BadBoxInput& c, std::ostream* out) { *out << c.what; }

class OBBBadInput : public ::testing::TestWithParam<BadBoxInput> {};

TEST_P(OBBBadInput, IsAnErrorNamingTheComponentAndField) {
  const BadBoxInput& c = GetParam();
  Runtime runtime;
  Scene scene(runtime);
  EXPECT_FALSE(scene.loadString("<Node name=\"root\">" + kProximity + c.xml + "</Node>"));
  bool found = false;
  for (const Message& m : errors(scene.log()))
    found |= m.componentPath == "/root/A/boxes" && m.field == c.field &&
             m.text.find(c.text) != std::string::npos;
  EXPECT_TRUE(found) << c.what << ":\n" << describe(scene.log());
}

INSTANTIATE_TEST_SUITE_P(
    Collision, OBBBadInput,
    ::testing::Values(BadBoxInput{"on_a_Vec3d_state",
                                  "<Node name=\"A\"><MechanicalObject position=\"0 0 0\"/>"
                                  "<OBBCollisionModel name=\"boxes\"/></Node>",
                                  "",
                                  "is for rigid frames (template Rigid3d): the state "
                                  "/root/A/mechanicalObject beside it is Vec3d"},
                      BadBoxInput{"without_a_state",
                                  "<Node name=\"A\"><OBBCollisionModel name=\"boxes\"/></Node>", "",
                                  "needs a mechanical state of template Rigid3d"},
                      BadBoxInput{"a_negative_extent",
                                  "<Node name=\"A\"><MechanicalObject template=\"Rigid3d\" "
                                  "position=\"0 0 0 0 0 0 1\"/>"
                                  "<OBBCollisionModel name=\"boxes\" extents=\"1 -0.5 1\"/></Node>",
                                  "extents", ">= 0"},
                      BadBoxInput{"a_negative_default_extent",
                                  "<Node name=\"A\"><MechanicalObject template=\"Rigid3d\" "
                                  "position=\"0 0 0 0 0 0 1\"/>"
                                  "<OBBCollisionModel name=\"boxes\" defaultExtent=\"-1\"/></Node>",
                                  "defaultExtent", ">= 0"}),
    NameFromWhat());

TEST(OBBCollisionModel, ExtentsDefaultToDefaultExtentAndFollowTheFrames) {
  // Two frames, one extent given: the second box takes defaultExtent (a warning, as for
  // SphereCollisionModel's listRadius); each box is centred on its frame and turned with it.
  Runtime runtime;
  Scene scene(runtime);
  const Quat q(Eigen::AngleAxisd(0.7, Vec3d(0, 0, 1)));
  ASSERT_TRUE(scene.loadString("<Node name=\"root\">" + kProximity +
                               "<Node name=\"A\"><MechanicalObject template=\"Rigid3d\" "
                               "position=\"0 0 0 0 0 0 1  " +
                               frame(Vec3d(1, 2, 3), q) +
                               "\"/><OBBCollisionModel name=\"boxes\" extents=\"0.1 0.2 0.3\" "
                               "defaultExtent=\"0.5\"/></Node></Node>"))
      << describe(scene.log());
  bool warned = false;
  for (const Message& m : scene.log().messages())
    warned |= m.level == MessageLevel::warning && m.componentPath == "/root/A/boxes" &&
              m.field == "extents" &&
              m.text.find("has 1 extents for the 2 frames") != std::string::npos;
  EXPECT_TRUE(warned) << describe(scene.log());
  const auto* model =
      dynamic_cast<const CollisionModel*>(scene.root().children().front()->findObject("boxes"));
  ASSERT_NE(model, nullptr);
  const CollisionGeometry& g = model->geometry();
  ASSERT_EQ(g.kind, PrimitiveKind::box);
  ASSERT_EQ(g.boxes.size(), 2u);
  EXPECT_EQ(g.boxes[0].halfExtents, Vec3d(0.1, 0.2, 0.3));
  EXPECT_EQ(g.boxes[1].halfExtents, Vec3d::Constant(0.5));
  EXPECT_EQ(g.boxes[1].center, Vec3d(1, 2, 3));
  EXPECT_LT((g.boxes[1].rotation - q.toRotationMatrix()).norm(), 1e-15);
  // Its box for the broad phase: |R| h around the centre.
  std::vector<Aabb> boxes;
  model->computeBoxes(boxes, 0);
  const Vec3d half = q.toRotationMatrix().cwiseAbs() * Vec3d::Constant(0.5);
  EXPECT_LT((boxes[1].max - (Vec3d(1, 2, 3) + half)).norm(), 1e-15);
}

TEST(CubeCollisionModel, IsAcceptedAndAddsNothing) {
  // SOFA's hierarchy of cubes over another model: a scene that names it loads, and it adds no
  // primitive (the sphere alone meets the floor).
  Runtime runtime;
  Scene scene(runtime);
  ASSERT_TRUE(scene.loadString(
      "<Node name=\"root\" dt=\"0.01\" gravity=\"0 -9.81 0\">" + kProximity + kFloor +
      "<Node name=\"Ball\"><EulerImplicitSolver/><SparseLDLSolver/>"
      "<MechanicalObject position=\"0.5 0.06 0.4\"/><UniformMass vertexMass=\"0.1\"/>"
      "<CubeCollisionModel name=\"cubes\" moving=\"1\" contactStiffness=\"5\"/>"
      "<SphereCollisionModel radius=\"0.05\"/></Node></Node>"))
      << describe(scene.log());
  ASSERT_TRUE(scene.step()) << describe(scene.log());
  const auto* cubes =
      dynamic_cast<const CollisionModel*>(findNode(scene.root(), "Ball")->findObject("cubes"));
  ASSERT_NE(cubes, nullptr);
  EXPECT_EQ(cubes->geometry().primitiveCount(), 0u);
  EXPECT_EQ(contactCount(scene), 1u);
}

}  // namespace
}  // namespace stroma::test
