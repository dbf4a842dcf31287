// SPDX-License-Identifier: MIT
// The contact cases of `stroma check --stability`. Soft boxes of corotational hexahedra (5 cm
// wide, E = 100 kPa as the beam cases' baseline, nu = 0.3, 1000 kg/m^3) above a fixed floor (an
// oriented box whose top face is y = 0), gravity along -y, all bodies under one solver (bodies in
// contact share one: plugins/Collision/README.md), dt = 1 ms as an interactive loop runs:
//   impact 10 m/s       a box 1.5 cm above the floor thrown down at 10 m/s: 1 cm a step, more
//                       than the alarm distance (4 mm), so that it is 5 mm into the floor
//                       before any contact is found;
//   stiff on soft       a box of E = 10 GPa, 8000 kg/m^3 laid on a soft one;
//   stack               3 (5 in the full suite) boxes on one another, 1.5 mm apart;
//   thin pressed flat   a 2 mm sheet on the floor, a stiff box pushed onto it with the force
//                       that would halve the sheet's thickness (linear estimate, 125 N).
// Upper boxes are shifted 2 mm along x and z: faces never exactly aligned. The responses:
// PenalityContactForceField with SOFA's default stiffness (k = 10 x 10 / d0 = 1e5 N/m a
// contact, d0 = contactDistance = 1 mm), or FrictionContactConstraint (mu = 0.3) under
// FreeMotionAnimationLoop with the solver's own compliance (LinearSolverConstraintCorrection).
// Besides the solvers' own reports, a case diverged when, at the end, a box passed through the
// floor or the box under it, or lies deeper in it than half the thinner of the two;
// `penetration` is the deepest that a point of a box went into the floor or into the box under
// it during the run.
#include "StabilityContactCases.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include "core/PluginManager.h"
#include "core/Runtime.h"
#include "core/StateTypes.h"
#include "simulation/MechanicalState.h"
#include "simulation/Scene.h"

namespace stroma::cli {

namespace {

constexpr double kSide = 0.05, kGap = 0.0015, kShift = 0.002, kDt = 1e-3;

struct Box {
  double bottom, height;      // y of the bottom face at rest, thickness (m)
  double shift;               // along x and z (m)
  double youngModulus = 1e5;  // Pa
  double density = 1000;      // kg/m^3
  double downSpeed = 0;       // initial velocity along -y (m/s)
  double pushForce = 0;       // total force along -y on its points (N)
  int layers = 0;             // grid points along y; 0: as along x and z
};

enum class Response { penalty, constraint };

struct ContactCase {
  const char* name;
  std::vector<Box> boxes;  // bottom to top
};

std::vector<ContactCase> makeCases(bool quick) {
  const double stiffPush = 0.5 * 1e5 * kSide * kSide;  // halves a 100 kPa sheet, linearly
  std::vector<ContactCase> cases;
  cases.push_back({"impact 10 m/s", {{0.015, kSide, 0, 1e5, 1000, 10}}});
  cases.push_back(
      {"stiff on soft", {{kGap, kSide, 0}, {2 * kGap + kSide, kSide, kShift, 1e10, 8000}}});
  ContactCase stack{"stack", {}};
  for (int k = 0; k < (quick ? 3 : 5); ++k)
    stack.boxes.push_back({kGap + k * (kSide + kGap), kSide, k % 2 ? kShift : 0.0});
  cases.push_back(stack);
  Box sheet{kGap, 0.002, 0};
  sheet.layers = 2;
  Box pusher{2 * kGap + 0.002, kSide, kShift, 1e10};
  pusher.pushForce = stiffPush;
  cases.push_back({"thin pressed flat", {sheet, pusher}});
  return cases;
}

struct Solver {
  const char* name;
  const char* xml;
};

// The beam cases' implicit solvers (StabilityCommand.cpp), warning instead of stopping.
const Solver kSolvers[] = {
    {"implicit Euler + CG",
     R"(<EulerImplicitSolver name="ode" rayleighStiffness="0.05" rayleighMass="0.05" onDivergence="warn"/>
    <CGLinearSolver name="linear" iterations="200" tolerance="1e-8" threshold="1e-300"/>)"},
    {"implicit Euler + LDL",
     R"(<EulerImplicitSolver name="ode" rayleighStiffness="0.05" rayleighMass="0.05" onDivergence="warn"/>
    <SparseLDLSolver name="linear"/>)"},
};

const char* responseName(Response r) {
  return r == Response::penalty ? "penalty contact" : "constraint contact";
}

std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.10g", value);
  return text;
}

int pointsAlong(int n, const Box& b) { return b.layers > 0 ? b.layers : n; }

std::string sceneXml(const ContactCase& c, Response response, const Solver& solver, int n) {
  std::ostringstream xml;
  xml << "<Node name=\"root\" dt=\"" << number(kDt) << "\" gravity=\"0 -9.81 0\">\n";
  if (response == Response::constraint)
    xml << "  <FreeMotionAnimationLoop/>\n"
           "  <GenericConstraintSolver tolerance=\"1e-8\" maxIterations=\"1000\"/>\n";
  xml << "  <CollisionPipeline/>\n  <BruteForceBroadPhase/>\n  <BVHNarrowPhase/>\n"
         "  <MinProximityIntersection alarmDistance=\"0.004\" contactDistance=\"0.001\"/>\n";
  xml << (response == Response::constraint
              ? "  <CollisionResponse response=\"FrictionContactConstraint\" "
                "responseParams=\"mu=0.3\"/>\n"
              : "  <CollisionResponse/>\n");
  xml << "  <Node name=\"Floor\">\n    <MechanicalObject template=\"Rigid3d\" position=\"0.025 "
         "-0.05 0.025 0 0 0 1\"/>\n    <OBBCollisionModel extents=\"0.25 0.05 0.25\" "
         "simulated=\"0\" moving=\"0\"/>\n  </Node>\n";
  xml << "  <Node name=\"Bodies\">\n    " << solver.xml << "\n";
  if (response == Response::constraint) xml << "    <LinearSolverConstraintCorrection/>\n";
  for (std::size_t k = 0; k < c.boxes.size(); ++k) {
    const Box& b = c.boxes[k];
    const int ny = pointsAlong(n, b), count = n * n * ny;
    xml << "    <Node name=\"Box" << k << "\">\n      <RegularGridTopology name=\"grid\" min=\""
        << number(b.shift) << " " << number(b.bottom) << " " << number(b.shift) << "\" max=\""
        << number(b.shift + kSide) << " " << number(b.bottom + b.height) << " "
        << number(b.shift + kSide) << "\" n=\"" << n << " " << ny << " " << n << "\"/>\n"
        << "      <MechanicalObject name=\"dofs\"";
    if (b.downSpeed != 0) {
      xml << " velocity=\"";
      for (int i = 0; i < count; ++i) xml << "0 " << number(-b.downSpeed) << " 0 ";
      xml << "\"";
    }
    xml << "/>\n      <UniformMass totalMass=\"" << number(b.density * kSide * kSide * b.height)
        << "\"/>\n      <HexahedronFEMForceField method=\"large\" youngModulus=\""
        << number(b.youngModulus) << "\" poissonRatio=\"0.3\"/>\n";
    if (b.pushForce != 0) {
      xml << "      <ConstantForceField indices=\"";
      for (int i = 0; i < count; ++i) xml << i << " ";
      xml << "\" totalForce=\"0 " << number(-b.pushForce) << " 0\"/>\n";
    }
    xml << "      <PointCollisionModel/>\n      <TriangleCollisionModel/>\n    </Node>\n";
  }
  xml << "  </Node>\n</Node>\n";
  return xml.str();
}

/// The grid of a box as it is now: points in RegularGridTopology's order (x fastest, then y).
struct Grid {
  const std::vector<Vec3d>* x = nullptr;
  int nx = 0, ny = 0;
  const Vec3d& at(int i, int j, int k) const { return (*x)[i + nx * (j + ny * k)]; }
  Vec3d centroid() const {
    Vec3d sum = Vec3d::Zero();
    for (const Vec3d& p : *x) sum += p;
    return sum / static_cast<double>(x->size());
  }
};

/// How deep `p` lies under the top face of `lower` (bilinear in the face's rest cells, found
/// from p's x and z); <= 0 above it or beside it.
double depthUnderTop(const Grid& lower, const Box& box, const Vec3d& p) {
  const double h = kSide / (lower.nx - 1);
  const double u = (p.x() - box.shift) / h, w = (p.z() - box.shift) / h;
  if (u < 0 || w < 0 || u > lower.nx - 1 || w > lower.nx - 1) return 0;
  const int i = std::min(static_cast<int>(u), lower.nx - 2);
  const int k = std::min(static_cast<int>(w), lower.nx - 2);
  const double a = u - i, c = w - k;
  const int top = lower.ny - 1;
  const double y =
      (1 - a) * (1 - c) * lower.at(i, top, k).y() + a * (1 - c) * lower.at(i + 1, top, k).y() +
      (1 - a) * c * lower.at(i, top, k + 1).y() + a * c * lower.at(i + 1, top, k + 1).y();
  return y - p.y();
}

/// How deep points of box k lie in the floor and in the box under it (<= 0: not at all).
void depths(const std::vector<Grid>& grids, const std::vector<Box>& boxes, std::size_t k,
            double& intoFloor, double& intoLower) {
  intoFloor = intoLower = 0;
  for (const Vec3d& p : *grids[k].x) {
    intoFloor = std::max(intoFloor, -p.y());
    if (k > 0) intoLower = std::max(intoLower, depthUnderTop(grids[k - 1], boxes[k - 1], p));
  }
}

StabilityOutcome runCase(Runtime& runtime, const ContactCase& c, Response response,
                         const Solver& solver, int n, long long steps) {
  StabilityOutcome out;
  const auto start = std::chrono::steady_clock::now();
  Scene scene(runtime);
  scene.setThreadCount(1);
  if (!scene.loadString(sceneXml(c, response, solver, n), "<stability contact case>")) {
    classifyOutcome(scene.log(), "", out);
    out.status = "invalid";
    return out;
  }
  std::vector<Grid> grids;
  std::vector<const std::vector<Vec3d>*> rest;
  for (std::size_t k = 0; k < c.boxes.size(); ++k) {
    Node* node = scene.root().findChild("Bodies");
    node = node ? node->findChild("Box" + std::to_string(k)) : nullptr;
    const auto* state = node ? node->get<MechanicalState<Vec3Types>>() : nullptr;
    if (!state) return out.status = "crash", out.reason = "a box's state is missing", out;
    grids.push_back({&state->readCoord(VecId::position()), n, pointsAlong(n, c.boxes[k])});
    rest.push_back(&state->readCoord(VecId::restPosition()));
  }

  // The deepest interpenetration over the run: a fast body may go in and come back out.
  bool finite = true;
  out.penetration = 0;
  for (; out.steps < steps && finite; ++out.steps) {
    const bool ok = scene.step();
    for (std::size_t k = 0; k < grids.size(); ++k) {
      double intoFloor, intoLower;
      depths(grids, c.boxes, k, intoFloor, intoLower);
      finite = finite && std::isfinite(intoFloor) && std::isfinite(intoLower);
      out.penetration = std::max({out.penetration, intoFloor, intoLower});
    }
    if (!ok) {
      ++out.steps;
      break;
    }
  }
  for (std::size_t k = 0; k < grids.size(); ++k)
    for (std::size_t i = 0; i < grids[k].x->size(); ++i) {
      const double d = ((*grids[k].x)[i] - (*rest[k])[i]).norm();
      finite = finite && std::isfinite(d);
      out.maxDisplacement = std::max(out.maxDisplacement, d);
    }

  // At the end: a box passed through what holds it when its centre went below it, and sank
  // when its points are deeper than half the thinner of the two.
  std::string unbounded = finite ? "" : "a position is not finite";
  for (std::size_t k = 0; k < grids.size() && unbounded.empty(); ++k) {
    const std::string name = "box " + std::to_string(k);
    double intoFloor, intoLower;
    depths(grids, c.boxes, k, intoFloor, intoLower);
    const double height = c.boxes[k].height;
    const double thinner = k > 0 ? std::min(height, c.boxes[k - 1].height) : height;
    const double centre = grids[k].centroid().y();
    if (centre < 0)
      unbounded =
          "passed through: the centre of " + name + " is " + number(-centre) + " m under the floor";
    else if (k > 0 && centre < grids[k - 1].centroid().y())
      unbounded = "passed through: " + name + " went under box " + std::to_string(k - 1);
    else if (intoFloor > 0.5 * height)
      unbounded = name + " sank " + number(intoFloor) + " m into the floor (over half its " +
                  number(height) + " m)";
    else if (intoLower > 0.5 * thinner)
      unbounded = name + " sank " + number(intoLower) + " m into box " + std::to_string(k - 1) +
                  " (over half of " + number(thinner) + " m)";
  }
  classifyOutcome(scene.log(), unbounded, out);
  out.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace

int runContactCases(Runtime& runtime, bool quick, const std::string* sceneDir,
                    const StabilityReport& report) {
  const PluginIndexEntry* collision = runtime.plugins().providerOf("CollisionPipeline");
  if (!collision || !collision->unavailable.empty()) {
    std::printf("Contact cases left out: this build has no Collision plugin%s\n",
                collision ? (" (" + collision->unavailable + ")").c_str() : "");
    return 0;
  }
  const int n = quick ? 3 : 4;  // grid points along each side of a box
  const long long steps = quick ? 50 : 100;
  const std::vector<ContactCase> cases = makeCases(quick);
  std::printf(
      "Contact cases: 2 responses x %zu solvers x %zu cases, boxes of %dx%dx%d points, "
      "%lld steps of %g s\n",
      std::size(kSolvers), cases.size(), n, n, n, steps, kDt);
  int rows = 0;
  for (Response response : {Response::penalty, Response::constraint})
    for (const Solver& solver : kSolvers)
      for (const ContactCase& c : cases) {
        if (sceneDir)
          std::ofstream(std::filesystem::path(*sceneDir) /
                        stabilityCaseFileName(responseName(response), solver.name, c.name, "-"))
              << sceneXml(c, response, solver, n);
        StabilityOutcome out;
        try {
          out = runCase(runtime, c, response, solver, n, steps);
        } catch (const std::exception& e) {
          out.status = "crash";
          out.reason = e.what();
        }
        report(responseName(response), solver.name, c.name, "-", out);
        ++rows;
      }
  return rows;
}

}  // namespace stroma::cli
