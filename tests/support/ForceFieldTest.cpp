// SPDX-License-Identifier: MIT
#include "support/ForceFieldTest.h"

#include <gtest/gtest.h>

#include <Eigen/Sparse>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <numbers>
#include <random>
#include <sstream>

#include "core/Runtime.h"
#include "core/StateTypes.h"
#include "simulation/ForceField.h"
#include "simulation/Mapping.h"
#include "simulation/Mass.h"
#include "simulation/MechanicalOperations.h"
#include "simulation/Scene.h"

namespace stroma::test {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

void collect(const Node& node, std::vector<BaseForceField*>& fields) {
  for (const auto& o : node.objects())
    if (auto* f = dynamic_cast<BaseForceField*>(o.get())) fields.push_back(f);
  for (const auto& child : node.children()) collect(*child, fields);
}

// The field under test: by path, else the only non-mass field, else the only mass.
BaseForceField* findField(const Node& root, const std::string& path, std::string& why) {
  std::vector<BaseForceField*> fields;
  collect(root, fields);
  if (!path.empty()) {
    for (BaseForceField* f : fields)
      if (f->path() == path) return f;
    why = "no force field at " + path;
    return nullptr;
  }
  std::vector<BaseForceField*> plain, masses;
  for (BaseForceField* f : fields) (dynamic_cast<BaseMass*>(f) ? masses : plain).push_back(f);
  const auto& pick = plain.empty() ? masses : plain;
  if (pick.size() == 1) return pick.front();
  why = pick.empty() ? "the scene has no force field"
                     : "the scene has " + std::to_string(pick.size()) +
                           " force fields: name the one to test in options.forceField";
  return nullptr;
}

// Applies f to each frame or point of every independent state: f(positions of a Vec3 state)
// or f(frames of a Rigid3 state).
template <class PointF, class FrameF>
void forEachTypedState(const std::vector<BaseMechanicalState*>& states, VecId x, PointF&& points,
                       FrameF&& frames) {
  for (BaseMechanicalState* s : states) {
    if (auto* v = dynamic_cast<MechanicalState<Vec3Types>*>(s)) points(v->writeCoord(x));
    if (auto* r = dynamic_cast<MechanicalState<Rigid3Types>*>(s)) frames(r->writeCoord(x));
  }
}

// One run of the checks on a loaded scene.
class Harness {
 public:
  Harness(Scene& scene, BaseForceField& field, const ForceFieldTestOptions& options,
          ForceFieldTestReport& report)
      : m_mop(scene.root(), scene.timing()),
        m_field(field),
        m_options(options),
        m_report(report),
        m_rng(options.seed) {}

  bool setUp() {
    const auto& independent = m_mop.independentStates();
    for (BaseMechanicalState* s : m_field.states())
      if (std::find(independent.begin(), independent.end(), s) == independent.end()) {
        m_report.failure = m_field.path() + " acts on " + (s ? s->path() : "no state") +
                           ", which is not an independent state of the scene";
        return false;
      }
    std::size_t offset = 0;
    for (BaseMechanicalState* s : independent) {
      if (m_options.rotationInvariant && !dynamic_cast<MechanicalState<Vec3Types>*>(s) &&
          !dynamic_cast<MechanicalState<Rigid3Types>*>(s)) {
        m_report.failure = s->path() + " is a " + s->templateName() +
                           " state: the rigid-motion checks (rotationInvariant) move Vec3d and "
                           "Rigid3d states only";
        return false;
      }
      m_offsets.set(s, offset);
      offset += s->matrixSize();
      const auto dim = static_cast<std::size_t>(s->derivDimension());
      for (std::size_t i = 0; i < s->matrixSize(); ++i)
        m_angular.push_back(dim == 6 && i % dim >= 3);
    }
    m_report.dofs = m_mop.systemSize();
    if (m_report.dofs == 0) {
      m_report.failure = "the scene has no degree of freedom";
      return false;
    }
    m_f = m_mop.allocDeriv();
    m_df = m_mop.allocDeriv();
    m_dx = m_mop.allocDeriv();
    m_x0 = m_mop.allocCoord();
    m_report.spacing = typicalSpacing();
    m_mop.vOp(VecId::velocity(), VecId::null());  // forces at rest velocity
    return true;
  }

  void run() {
    const VecId x = VecId::position(), rest = VecId::restPosition();
    // Rest shape, then the perturbed positions x0 every check starts from.
    m_mop.vOp(x, rest);
    const Eigen::VectorXd fRest = force();
    scatter(randomVector(m_report.spacing * m_options.perturbation, m_options.perturbation), m_dx);
    m_mop.vOp(m_x0, rest, m_dx, 1.0);
    m_mop.vOp(x, m_x0);
    const Eigen::VectorXd f0 = force();
    m_report.forceNorm = f0.norm();
    if (m_options.zeroAtRest) m_report.restForce = ratio(fRest.norm(), f0.norm());

    checkDerivatives(f0);
    checkMatrices();
    checkDamping();
    if (m_options.rotationInvariant) {
      checkMomentum(f0);
      checkRigidMotions(f0.norm());
    }
  }

 private:
  // (a) and (b): directional derivatives against central differences.
  void checkDerivatives(const Eigen::VectorXd& f0) {
    const double h = m_options.fdStep;
    MechanicalParams stiffness;
    stiffness.kFactor = 1;
    m_report.dForceError = m_report.dForceNoise = 0;
    if (m_options.hasEnergy) m_report.energyError = m_report.energyNoise = 0;
    for (int k = 0; k < m_options.samples; ++k) {
      const Eigen::VectorXd dir = randomVector(m_report.spacing, 1.0);
      scatter(dir, m_dx);
      m_mop.vOp(VecId::position(), m_x0);
      force();  // the linearization point of addDForce
      m_mop.vOp(m_df, VecId::null());
      m_field.accumulateDForce(stiffness, m_df, m_dx);
      const Eigen::VectorXd Kdx = gather(m_df);

      m_mop.vOp(VecId::position(), m_x0, m_dx, h);
      const Eigen::VectorXd fPlus = force();
      const double ePlus = m_field.energy(MechanicalParams{});
      m_mop.vOp(VecId::position(), m_x0, m_dx, -h);
      const Eigen::VectorXd fMinus = force();
      const double eMinus = m_field.energy(MechanicalParams{});

      // Round-off of a central difference: about eps |f| / h per term.
      const Eigen::VectorXd fd = (fPlus - fMinus) / (2 * h);
      const double roundOff = 100 * kEps * (fPlus.norm() + fMinus.norm()) / (2 * h);
      const double scale = std::max(Kdx.norm(), fd.norm());
      m_report.dForceError = std::max(m_report.dForceError, ratio((Kdx - fd).norm(), scale));
      m_report.dForceNoise = std::max(m_report.dForceNoise, ratio(roundOff, scale));
      if (m_options.hasEnergy) {
        const double dE = (ePlus - eMinus) / (2 * h);
        const double eRoundOff = 100 * kEps * (std::abs(ePlus) + std::abs(eMinus)) / (2 * h);
        const double eScale = f0.norm() * dir.norm();
        m_report.energyError =
            std::max(m_report.energyError, ratio(std::abs(f0.dot(dir) + dE), eScale));
        m_report.energyNoise = std::max(m_report.energyNoise, ratio(eRoundOff, eScale));
      }
    }
    m_mop.vOp(VecId::position(), m_x0);
  }

  // (c): assembled matrices against matrix-free products, and symmetry.
  void checkMatrices() {
    MechanicalParams mp;
    mp.kFactor = 1;
    mp.mFactor = 0;
    mp.bFactor = 0;
    const auto n = static_cast<Eigen::Index>(m_report.dofs);
    m_mop.vOp(VecId::position(), m_x0);
    m_mop.computeForce(MechanicalParams{}, m_f);  // linearization point of every field

    AssembledMatrix fieldK;
    fieldK.begin(m_report.dofs);
    m_field.accumulateKMatrix(mp, fieldK, m_offsets);
    fieldK.finish();
    AssembledMatrix system;
    m_mop.assemble(mp, system);
    const Eigen::SparseMatrix<double>& K = fieldK.matrix();
    const Eigen::SparseMatrix<double>& A = system.matrix();
    if (K.rows() != n || A.rows() != n) {
      m_report.failure = "assembled matrices have " + std::to_string(K.rows()) + " and " +
                         std::to_string(A.rows()) + " rows for " + std::to_string(n) + " dofs";
      return;
    }
    m_report.fieldMatrixError = 0;
    m_report.systemMatrixError = 0;
    for (int k = 0; k < m_options.samples; ++k) {
      const Eigen::VectorXd u = randomVector(1.0, 1.0);
      // The field alone.
      scatter(u, m_dx);
      m_mop.vOp(m_df, VecId::null());
      m_field.accumulateDForce(mp, m_df, m_dx);
      const Eigen::VectorXd Ku = gather(m_df);
      const Eigen::VectorXd KuAssembled = K * u;
      m_report.fieldMatrixError =
          std::max(m_report.fieldMatrixError,
                   ratio((KuAssembled - Ku).norm(), std::max(Ku.norm(), KuAssembled.norm())));
      // The system: assemble() puts the identity at fixed rows and columns, that is
      // P K P + (I - P) with P the projection of the constraints.
      scatter(u, m_dx);
      m_mop.projectResponse(m_dx);
      const Eigen::VectorXd Pu = gather(m_dx);
      m_mop.computeMBKdx(mp, m_df, m_dx);
      m_mop.projectResponse(m_df);
      const Eigen::VectorXd Au = gather(m_df) + (u - Pu);
      const Eigen::VectorXd AuAssembled = A * u;
      m_report.systemMatrixError =
          std::max(m_report.systemMatrixError,
                   ratio((AuAssembled - Au).norm(), std::max(Au.norm(), AuAssembled.norm())));
    }
    if (m_options.conservative) {
      const Eigen::SparseMatrix<double> Kt = K.transpose();
      m_report.asymmetry = ratio((K - Kt).norm(), K.norm());
    }
  }

  // (f) damping: the bFactor part of addDForce and addKToMatrix against the central difference
  // of addForce in the velocities (at the perturbed positions, about zero velocity).
  void checkDamping() {
    const double h = m_options.fdStep;
    MechanicalParams damping;
    damping.kFactor = 0;
    damping.bFactor = 1;
    const VecId v = VecId::velocity();
    m_report.dampingError = m_report.dampingNoise = m_report.dampingMatrixError = 0;
    m_mop.vOp(VecId::position(), m_x0);
    AssembledMatrix B;
    for (int k = 0; k < m_options.samples; ++k) {
      const Eigen::VectorXd dir = randomVector(m_report.spacing, 1.0);
      scatter(dir, m_dx);
      m_mop.vOp(v, VecId::null());
      force();
      m_mop.vOp(m_df, VecId::null());
      m_field.accumulateDForce(damping, m_df, m_dx);
      const Eigen::VectorXd Bdv = gather(m_df);
      if (k == 0) {
        B.begin(m_report.dofs);
        m_field.accumulateKMatrix(damping, B, m_offsets);
        B.finish();
      }
      const Eigen::VectorXd BdvAssembled = B.matrix() * dir;
      m_mop.vOp(v, VecId::null(), m_dx, h);
      const Eigen::VectorXd fPlus = force();
      m_mop.vOp(v, VecId::null(), m_dx, -h);
      const Eigen::VectorXd fMinus = force();
      const Eigen::VectorXd fd = (fPlus - fMinus) / (2 * h);
      const double scale = std::max(Bdv.norm(), fd.norm());
      m_report.dampingError = std::max(m_report.dampingError, ratio((Bdv - fd).norm(), scale));
      m_report.dampingNoise =
          std::max(m_report.dampingNoise,
                   ratio(100 * kEps * (fPlus.norm() + fMinus.norm()) / (2 * h), scale));
      m_report.dampingMatrixError =
          std::max(m_report.dampingMatrixError,
                   ratio((BdvAssembled - Bdv).norm(), std::max(Bdv.norm(), BdvAssembled.norm())));
    }
    m_mop.vOp(v, VecId::null());
  }

  // (e) at the perturbed positions: no net force, no net moment (about the origin).
  void checkMomentum(const Eigen::VectorXd& f0) {
    scatter(f0, m_f);
    Vec3d net = Vec3d::Zero(), moment = Vec3d::Zero();
    double scale = 0, momentScale = 0;
    const auto& states = m_mop.independentStates();
    for (BaseMechanicalState* s : states) {
      if (auto* v = dynamic_cast<MechanicalState<Vec3Types>*>(s)) {
        const auto& x = v->readCoord(VecId::position());
        const auto& f = v->readDeriv(m_f);
        for (std::size_t i = 0; i < x.size(); ++i) {
          net += f[i];
          moment += x[i].cross(f[i]);
          scale += f[i].norm();
          momentScale += x[i].norm() * f[i].norm();
        }
      }
      if (auto* r = dynamic_cast<MechanicalState<Rigid3Types>*>(s)) {
        const auto& x = r->readCoord(VecId::position());
        const auto& f = r->readDeriv(m_f);
        for (std::size_t i = 0; i < x.size(); ++i) {
          net += f[i].linear;
          moment += x[i].center.cross(f[i].linear) + f[i].angular;
          scale += f[i].linear.norm();
          momentScale += x[i].center.norm() * f[i].linear.norm() + f[i].angular.norm();
        }
      }
    }
    m_report.netForce = ratio(net.norm(), scale);
    m_report.netMoment = ratio(moment.norm(), momentScale);
  }

  // (e) f(R rest + t) = 0.
  void checkRigidMotions(double forceScale) {
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    m_report.rigidMotionForce = 0;
    for (int k = 0; k < m_options.samples; ++k) {
      const Vec3d axis = Vec3d(uniform(m_rng), uniform(m_rng), uniform(m_rng)).normalized();
      const Quat q(Eigen::AngleAxisd(std::numbers::pi * uniform(m_rng), axis));
      const Vec3d t = 3 * m_report.spacing * Vec3d(uniform(m_rng), uniform(m_rng), uniform(m_rng));
      m_mop.vOp(VecId::position(), VecId::restPosition());
      forEachTypedState(
          m_mop.independentStates(), VecId::position(),
          [&](std::vector<Vec3d>& x) {
            for (Vec3d& p : x) p = q * p + t;
          },
          [&](std::vector<RigidCoord3>& x) {
            for (RigidCoord3& c : x) {
              c.center = q * c.center + t;
              c.orientation = q * c.orientation;
            }
          });
      m_report.rigidMotionForce =
          std::max(m_report.rigidMotionForce, ratio(force().norm(), forceScale));
    }
    m_mop.vOp(VecId::position(), m_x0);
  }

  // The field's force at the current positions, as a global vector.
  Eigen::VectorXd force() {
    m_mop.vOp(m_f, VecId::null());
    m_field.accumulateForce(MechanicalParams{}, m_f);
    return gather(m_f);
  }

  Eigen::VectorXd gather(VecId v) const {
    Eigen::VectorXd out;
    m_mop.gather(v, out);
    return out;
  }
  void scatter(const Eigen::VectorXd& in, VecId v) { m_mop.scatter(in, v); }

  // Uniform in [-1, 1] per component, times `linear` (translations) or `angular` (rotations).
  Eigen::VectorXd randomVector(double linear, double angular) {
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    Eigen::VectorXd v(static_cast<Eigen::Index>(m_report.dofs));
    for (Eigen::Index i = 0; i < v.size(); ++i)
      v[i] = uniform(m_rng) * (m_angular[static_cast<std::size_t>(i)] ? angular : linear);
    return v;
  }

  // Bounding-box diagonal over the cube root of the number of points; 1 for a single point.
  double typicalSpacing() {
    Eigen::AlignedBox3d box;
    std::size_t count = 0;
    auto add = [&](const Vec3d& p) {
      box.extend(p);
      ++count;
    };
    forEachTypedState(
        m_mop.independentStates(), VecId::restPosition(),
        [&](std::vector<Vec3d>& x) {
          for (const Vec3d& p : x) add(p);
        },
        [&](std::vector<RigidCoord3>& x) {
          for (const RigidCoord3& c : x) add(c.center);
        });
    // Points in a plane or on a line, their missing coordinates 0.
    for (BaseMechanicalState* s : m_mop.independentStates()) {
      if (auto* v = dynamic_cast<MechanicalState<Vec2Types>*>(s))
        for (const Vec2d& p : v->readCoord(VecId::restPosition())) add(Vec3d(p.x(), p.y(), 0));
      if (auto* v = dynamic_cast<MechanicalState<Vec1Types>*>(s))
        for (const Vec1d& p : v->readCoord(VecId::restPosition())) add(Vec3d(p.x(), 0, 0));
    }
    if (count < 2 || box.diagonal().norm() == 0) return 1.0;
    return box.diagonal().norm() / std::cbrt(static_cast<double>(count));
  }

  static double ratio(double value, double scale) {
    if (value == 0) return 0;
    return scale > 0 ? value / scale : std::numeric_limits<double>::infinity();
  }

  MechanicalOperations m_mop;
  BaseForceField& m_field;
  const ForceFieldTestOptions& m_options;
  ForceFieldTestReport& m_report;
  std::mt19937 m_rng;
  StateOffsets m_offsets;
  std::vector<bool> m_angular;  // per system row: a rotation (rigid frames' last 3)
  VecId m_f, m_df, m_dx, m_x0;
};

std::string messagesOf(const MessageLog& log, bool warningsToo) {
  std::string text;
  for (const Message& m : log.messages())
    if (m.level == MessageLevel::error || (warningsToo && m.level == MessageLevel::warning))
      text += formatForConsole(m) + '\n';
  return text;
}

void expectBelow(double value, double bound, const char* what, const ForceFieldTestReport& r) {
  if (value < 0) return;  // not run
  EXPECT_LE(value, bound) << what << " is " << value << ", above " << bound << "\n" << r.describe();
}

}  // namespace

std::string ForceFieldTestReport::describe() const {
  std::ostringstream out;
  if (!failure.empty()) out << "failure: " << failure << '\n';
  out << "dofs " << dofs << ", spacing " << spacing << ", |f| " << forceNorm << '\n';
  auto line = [&](const char* name, double v) {
    out << "  " << name << ": ";
    if (v < 0)
      out << "not run\n";
    else
      out << v << '\n';
  };
  line("(a) energy gradient error", energyError);
  line("(a) its round-off allowance", energyNoise);
  line("(b) addDForce vs finite differences", dForceError);
  line("(b) its round-off allowance", dForceNoise);
  line("(c) field matrix vs addDForce", fieldMatrixError);
  line("(c) system matrix vs matrix-free", systemMatrixError);
  line("(c) asymmetry", asymmetry);
  line("(d) force at rest", restForce);
  line("(e) force under rigid motions", rigidMotionForce);
  line("(e) net force", netForce);
  line("(e) net moment", netMoment);
  line("(f) damping (bFactor) vs finite differences in v", dampingError);
  line("(f) its round-off allowance", dampingNoise);
  line("(f) damping matrix vs addDForce", dampingMatrixError);
  return out.str();
}

ForceFieldTestReport measureForceField(const SceneFactory& makeScene,
                                       const ForceFieldTestOptions& options) {
  ForceFieldTestReport report;
  Runtime runtime;
  Scene scene(runtime);
  if (!makeScene(scene) || !scene.isLoaded() || scene.log().errorCount()) {
    report.failure = "the scene did not load:\n" + messagesOf(scene.log(), true);
    return report;
  }
  if (!options.allowWarnings && scene.log().count(MessageLevel::warning)) {
    report.failure = "loading the scene gave warnings:\n" + messagesOf(scene.log(), true);
    return report;
  }
  BaseForceField* field = findField(scene.root(), options.forceField, report.failure);
  if (!field) return report;
  Harness harness(scene, *field, options, report);
  if (harness.setUp()) harness.run();
  if (scene.log().errorCount() && report.failure.empty())
    report.failure = "the force field reported errors:\n" + messagesOf(scene.log(), false);
  return report;
}

ForceFieldTestReport measureForceField(std::string_view sceneXml,
                                       const ForceFieldTestOptions& options) {
  const std::string xml(sceneXml);
  return measureForceField([&](Scene& scene) { return scene.loadString(xml); }, options);
}

ForceFieldTestReport checkForceField(const SceneFactory& makeScene,
                                     const ForceFieldTestOptions& options) {
  ForceFieldTestReport r = measureForceField(makeScene, options);
  // In the XML output (--gtest_output=xml), and on the console with STROMA_TEST_VERBOSE set.
  testing::Test::RecordProperty("forceFieldTest", r.describe());
  if (std::getenv("STROMA_TEST_VERBOSE")) std::printf("%s", r.describe().c_str());
  EXPECT_TRUE(r.failure.empty()) << r.failure;
  if (!r.failure.empty()) return r;
  EXPECT_GT(r.forceNorm, 0) << "the field gives no force at the perturbed positions: the test "
                               "would prove nothing\n"
                            << r.describe();
  // (a) and (b) err by the truncation of the differences (tolerance) plus their round-off.
  expectBelow(r.energyError, options.tolerance + r.energyNoise, "(a) force + energy gradient", r);
  expectBelow(r.dForceError, options.tolerance + r.dForceNoise,
              "(b) addDForce - finite differences", r);
  expectBelow(r.fieldMatrixError, options.roundOffTolerance, "(c) addKToMatrix - addDForce", r);
  expectBelow(r.systemMatrixError, options.roundOffTolerance,
              "(c) assembled system - matrix-free product", r);
  expectBelow(r.asymmetry, options.roundOffTolerance, "(c) asymmetry of K", r);
  expectBelow(r.dampingError, options.tolerance + r.dampingNoise,
              "(f) damping - finite differences in the velocities", r);
  expectBelow(r.dampingMatrixError, options.roundOffTolerance,
              "(f) addKToMatrix (bFactor) - addDForce (bFactor)", r);
  expectBelow(r.restForce, options.roundOffTolerance, "(d) force at rest", r);
  expectBelow(r.rigidMotionForce, options.roundOffTolerance, "(e) force under rigid motion", r);
  expectBelow(r.netForce, options.roundOffTolerance, "(e) net force", r);
  expectBelow(r.netMoment, options.roundOffTolerance, "(e) net moment", r);
  return r;
}

ForceFieldTestReport checkForceField(std::string_view sceneXml,
                                     const ForceFieldTestOptions& options) {
  const std::string xml(sceneXml);
  return checkForceField([&](Scene& scene) { return scene.loadString(xml); }, options);
}

}  // namespace stroma::test
