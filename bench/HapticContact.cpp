// SPDX-License-Identifier: MIT
// stroma-bench-haptic: the contact force on a rigid probe pressed into the organ, at haptic
// rates (issue 16 item 6; seed 000 chapter 2, force feedback). bench/README.md has the numbers
// and the command. Timings are never pass/fail: the ctest entry only checks that every entry
// runs.
//
// The organ: share/mesh/organ.msh (935 points, 3579 tetrahedra), E = 30 kPa, nu = 0.45, its
// base fixed (the points below y = -0.03 m), as scenes/collision/InstrumentOnOrgan.scn. The
// probe: a sphere of radius 8 mm on a Rigid3d frame without a solver (a haptic device drives
// it: its pose and velocity are written before each step), pressed 4 mm into the top of the
// right lobe, then sliding round an ellipse of 1 cm x 0.5 cm in the surface's plane once a
// second. Contacts as Lagrangian constraints: FreeMotionAnimationLoop, GenericConstraintSolver,
// CollisionPipeline with LocalMinDistance and CollisionResponse FrictionContactConstraint
// (frictionless by default, the "friction" entry mu = 0.3). dt = 1 ms.
//
// Entries (each iteration is a block of 100 steps along the path, after 0.45 s untimed; steps/s
// per processor second, as Google Benchmark's rates are, wall time in the Time column; the
// phases per step (wall) from the scene's timing; contactRows the mean constraint rows per step;
// force_N the mean magnitude of the force on the probe, its constraintForce):
//   Precomputed         PrecomputedLinearModel with PrecomputedConstraintCorrection: the
//                       model's own compliance (its basis, K^-1 on the surface), no solve.
//   Precomputed/friction   the same with Coulomb friction, mu = 0.3.
//   FEM/LinearSolverConstraintCorrection   corotational TetrahedronFEMForceField (large),
//                       DiagonalMass, EulerImplicitSolver + SparseLDLSolver; the compliance by
//                       one solve per row with the step's factorization.
//   FEM/PrecomputedConstraintCorrection    the same organ; the compliance of A at rest (cached
//                       on disk), turned per node.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "core/Runtime.h"
#include "core/StateTypes.h"
#include "simulation/MechanicalState.h"
#include "simulation/Scene.h"

namespace stroma::bench {
namespace {

constexpr double kDt = 0.001;
constexpr double kRadius = 0.008;
constexpr double kDepth = 0.004;

/// Steps per benchmark iteration: STROMA_BENCH_STEPS, default 100 (the smoke test uses 5); the
/// untimed approach before them is 4.5 times as many (0.45 s: pressed in, a quarter turn).
int stepsPerBlock() {
  const char* env = std::getenv("STROMA_BENCH_STEPS");
  const int steps = env ? std::atoi(env) : 100;
  return steps > 0 ? steps : 100;
}

std::string organScene(const std::string& solver, double mu) {
  return R"(<Node name="root" dt="0.001" gravity="0 0 0">
  <FreeMotionAnimationLoop/>
  <GenericConstraintSolver tolerance="1e-9" maxIterations="500"/>
  <CollisionPipeline/><BruteForceBroadPhase/><BVHNarrowPhase/>
  <LocalMinDistance alarmDistance="0.004" contactDistance="0.0005"/>
  <CollisionResponse response="FrictionContactConstraint" responseParams="mu=)" +
         std::to_string(mu) + R"("/>
  <Node name="Organ">
    <MeshGmshLoader name="loader" filename="mesh/organ.msh"/>
    <TetrahedronSetTopologyContainer name="topology" src="@loader"/>
    <MechanicalObject name="dofs" template="Vec3" src="@loader"/>
    )" + solver +
         R"(
    <BoxROI name="base" box="-0.2 -0.1 -0.1  0.1 -0.03 0.1" position="@dofs.rest_position"/>
    <FixedConstraint name="fixed" indices="@base.indices"/>
    <Node name="Surface">
      <TriangleSetTopologyContainer name="surface"/>
      <Tetra2TriangleTopologicalMapping input="@../topology" output="@surface"/>
      <TriangleCollisionModel/><LineCollisionModel/><PointCollisionModel/>
    </Node>
  </Node>
  <Node name="Probe">
    <MechanicalObject name="frame" template="Rigid3d" position="0.03 0.1 0  0 0 0 1"/>
    <SphereCollisionModel radius="0.008"/>
  </Node>
</Node>)";
}

const char* kPrecomputed = R"(<PrecomputedLinearModel youngModulus="30000" poissonRatio="0.45"/>
    <PrecomputedConstraintCorrection/>)";
const char* kFem = R"(<EulerImplicitSolver rayleighStiffness="0.005" rayleighMass="1"/>
    <SparseLDLSolver/>
    <DiagonalMass massDensity="1060"/>
    <TetrahedronFEMForceField method="large" youngModulus="30000" poissonRatio="0.45"/>)";

/// The probe's path: down from 2 cm above the contact point over the first 0.2 s, then round
/// the ellipse (x +- 1 cm, z +- 0.5 cm) once a second at the pressed height.
struct ProbePath {
  Vec3d centre;  // the sphere's centre pressed kDepth into the surface's top
  Vec3d at(double t) const {
    constexpr double kDescent = 0.2;
    if (t < kDescent) return centre + Vec3d(0, 0.02 * (1 - t / kDescent), 0);
    const double a = 2 * M_PI * (t - kDescent);
    return centre + Vec3d(0.01 * std::sin(a), 0, 0.005 * (1 - std::cos(a)));
  }
};

/// The top of the organ under x = 0.03, z = 0 (its highest rest point within 1 cm).
Vec3d pressedCentre(const std::vector<Vec3d>& rest) {
  double top = -1e9;
  for (const Vec3d& p : rest)
    if (std::hypot(p.x() - 0.03, p.z()) < 0.01) top = std::max(top, p.y());
  return Vec3d(0.03, top + kRadius - kDepth, 0);
}

void hapticContact(benchmark::State& state, const std::string& solver, double mu) {
  Runtime runtime;
  Scene scene(runtime);
  const auto where = std::filesystem::path(STROMA_SOURCE_DIR) / "bench/haptic.scn";
  if (!scene.loadString(organScene(solver, mu), where)) {
    std::string text;
    for (const Message& m : scene.log().messages()) text += formatForConsole(m) + "\n";
    state.SkipWithError(("the organ scene did not load:\n" + text).c_str());
    return;
  }
  scene.setThreadCount(1);
  auto* organ = scene.root().findChild("Organ")->get<MechanicalState<Vec3Types>>();
  auto* probe = scene.root().findChild("Probe")->get<MechanicalState<Rigid3Types>>();
  const ProbePath path{pressedCentre(organ->readCoord(VecId::restPosition()))};
  long long step = 0;
  auto advance = [&] {
    // The device's pose at the end of the step and its mean velocity over it.
    const double t = double(step++) * kDt;
    probe->writeCoord(VecId::position())[0].center = path.at(t + kDt);
    RigidDeriv3& twist = probe->writeDeriv(VecId::velocity())[0];
    twist.linear = (path.at(t + kDt) - path.at(t)) / kDt;
    twist.angular.setZero();
    return scene.step();
  };
  // Pressed in (0.2 s) and a quarter turn, untimed.
  const int block = stepsPerBlock();
  for (int k = 0; k < block * 9 / 2; ++k)
    if (!advance()) {
      state.SkipWithError("a step failed while pressing the probe in");
      return;
    }
  scene.timing().clear();
  double rows = 0, force = 0;
  long long steps = 0;
  const auto* loop = scene.root().findObject("freeMotionAnimationLoop");
  const auto* rowCount =
      loop ? dynamic_cast<const Data<int>*>(loop->findData("constraintRows")) : nullptr;
  for (auto _ : state) {
    for (int k = 0; k < block; ++k) {
      if (!advance()) {
        state.SkipWithError("a step failed");
        return;
      }
      rows += rowCount ? rowCount->value() : 0;
      // What a device renders: the constraint force on the probe (FreeMotionAnimationLoop's
      // H^T lambda on the probe's state).
      if (const auto& f = probe->readDeriv(VecId::constraintForce()); !f.empty())
        force += f[0].linear.norm();
    }
    steps += block;
  }
  state.counters["steps/s"] = benchmark::Counter(double(steps), benchmark::Counter::kIsRate);
  state.counters["contactRows"] = rows / double(std::max(1LL, steps));
  state.counters["force_N"] = force / double(std::max(1LL, steps));
  for (const char* phase : {"freeMotion", "collision", "constraints"})
    state.counters[std::string(phase) + "_us"] =
        1e6 * scene.timing().seconds(phase) / double(std::max(1LL, steps));
}

void registerEntries() {
  struct Entry {
    const char* name;
    std::string solver;
    double mu;
  };
  const std::string fem = kFem;
  for (const Entry& e : {Entry{"HapticContact/Precomputed", kPrecomputed, 0.0},
                         Entry{"HapticContact/Precomputed/friction", kPrecomputed, 0.3},
                         Entry{"HapticContact/FEM/LinearSolverConstraintCorrection",
                               fem + "<LinearSolverConstraintCorrection/>", 0.0},
                         Entry{"HapticContact/FEM/PrecomputedConstraintCorrection",
                               fem + "<PrecomputedConstraintCorrection/>", 0.0}})
    benchmark::RegisterBenchmark(e.name, [solver = e.solver, mu = e.mu](benchmark::State& s) {
      hapticContact(s, solver, mu);
    })->Unit(benchmark::kMillisecond);
}

}  // namespace
}  // namespace stroma::bench

int main(int argc, char** argv) {
  stroma::bench::registerEntries();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
