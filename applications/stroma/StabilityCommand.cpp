// SPDX-License-Identifier: MIT
// `stroma check --stability`: the stability suite. Every model (linear, corotational and
// hyperelastic tetrahedra, tensor-mass, hexahedra) with every solver (implicit Euler with CG or
// LDL, static, central differences, symplectic Euler, RK4) on a clamped beam, one extreme
// setting at a time: Young's modulus, Poisson's ratio, time step, a mesh with slivers and
// near-flat elements, elements inverted by an imposed displacement, a load 100 times the
// stiffness scale, an impact; then the contact cases (StabilityContactCases.cpp). Each case is a
// scene made from a text template and run in this process; it ends stable, stalled, refused or
// diverged, with the reason the solvers reported.
#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "CommandLine.h"
#include "StabilityContactCases.h"
#include "core/Runtime.h"
#include "core/StateTypes.h"
#include "simulation/MechanicalState.h"
#include "simulation/Scene.h"

namespace stroma::cli {

namespace {

// The beam: length 0.1 m along x, square section 0.05 m, clamped at x = 0, density 1000 kg/m^3,
// gravity -9.81 m/s^2 along y. With the baseline setting it sags by 6 % of its length (linear
// estimate), and the explicit schemes' bound is 7 (full) to 15 (quick) times the baseline time
// step.
constexpr double kLength = 0.1, kSide = 0.05, kDensity = 1000, kGravity = 9.81;

enum class Mesh { regular, slivers };
enum class Load { gravity, hundredTimesStiffness, inverted, impact };

struct Setting {
  double youngModulus = 1e5;  // Pa: soft tissue
  double poissonRatio = 0.3;
  double dt = 1e-4;  // s: below the explicit schemes' bound on both beams
  Mesh mesh = Mesh::regular;
  Load load = Load::gravity;
};

struct Case {
  std::string name, value;
  Setting setting;
};

struct Model {
  const char* name;
  bool hexahedra;
  const char* forceField;  // XML with %E and %NU for the material
};

struct Solver {
  const char* name;
  bool explicitScheme, isStatic;
  const char* xml;
};

// clang-format off
const Model kModels[] = {
  {"linear tetrahedra", false, R"(<TetrahedronFEMForceField method="small" youngModulus="%E" poissonRatio="%NU"/>)"},
  {"corotational tetrahedra (large)", false, R"(<TetrahedronFEMForceField method="large" youngModulus="%E" poissonRatio="%NU"/>)"},
  {"corotational tetrahedra (polar)", false, R"(<TetrahedronFEMForceField method="polar" youngModulus="%E" poissonRatio="%NU"/>)"},
  {"StVK tetrahedra", false, R"(<StandardTetrahedralFEMForceField materialName="StVenantKirchhoff" youngModulus="%E" poissonRatio="%NU"/>)"},
  {"neo-Hookean tetrahedra", false, R"(<StandardTetrahedralFEMForceField materialName="NeoHookean" youngModulus="%E" poissonRatio="%NU"/>)"},
  {"tensor-mass tetrahedra", false, R"(<TetrahedralTensorMassForceField youngModulus="%E" poissonRatio="%NU"/>)"},
  {"corotational hexahedra", true, R"(<HexahedronFEMForceField method="large" youngModulus="%E" poissonRatio="%NU"/>)"},
};

// Implicit solvers warn (onDivergence="warn"): a stalled Newton or an unconverged solve is then
// reported while the run goes on, to show whether the motion stays bounded. Explicit solvers
// stop: above their stability bound they refuse to start.
const Solver kSolvers[] = {
  {"implicit Euler + CG", false, false,
   R"(<EulerImplicitSolver name="ode" rayleighStiffness="0.05" rayleighMass="0.05" onDivergence="warn"/>
      <CGLinearSolver name="linear" iterations="200" tolerance="1e-8" threshold="1e-300"/>)"},
  {"implicit Euler + LDL", false, false,
   R"(<EulerImplicitSolver name="ode" rayleighStiffness="0.05" rayleighMass="0.05" onDivergence="warn"/>
      <SparseLDLSolver name="linear"/>)"},
  {"static + LDL", false, true,
   R"(<StaticSolver name="ode" newton_iterations="20" onDivergence="warn"/>
      <SparseLDLSolver name="linear"/>)"},
  {"central differences", true, false, R"(<CentralDifferenceSolver name="ode" onDivergence="stop"/>)"},
  {"symplectic Euler", true, false, R"(<EulerExplicitSolver name="ode" onDivergence="stop"/>)"},
  {"RK4", true, false, R"(<RungeKutta4Solver name="ode" onDivergence="stop"/>)"},
};
// clang-format on

std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", value);
  return text;
}

std::string shortNumber(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", value);
  return text;
}

std::vector<Case> makeCases(bool quick) {
  std::vector<Case> cases;
  const auto add = [&](const std::string& name, double value, auto change) {
    Case c{name, shortNumber(value), {}};
    change(c.setting, value);
    cases.push_back(c);
  };
  const std::vector<double> moduli =
      quick ? std::vector<double>{1e2, 1e10} : std::vector<double>{1e2, 1e4, 1e6, 1e8, 1e10};
  const std::vector<double> ratios =
      quick ? std::vector<double>{0.4999} : std::vector<double>{0.3, 0.45, 0.49, 0.499, 0.4999};
  const std::vector<double> steps =
      quick ? std::vector<double>{1e-5, 1} : std::vector<double>{1e-5, 1e-4, 1e-3, 1e-2, 1e-1, 1};
  for (double e : moduli) add("youngModulus", e, [](Setting& s, double v) { s.youngModulus = v; });
  for (double nu : ratios)
    add("poissonRatio", nu, [](Setting& s, double v) { s.poissonRatio = v; });
  for (double dt : steps) add("dt", dt, [](Setting& s, double v) { s.dt = v; });
  cases.push_back({"slivers", "-", {}});
  cases.back().setting.mesh = Mesh::slivers;
  cases.push_back({"inverted", "-", {}});
  cases.back().setting.load = Load::inverted;
  cases.push_back({"load 100 E", "-", {}});
  cases.back().setting.load = Load::hundredTimesStiffness;
  cases.push_back({"impact", "-", {}});
  cases.back().setting.load = Load::impact;
  return cases;
}

/// Grid points of the beam (x fastest, as RegularGridTopology numbers them).
struct Beam {
  int nx, ny, nz;
  int index(int i, int j, int k) const { return i + nx * (j + ny * k); }
  double spacing() const { return kLength / (nx - 1); }
  std::vector<Vec3d> points() const {
    std::vector<Vec3d> p;
    for (int k = 0; k < nz; ++k)
      for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i)
          p.emplace_back(i * spacing(), j * kSide / (ny - 1), k * kSide / (nz - 1));
    return p;
  }
  std::vector<int> layer(int i) const {
    std::vector<int> indices;
    for (int k = 0; k < nz; ++k)
      for (int j = 0; j < ny; ++j) indices.push_back(index(i, j, k));
    return indices;
  }
};

std::string join(const std::vector<Vec3d>& points) {
  std::string text;
  for (const Vec3d& p : points)
    text += number(p.x()) + " " + number(p.y()) + " " + number(p.z()) + " ";
  return text;
}

std::string join(const std::vector<int>& indices) {
  std::string text;
  for (int i : indices) text += std::to_string(i) + " ";
  return text;
}

std::string replaceAll(std::string text, const std::string& from, const std::string& to) {
  for (std::size_t at = text.find(from); at != std::string::npos;
       at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
  return text;
}

/// The linear static tip deflection of the load (Euler-Bernoulli cantilever): q L^4 / (8 E I)
/// under gravity, plus F L^3 / (3 E I) for the tip load. The scale of "bounded".
double linearTipDeflection(const Setting& s) {
  const double inertia = kSide * kSide * kSide * kSide / 12;
  const double q = kDensity * kGravity * kSide * kSide;
  double w = q * std::pow(kLength, 4) / (8 * s.youngModulus * inertia);
  if (s.load == Load::hundredTimesStiffness)
    w += 100 * s.youngModulus * kSide * kSide * std::pow(kLength, 3) /
         (3 * s.youngModulus * inertia);
  return w;
}

std::string sceneXml(const Beam& beam, const Model& model, const Solver& solver, const Setting& s) {
  std::vector<Vec3d> rest = beam.points(), position;
  const double h = beam.spacing();
  if (s.mesh == Mesh::slivers) {
    // Near-flat elements: layer 1 moved to 1/1000 of a cell from layer 2. Slivers: one corner of
    // the next-to-last cell pushed 45 % of a cell inwards along y and z.
    for (int index : beam.layer(1)) rest[static_cast<std::size_t>(index)].x() += 0.999 * h;
    rest[static_cast<std::size_t>(beam.index(beam.nx - 2, 0, 0))] += Vec3d(0, 0.45, 0.45) * h;
  }
  position = rest;
  std::vector<int> held = beam.layer(0);
  const std::vector<int> tip = beam.layer(beam.nx - 1);
  if (s.load == Load::inverted || s.load == Load::impact) {
    // Imposed at once and held: the tip pushed back two cells past its neighbours (the last
    // cell's elements inverted), or moved a quarter of the length sideways (an impact).
    for (int index : tip) {
      Vec3d& p = position[static_cast<std::size_t>(index)];
      if (s.load == Load::inverted)
        p.x() -= 2 * h;
      else
        p.y() += 0.25 * kLength;
    }
    held.insert(held.end(), tip.begin(), tip.end());
  }
  std::string material = replaceAll(model.forceField, "%E", number(s.youngModulus));
  material = replaceAll(material, "%NU", number(s.poissonRatio));
  std::ostringstream xml;
  xml << "<Node name=\"root\" dt=\"" << number(s.dt) << "\" gravity=\"0 " << -kGravity << " 0\">\n"
      << " <Node name=\"Beam\">\n  " << solver.xml << "\n"
      << "  <RegularGridTopology name=\"grid\" min=\"0 0 0\" max=\"" << kLength << " " << kSide
      << " " << kSide << "\" n=\"" << beam.nx << " " << beam.ny << " " << beam.nz << "\"/>\n"
      << "  <MechanicalObject name=\"dofs\" position=\"" << join(position) << "\" rest_position=\""
      << join(rest) << "\"/>\n";
  if (!model.hexahedra)
    xml << "  <TetrahedronSetTopologyContainer name=\"tetrahedra\"/>\n"
        << "  <Hexa2TetraTopologicalMapping input=\"@grid\" output=\"@tetrahedra\"/>\n";
  xml << "  <UniformMass totalMass=\"" << number(kDensity * kLength * kSide * kSide) << "\"/>\n"
      << "  " << material << "\n"
      << "  <FixedConstraint indices=\"" << join(held) << "\"/>\n";
  if (s.load == Load::hundredTimesStiffness)
    xml << "  <ConstantForceField indices=\"" << join(tip) << "\" totalForce=\"0 "
        << number(-100 * s.youngModulus * kSide * kSide) << " 0\"/>\n";
  xml << " </Node>\n</Node>\n";
  return xml.str();
}

using Outcome = StabilityOutcome;

// The first warning or error (error only: `errorsOnly`) whose text holds `key`, or "".
std::string findMessage(const MessageLog& log, const std::string& key, bool errorsOnly = false) {
  for (const Message& m : log.messages())
    if ((m.level == MessageLevel::error || (!errorsOnly && m.level == MessageLevel::warning)) &&
        m.text.find(key) != std::string::npos)
      return (m.componentPath.empty() ? "" : m.componentPath + ": ") + m.text;
  return {};
}

Outcome runCase(Runtime& runtime, const Beam& beam, const Model& model, const Solver& solver,
                const Setting& s, long long steps) {
  Outcome out;
  const auto start = std::chrono::steady_clock::now();
  Scene scene(runtime);
  scene.setThreadCount(1);
  if (!scene.loadString(sceneXml(beam, model, solver, s), "<stability case>")) {
    out.status = "invalid";
    out.reason = findMessage(scene.log(), "", true);
    return out;
  }
  for (; out.steps < steps; ++out.steps)
    if (!scene.step()) {
      ++out.steps;
      break;
    }
  // Displacements from the rest shape: the largest, and the tip's mean along y.
  Node* body = scene.root().findChild("Beam");
  const auto* state = body ? body->get<MechanicalState<Vec3Types>>() : nullptr;
  bool finite = state != nullptr;
  double tipY = 0;
  if (state) {
    const auto& x = state->readCoord(VecId::position());
    const auto& x0 = state->readCoord(VecId::restPosition());
    for (std::size_t i = 0; i < x.size(); ++i) {
      const double d = (x[i] - x0[i]).norm();
      finite = finite && std::isfinite(d);
      out.maxDisplacement = std::max(out.maxDisplacement, d);
    }
    for (int i : beam.layer(beam.nx - 1)) tipY += x[i].y() - x0[i].y();
    tipY /= beam.ny * beam.nz;
  }
  if (solver.isStatic && s.load == Load::gravity && s.mesh == Mesh::regular)
    out.tipRatio = -tipY / linearTipDeflection(s);
  if (Base* ode = body ? body->findObject("ode") : nullptr)
    if (BaseData* bound = ode->findData("criticalTimeStep"))
      out.criticalDt = std::atof(bound->valueText().c_str());

  const double limit = 10 * std::max(kLength, linearTipDeflection(s));
  std::string unbounded;
  if (!finite || out.maxDisplacement > limit)
    unbounded = "unbounded: largest displacement " + shortNumber(out.maxDisplacement) + " m > " +
                shortNumber(limit) + " m (10 times the beam's length or linear deflection)";
  classifyOutcome(scene.log(), unbounded, out);
  out.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

std::string csvField(const std::string& text) {
  std::string quoted = "\"";
  for (char c : text)
    quoted += c == '"' ? std::string("\"\"") : std::string(1, c == '\n' ? ' ' : c);
  return quoted + "\"";
}

std::string csvNumber(double value) { return std::isnan(value) ? "" : shortNumber(value); }

}  // namespace

void classifyOutcome(const MessageLog& log, const std::string& unbounded, StabilityOutcome& out) {
  // The outcome, the worst first.
  std::string text;
  if (!(text = findMessage(log, "is not finite")).empty() ||
      !(text = findMessage(log, "divergence (energy growth)")).empty()) {
    out.status = "diverged";
  } else if (!unbounded.empty()) {
    out.status = "diverged";
    text = unbounded;
  } else if (!(text = findMessage(log, "divergence (time step above")).empty()) {
    out.status = "refused";
  } else if (!(text = findMessage(log, "divergence (stalled Newton")).empty() ||
             !(text = findMessage(log, "divergence (unconverged linear")).empty()) {
    out.status = "stalled";
  } else if (log.errorCount() > 0) {
    out.status = "error";
    text = findMessage(log, "", true);
  } else {
    out.status = "stable";
  }
  out.reason = text;
}

std::string stabilityCaseFileName(const std::string& model, const std::string& solver,
                                  const std::string& caseName, const std::string& value) {
  // Words in lower case joined by '-'; the value as written ("1e+10", "0.4999").
  const auto words = [](const std::string& text) {
    std::string out;
    for (char ch : text) {
      if (std::isalnum(static_cast<unsigned char>(ch)))
        out += static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
      else if (!out.empty() && out.back() != '-')
        out += '-';
    }
    while (!out.empty() && out.back() == '-') out.pop_back();
    return out;
  };
  return words(model) + "_" + words(solver) + "_" + words(caseName) +
         (value == "-" ? "" : "-" + value) + ".scn";
}

int stabilityCommand(const std::vector<std::string>& args) {
  Arguments a;
  std::string error;
  if (!parseArguments(args, {"--csv", "--save-scenes", "--data-path", "--log-json"},
                      {"--stability", "--quick", "--verbose"}, a, error))
    return usageError(error);
  if (!a.positional.empty())
    return usageError("check --stability takes no scene: its cases are built in");
  const bool quick = a.has("--quick");
  const std::string* sceneDir = a.value("--save-scenes");
  if (sceneDir) {
    std::error_code failed;
    std::filesystem::create_directories(*sceneDir, failed);
    if (failed) return usageError("cannot make the folder '" + *sceneDir + "'");
  }
  std::ofstream csv;
  if (const std::string* path = a.value("--csv")) {
    csv.open(*path);
    if (!csv) return usageError("cannot write the CSV file '" + *path + "'");
    csv << "model,solver,case,value,status,steps,max_displacement_m,static_tip_over_linear,"
           "critical_dt_s,wall_s,max_penetration_m,reason\n";
  }
  const Beam beam = quick ? Beam{5, 2, 2} : Beam{9, 3, 3};
  const long long steps = quick ? 50 : 100;
  const std::vector<Case> cases = makeCases(quick);
  Runtime runtime;
  for (const auto& dir : a.values("--data-path")) runtime.addDataDirectory(dir);
  std::map<std::string, int> counts;
  // One row: counted, printed, and in the CSV.
  const StabilityReport report = [&](const std::string& model, const std::string& solver,
                                     const std::string& caseName, const std::string& value,
                                     const Outcome& out) {
    ++counts[out.status];
    std::printf("  %-32s %-22s %-12s %-7s %-8s %s\n", model.c_str(), solver.c_str(),
                caseName.c_str(), value.c_str(), out.status.c_str(),
                out.status == "stable" ? "" : out.reason.substr(0, 160).c_str());
    if (csv.is_open())
      csv << csvField(model) << ',' << csvField(solver) << ',' << csvField(caseName) << ',' << value
          << ',' << out.status << ',' << out.steps << ',' << csvNumber(out.maxDisplacement) << ','
          << csvNumber(out.tipRatio) << ',' << csvNumber(out.criticalDt) << ','
          << csvNumber(out.wallSeconds) << ',' << csvNumber(out.penetration) << ','
          << csvField(out.reason) << '\n';
  };
  std::printf("Stability suite%s: %zu models x %zu solvers x %zu cases, beam %dx%dx%d points\n",
              quick ? " (quick)" : "", std::size(kModels), std::size(kSolvers), cases.size(),
              beam.nx, beam.ny, beam.nz);
  for (const Model& model : kModels)
    for (const Solver& solver : kSolvers)
      for (const Case& c : cases) {
        if (sceneDir)
          std::ofstream(std::filesystem::path(*sceneDir) /
                        stabilityCaseFileName(model.name, solver.name, c.name, c.value))
              << sceneXml(beam, model, solver, c.setting);
        Outcome out;
        try {
          out = runCase(runtime, beam, model, solver, c.setting, solver.isStatic ? 3 : steps);
        } catch (const std::exception& e) {
          out.status = "crash";
          out.reason = e.what();
        }
        report(model.name, solver.name, c.name, c.value, out);
      }
  runContactCases(runtime, quick, sceneDir, report);
  std::printf("Outcomes:");
  for (const auto& [status, count] : counts) std::printf(" %s %d", status.c_str(), count);
  std::printf("\n");
  if (csv.is_open() && !csv.flush()) {
    std::cerr << "stroma: writing the CSV file failed\n";
    return kSimulationFailure;
  }
  // The suite's own scenes must load and no case may throw: anything else is its result.
  return counts.count("invalid") || counts.count("crash") || counts.count("error")
             ? kSimulationFailure
             : kSuccess;
}

}  // namespace stroma::cli
