// SPDX-License-Identifier: MIT
// `stroma run` and `stroma check` (`check --stability` is StabilityCommand.cpp).
#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>

#include "CommandLine.h"
#include "core/PathResolver.h"
#include "core/Runtime.h"
#include "simulation/RunSummary.h"
#include "simulation/Scene.h"
#include "simulation/StateFile.h"
#include "simulation/Timing.h"

#if STROMA_HAS_EXPORT_FILES
#include "SceneVtkExport.h"
#endif

namespace stroma::cli {

namespace {

const std::vector<std::string> kSceneOptions = {"--data-path", "--log-json"};

/// Loads the scene named by the arguments, with console and JSON sinks attached.
/// Returns kSuccess or kBadInput (after printing why).
int loadScene(const Arguments& a, Runtime& runtime, Scene& scene,
              std::unique_ptr<std::ofstream>& jsonFile) {
  if (a.positional.size() != 1)
    return usageError(a.positional.empty() ? "expected a scene file"
                                           : "expected one scene file, got " +
                                                 std::to_string(a.positional.size()));
  for (const auto& dir : a.values("--data-path")) runtime.addDataDirectory(dir);
  scene.log().addSink(std::make_shared<StreamSink>(
      std::cerr, a.has("--verbose") ? MessageLevel::info : MessageLevel::warning));
  if (const std::string* json = a.value("--log-json")) {
    jsonFile = std::make_unique<std::ofstream>(*json);
    if (!*jsonFile) return usageError("cannot write the JSON log '" + *json + "'");
    scene.log().addSink(std::make_shared<JsonLinesSink>(*jsonFile));
  }
  if (!scene.loadFile(a.positional.front())) {
    const std::size_t errors = scene.log().errorCount();
    std::cerr << "stroma: " << a.positional.front() << ": " << errors
              << (errors == 1 ? " error" : " errors") << "; the scene was not run\n";
    return kBadInput;
  }
  return kSuccess;
}

void printTimingSummary(const Scene& scene, const Timing& timing, long long steps, double dt) {
  const double stepSeconds = timing.seconds("step");
  std::printf("Ran %lld steps of %s (dt %g s, simulated time %g s)\n", steps,
              scene.file().string().c_str(), dt, scene.root().time());
  std::printf("  wall time %.6f s for the steps (%.1f steps/s), %.6f s to load and initialize\n",
              stepSeconds, stepSeconds > 0 ? static_cast<double>(steps) / stepSeconds : 0.0,
              timing.seconds("load+init"));
  std::printf("  %-24s %12s %10s %14s\n", "phase", "total (s)", "calls", "per call (ms)");
  for (const auto& p : timing.phases())
    std::printf("  %-24s %12.6f %10lld %14.4f\n", p.name.c_str(), p.seconds, p.calls,
                p.calls ? 1e3 * p.seconds / static_cast<double>(p.calls) : 0.0);
}

/// The lines of every component implementing RunSummaryProvider (an error against a
/// reference...), in graph order, each after its component's path.
void printComponentSummaries(const Node& node) {
  for (const auto& object : node.objects())
    if (const auto* provider = dynamic_cast<const RunSummaryProvider*>(object.get()))
      for (const std::string& line : provider->runSummaryLines())
        std::printf("  %s: %s\n", object->path().c_str(), line.c_str());
  for (const auto& child : node.children()) printComponentSummaries(*child);
}

/// The Data named by --print or --export-data ("/root/Probe/dofs.constraintForce", a leading
/// '@' optional). Prints why and returns false when one is not found.
bool resolveData(const Scene& scene, const std::vector<std::string>& paths, const char* option,
                 std::vector<const BaseData*>& out) {
  for (const std::string& path : paths) {
    std::string error;
    const std::string link = path.starts_with('@') ? path : "@" + path;
    const BaseData* data = resolveDataPath(scene.root(), link, error);
    if (!data) {
      std::cerr << "stroma: " << option << " " << path << ": " << error << "\n";
      return false;
    }
    out.push_back(data);
  }
  return true;
}

std::string dataName(const BaseData& data) {
  return (data.owner() ? data.owner()->path() : std::string("?")) + "." + data.name();
}

/// One line per Data after each step: "step N time T PATH.field VALUE".
void printData(const std::vector<const BaseData*>& printed, long long step, double time) {
  for (const BaseData* data : printed)
    std::printf("step %lld time %.17g %s %s\n", step, time, dataName(*data).c_str(),
                data->valueText().c_str());
}

void captureData(const std::vector<const BaseData*>& exported, StateSnapshot& snapshot) {
  for (const BaseData* data : exported)
    snapshot.data.push_back({dataName(*data), data->typeName(), data->valueText()});
}

}  // namespace

int runCommand(const std::vector<std::string>& args) {
  Arguments a;
  std::string error;
  std::vector<std::string> valueOptions = kSceneOptions;
  valueOptions.insert(valueOptions.end(),
                      {"-n", "--steps", "--dt", "--threads", "--export-state", "--export-every", "--print",
                       "--export-data", "--export-vtk"});
  if (!parseArguments(args, valueOptions, {"--verbose"}, a, error)) return usageError(error);
  long long steps = 100, threads = 0, exportEvery = 0;
  double dt = 0;
  if (const std::string* s = a.value("--steps")) a.options["-n"].push_back(*s);
  if (!readInteger(a, "-n", 0, steps, error) || !readInteger(a, "--threads", 0, threads, error) ||
      !readInteger(a, "--export-every", 1, exportEvery, error) || !readReal(a, "--dt", dt, error))
    return usageError(error);
  if (exportEvery && !a.value("--export-state") && !a.value("--export-vtk"))
    return usageError("--export-every needs --export-state FILE or --export-vtk DIR");
#if !STROMA_HAS_EXPORT_FILES
  if (a.value("--export-vtk"))
    return usageError("--export-vtk: this build has no Export plugin (plugins/Export)");
#endif
  if (!a.values("--export-data").empty() && !a.value("--export-state"))
    return usageError("--export-data needs --export-state FILE");

  Runtime runtime;
  // The JSON log outlives the scene: the solvers' summaries at unload still write to it.
  std::unique_ptr<std::ofstream> jsonFile;
  Scene scene(runtime);
  scene.setThreadCount(static_cast<int>(threads));
  if (int code = loadScene(a, runtime, scene, jsonFile)) return code;
  if (dt <= 0) dt = scene.root().dt();
  std::vector<const BaseData*> printed, exported;
  if (!resolveData(scene, a.values("--print"), "--print", printed) ||
      !resolveData(scene, a.values("--export-data"), "--export-data", exported))
    return kBadInput;
  auto snapshot = [&](long long step) {
    StateSnapshot s = captureState(scene.root(), step);
    captureData(exported, s);
    return s;
  };

  std::ofstream stateFile;
  if (const std::string* path = a.value("--export-state")) {
    stateFile.open(*path);
    if (!stateFile) return usageError("cannot write the state file '" + *path + "'");
    writeStateHeader(stateFile);
    if (exportEvery) writeSnapshot(stateFile, snapshot(0));
  }
#if STROMA_HAS_EXPORT_FILES
  // --export-vtk DIR: VTU files of every state at step 0, every K steps (1 by default) and the
  // last step, timed as the phase "exportVtk" (SceneVtkExport.h).
  std::unique_ptr<SceneVtkExport> vtkExport;
  auto exportVtk = [&](long long step) {
    ScopedPhase phase(scene.timing(), "exportVtk");
    std::string why;
    if (vtkExport->writeStep(step, scene.root().time(), why)) return true;
    std::cerr << "stroma: --export-vtk: " << why << "\n";
    return false;
  };
  if (const std::string* dir = a.value("--export-vtk")) {
    vtkExport = std::make_unique<SceneVtkExport>(scene.root(), *dir);
    std::string why;
    if (!vtkExport->open(why)) return usageError("--export-vtk: " + why);
    if (!exportVtk(0)) return kBadInput;
  }
  const long long vtkEvery = exportEvery ? exportEvery : 1;
#endif

  int code = kSuccess;
  long long done = 0;
  for (; done < steps; ++done) {
    if (!scene.step(dt)) {
      std::cerr << "stroma: the simulation failed at step " << done + 1 << " (time "
                << scene.root().time() << " s); see the errors above\n";
      code = kSimulationFailure;
      ++done;
      break;
    }
    printData(printed, done + 1, scene.root().time());
    if (exportEvery && stateFile.is_open() && (done + 1) % exportEvery == 0 && done + 1 != steps)
      writeSnapshot(stateFile, snapshot(done + 1));
#if STROMA_HAS_EXPORT_FILES
    if (vtkExport && ((done + 1) % vtkEvery == 0 || done + 1 == steps) && !exportVtk(done + 1)) {
      code = kSimulationFailure;
      ++done;
      break;
    }
#endif
  }
  if (stateFile.is_open()) {
    writeSnapshot(stateFile, snapshot(done));
    if (!stateFile.flush()) {
      std::cerr << "stroma: writing the state file failed\n";
      code = code ? code : kSimulationFailure;
    }
  }
  if (code == kSuccess && scene.log().runFailureCount() > 0) {
    // onDivergence="warn" let a diverged state go on: the run is still not a success.
    std::cerr << "stroma: the run went on after its state diverged (onDivergence=\"warn\"); "
                 "see the warnings above\n";
    code = kSimulationFailure;
  }
  printTimingSummary(scene, scene.timing(), done, dt);
  printComponentSummaries(scene.root());
  return code;
}

int checkCommand(const std::vector<std::string>& args) {
  if (std::find(args.begin(), args.end(), "--stability") != args.end())
    return stabilityCommand(args);
  Arguments a;
  std::string error;
  if (!parseArguments(args, kSceneOptions, {"--verbose"}, a, error)) return usageError(error);
  Runtime runtime;
  std::unique_ptr<std::ofstream> jsonFile;  // outlives the scene (its unload still logs)
  Scene scene(runtime);
  if (int code = loadScene(a, runtime, scene, jsonFile)) return code;
  std::size_t objects = 0, nodes = 0;
  std::vector<const Node*> stack{&scene.root()};
  while (!stack.empty()) {
    const Node* n = stack.back();
    stack.pop_back();
    ++nodes;
    objects += n->objects().size();
    for (const auto& c : n->children()) stack.push_back(c.get());
  }
  const std::size_t warnings = scene.log().count(MessageLevel::warning);
  std::cout << scene.file().string() << ": OK (" << nodes << " nodes, " << objects
            << " components, " << warnings << (warnings == 1 ? " warning" : " warnings")
            << "; plugins loaded:";
  for (const auto& p : runtime.plugins().loadedPlugins()) std::cout << ' ' << p;
  std::cout << ")\n";
  return kSuccess;
}

}  // namespace stroma::cli
