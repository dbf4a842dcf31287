// SPDX-License-Identifier: MIT
// Seed 004's table 2: how much the volume of a body changes under load with the linear
// tensor-mass model, the St Venant-Kirchhoff one, and the latter with the incompressibility
// penalty, at static equilibrium under three loads: on the cylinder of figures 3 and 5 (bottom
// face fixed, top face pushed to the right) and on the organ of figure 6 (held by its left
// lobe, forces on its right lobe). Our meshes, materials and loads differ from the paper's, so
// the test asserts the ordering of the models, how fast the linear model's variation grows,
// and the orders of magnitude; it prints our figures beside the paper's.
//
// The three stages are the loads F, 2F and 3F: the paper's linear figures 7, 28, 63 % are
// 7 x 1, 4, 9, the volume change of a linear model growing as the square of its displacement.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include "core/Data.h"
#include "plugins/SolidMechanics/FemTestScenes.h"
#include "plugins/TestPlugin/TestSupport.h"
#include "topology/Topology.h"

namespace stroma::test {
namespace {

enum class Model { linear, stvk, stvkPenalty };
constexpr std::array<Model, 3> kModels{Model::linear, Model::stvk, Model::stvkPenalty};
constexpr int kStages = 3;
constexpr double kNotGiven = -1;

/// One body of the study: a mesh of share/, where it is held, where and how it is pushed.
struct Body {
  std::string name;
  std::string mesh;                   ///< file under share/
  std::string fixedBox;               ///< BoxROI of the fixed points (rest positions, m)
  std::string loadedBox;              ///< BoxROI of the pushed points (m)
  Vec3d direction;                    ///< of the force (unit)
  std::array<double, kStages> loads;  ///< total force of each stage (N)
  int increments;                     ///< load steps from one stage to the next
  double youngModulus;                ///< Pa
  double poissonRatio;
  double penaltyStiffness;  ///< gamma of TetrahedralVolumePenaltyForceField (Pa)
  double length;            ///< the length the displacement is compared with (m)
  /// Seed 004 table 2 (%), [model][stage]; kNotGiven where the paper has no figure.
  std::array<std::array<double, kStages>, 3> paper;
};

/// Bottom face (y = 0) fixed, 0.11, 0.22 and 0.33 N to the right (+x) on the top face
/// (y = 0.1 m); the material of scenes/tensormass/Cylinder.scn.
Body cylinder() {
  return {"cylinder",
          "mesh/cylinder.msh",
          "-0.03 -0.001 -0.03  0.03 0.001 0.03",
          "-0.03 0.099 -0.03  0.03 0.101 0.03",
          Vec3d(1, 0, 0),
          {0.11, 0.22, 0.33},
          4,
          1e4,
          0.45,
          1e6,
          0.1,
          {{{7, 28, 63}, {0.3, 1, 2}, {0.2, 0.5, 1}}}};
}

/// The top of the left lobe fixed (y > 0.025 m, x < -0.06 m, 148 points), 0.075, 0.15 and
/// 0.225 N downwards on the tip of the right lobe (x > 0.045 m, 40 points), the setting of
/// scenes/tensormass/Organ.scn. The paper gives one figure per model for its liver; they are
/// printed beside our middle stage, where the linear model's variation is closest to its 9 %.
/// The StVK model stops converging near 0.26 N (its tangent becomes indefinite: St Venant-
/// Kirchhoff softens under strong compression), hence the last stage's 0.225 N.
Body organ() {
  return {"organ",
          "mesh/organ.msh",
          "-0.15 0.025 -0.05  -0.06 0.06 0.05",
          "0.045 -0.1 -0.1  0.1 0.1 0.1",
          Vec3d(0, -1, 0),
          {0.075, 0.15, 0.225},
          5,
          3e3,
          0.45,
          3e5,
          0.15,
          {{{kNotGiven, 9, kNotGiven}, {kNotGiven, 1.5, kNotGiven}, {kNotGiven, 0.7, kNotGiven}}}};
}

std::string forceFields(const Body& body, Model model) {
  const std::string material = "youngModulus=\"" + std::to_string(body.youngModulus) +
                               "\" poissonRatio=\"" + std::to_string(body.poissonRatio) + "\"";
  if (model == Model::linear) return "<TetrahedralTensorMassForceField " + material + "/>";
  std::string xml = "<TetrahedralStVKTensorMassForceField " + material + "/>";
  if (model == Model::stvkPenalty)
    xml += "<TetrahedralVolumePenaltyForceField stiffness=\"" +
           std::to_string(body.penaltyStiffness) + "\"/>";
  return xml;
}

/// Static equilibrium by Newton-Raphson and a direct solver, one load step per time step. The
/// iterations stop only when the residual |R| = |f_internal + f_external| is below 1e-9 N
/// (the correction criteria, which a short line-search step could meet, are off).
std::string staticScene(const Body& body, Model model) {
  return R"(<Node name="root" dt="1" gravity="0 0 0">
  <Node name="body">
    <StaticSolver name="solver" newton_iterations="40" absolute_residual_tolerance_threshold="1e-9"
                  relative_residual_tolerance_threshold="0" absolute_correction_tolerance_threshold="0"
                  relative_correction_tolerance_threshold="0"/>
    <SparseLDLSolver/>
    <MeshGmshLoader name="loader" filename=")" +
         body.mesh + R"("/>
    <TetrahedronSetTopologyContainer name="topology" src="@loader"/>
    <MechanicalObject name="dofs" template="Vec3" src="@loader"/>
    )" + forceFields(body, model) +
         R"(
    <BoxROI name="fixedBox" box=")" +
         body.fixedBox + R"(" position="@dofs.rest_position"/>
    <FixedConstraint indices="@fixedBox.indices"/>
    <BoxROI name="loadedBox" box=")" +
         body.loadedBox + R"(" position="@dofs.rest_position"/>
    <ConstantForceField name="load" indices="@loadedBox.indices" totalForce="0 0 0"/>
  </Node>
</Node>)";
}

/// One model at one stage, at equilibrium.
struct Stage {
  double volumeChange = 0;  ///< (V - V0) / V0 of the whole body
  double displacement = 0;  ///< mean displacement of the pushed points along the force (m)
  double residual = 1e300;  ///< |R| at the end of the last load step (N)
  bool converged = false;   ///< every load step of the stage met |R| <= 1e-9 N
};

double volume(const Topology& topology, const std::vector<Vec3d>& p) {
  double v = 0;
  for (const Tetrahedron& t : topology.tetrahedra())
    v += (p[t[1]] - p[t[0]]).dot((p[t[2]] - p[t[0]]).cross(p[t[3]] - p[t[0]])) / 6;
  return v;
}

template <class T>
const T& dataValue(Base& object, const std::string& name) {
  const auto* data = dynamic_cast<const Data<T>*>(object.findData(name));
  EXPECT_NE(data, nullptr) << name;
  static const T none{};
  return data ? data->value() : none;
}

/// The three stages of one model, each reached from the previous equilibrium in
/// `body.increments` load steps. Each step starts from the secant prediction along the
/// equilibrium path, x_k + (x_k - x_{k-1}) (F_{k+1} - F_k) / (F_k - F_{k-1}), which Newton
/// corrects in 2 to 5 iterations (the first step, from rest, in 7 to 12).
std::array<Stage, kStages> runStages(const Body& body, Model model) {
  std::array<Stage, kStages> stages{};
  Runtime runtime;
  Scene scene(runtime);
  if (!scene.loadString(staticScene(body, model))) {
    ADD_FAILURE() << describe(scene.log());
    return stages;
  }
  auto* dofs = objectAt<MechanicalState<Vec3Types>>(scene, "/root/body/dofs");
  auto* topology = objectAt<Topology>(scene, "/root/body/topology");
  auto* solver = objectAt<Base>(scene, "/root/body/solver");
  auto* load = objectAt<Base>(scene, "/root/body/load");
  auto* loaded = objectAt<Base>(scene, "/root/body/loadedBox");
  if (!dofs || !topology || !solver || !load || !loaded) return stages;
  const std::vector<Vec3d> rest = dofs->readCoord(VecId::restPosition());
  const std::vector<unsigned>& pushed = dataValue<std::vector<unsigned>>(*loaded, "indices");
  EXPECT_FALSE(pushed.empty());
  const double restVolume = volume(*topology, rest);

  std::vector<Vec3d> previousX = rest;
  double previousLoad = 0, currentLoad = 0;
  for (int s = 0; s < kStages; ++s) {
    Stage& stage = stages[s];
    stage.converged = true;
    const double stageStart = currentLoad;
    for (int k = 1; k <= body.increments; ++k) {
      const double next = stageStart + (body.loads[s] - stageStart) * k / body.increments;
      // Secant predictor (none at the first step: the first Newton step is the linear one).
      std::vector<Vec3d> x = dofs->readCoord(VecId::position());
      const std::vector<Vec3d> currentX = x;
      if (currentLoad > 0)
        for (std::size_t i = 0; i < x.size(); ++i)
          x[i] +=
              (currentX[i] - previousX[i]) * ((next - currentLoad) / (currentLoad - previousLoad));
      dofs->writeCoord(VecId::position()) = x;
      previousX = currentX;
      previousLoad = currentLoad;
      currentLoad = next;
      // Newton at the new load.
      std::string why;
      const Vec3d f = next * body.direction;
      std::ostringstream force;
      force.precision(17);
      force << f.x() << ' ' << f.y() << ' ' << f.z();
      EXPECT_TRUE(load->findData("totalForce")->read(force.str(), why)) << why;
      EXPECT_TRUE(scene.step()) << describe(scene.log());
      stage.converged = stage.converged && dataValue<bool>(*solver, "lastConverged");
    }
    const std::vector<Vec3d>& x = dofs->readCoord(VecId::position());
    stage.volumeChange = volume(*topology, x) / restVolume - 1;
    for (unsigned i : pushed) stage.displacement += (x[i] - rest[i]).dot(body.direction);
    stage.displacement /= static_cast<double>(pushed.size());
    stage.residual = dataValue<double>(*solver, "lastResidual");
  }
  EXPECT_EQ(scene.log().count(MessageLevel::warning) + scene.log().errorCount(), 0u)
      << describe(scene.log());
  return stages;
}

using Results = std::array<std::array<Stage, kStages>, 3>;  // [model][stage]

std::string percent(double fraction) {
  char text[32];
  std::snprintf(text, sizeof text, "%+.2f", 100 * fraction);
  return text;
}

std::string paperPercent(double value) {
  if (value == kNotGiven) return "    -";
  char text[32];
  std::snprintf(text, sizeof text, "%5g", value);
  return text;
}

/// Our figures beside the paper's; its stages are named after their place in figures 3 and 5
/// (left, middle, right). The displacement is that of the pushed points along the force, for
/// the three models.
void printReport(const Body& body, const Results& r) {
  std::printf(
      "[ seed 004 table 2 ] %s: volume change (V - V0) / V0 at static equilibrium, %% ours "
      "(paper)\n"
      "  stage    load (N)  displacement / L    linear           StVK             StVK + penalty\n"
      "                     lin.  StVK  pen.\n",
      body.name.c_str());
  const char* names[kStages] = {"left  ", "middle", "right "};
  for (int s = 0; s < kStages; ++s) {
    std::printf("  %s   %5.3f    %.2f  %.2f  %.2f", names[s], body.loads[s],
                r[0][s].displacement / body.length, r[1][s].displacement / body.length,
                r[2][s].displacement / body.length);
    for (std::size_t m = 0; m < kModels.size(); ++m)
      std::printf("   %7s (%s)", percent(r[m][s].volumeChange).c_str(),
                  paperPercent(body.paper[m][s]).c_str());
    std::printf("\n");
  }
}

/// The assertions of issue 4 on one body.
void checkStudy(const Body& body) {
  Results r;
  for (std::size_t m = 0; m < kModels.size(); ++m) r[m] = runStages(body, kModels[m]);
  printReport(body, r);
  const auto change = [&](Model m, int s) {
    return std::abs(r[static_cast<int>(m)][s].volumeChange);
  };

  // At rest: every load step converged to |R| <= 1e-9 N.
  for (std::size_t m = 0; m < kModels.size(); ++m)
    for (int s = 0; s < kStages; ++s) {
      SCOPED_TRACE("model " + std::to_string(m) + ", stage " + std::to_string(s));
      EXPECT_TRUE(r[m][s].converged);
      EXPECT_LE(r[m][s].residual, 1e-9);
    }
  // Real deformation stages: the StVK body bends further at each load, its pushed points by a
  // good part of the body's length at the last.
  for (int s = 1; s < kStages; ++s) EXPECT_GT(r[1][s].displacement, 1.3 * r[1][s - 1].displacement);
  EXPECT_GT(r[1][2].displacement, 0.25 * body.length);

  for (int s = 0; s < kStages; ++s) {
    SCOPED_TRACE("stage " + std::to_string(s));
    // The ordering of table 2.
    EXPECT_GT(change(Model::linear, s), 3 * change(Model::stvk, s));
    EXPECT_LT(change(Model::stvkPenalty, s), change(Model::stvk, s));
    // The linear model swells; the others nearly keep their volume.
    EXPECT_GT(r[0][s].volumeChange, 0);
  }
  // The linear model's variation grows with the load much faster than the others' (paper:
  // +56 % from the first stage to the last, against +1.7 % and +0.8 %).
  const double linearGrowth = change(Model::linear, 2) - change(Model::linear, 0);
  EXPECT_GT(linearGrowth, 10 * (change(Model::stvk, 2) - change(Model::stvk, 0)));
  EXPECT_GT(linearGrowth, 10 * (change(Model::stvkPenalty, 2) - change(Model::stvkPenalty, 0)));
  // As the square of the load (the paper's 7 : 28 : 63 = 1 : 4 : 9).
  EXPECT_NEAR(change(Model::linear, 1) / change(Model::linear, 0), 4, 0.5);
  EXPECT_NEAR(change(Model::linear, 2) / change(Model::linear, 0), 9, 1.5);
  // Orders of magnitude: the linear model several to tens of %, StVK about 1 % at the largest
  // load, the penalty below it.
  EXPECT_GT(change(Model::linear, 1), 0.05);
  EXPECT_GT(change(Model::linear, 2), 0.1);
  EXPECT_LT(change(Model::linear, 2), 1.0);
  EXPECT_GT(change(Model::stvk, 2), 0.003);
  EXPECT_LT(change(Model::stvk, 2), 0.03);
  EXPECT_LT(change(Model::stvkPenalty, 2), 0.7 * change(Model::stvk, 2));
}

TEST(VolumeVariation, CylinderAtThreeBendingStages) { checkStudy(cylinder()); }

TEST(VolumeVariation, OrganWithForcesOnItsRightLobe) { checkStudy(organ()); }

}  // namespace
}  // namespace stroma::test
