// SPDX-License-Identifier: MIT
// Running a SOFA example scene unmodified and comparing one state's positions after N steps
// with SOFA's own (a reference file written by a scripts/make-sofa-*-references.sh script from
// runSofa's WriteState: '#' comments, then "x y z" per point, 6 significant digits).
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "core/PathResolver.h"
#include "core/Runtime.h"
#include "core/StateTypes.h"
#include "plugins/TestPlugin/TestSupport.h"
#include "scenes/SceneLists.h"
#include "simulation/MechanicalState.h"
#include "simulation/Scene.h"

namespace stroma::test {

/// What a comparison found: the largest coordinate difference from SOFA's positions and the
/// largest coordinate displacement from the start (so that a test can see the body moved).
struct SofaComparison {
  std::string skipped;  ///< why it could not run here (no ../shared, a plugin left out)
  double difference = -1;
  double moved = -1;
};

/// Runs `steps` steps of ../shared/sofa/examples/`scene` (one thread) and compares the state at
/// `statePath` ("/root/Liver/dofs", absolute) with the reference file `reference` (relative to the
/// source tree). Fails the test (and returns difference -1) when the scene does not load or
/// run, or the sizes differ.
inline SofaComparison compareWithSofa(const std::string& scene, const std::string& statePath,
                                      int steps, const std::string& reference,
                                      const std::vector<std::string>& plugins = {}) {
  namespace fs = std::filesystem;
  SofaComparison result;
  const fs::path sofa = fs::path(STROMA_SHARED_DIR) / "sofa";
  if (!fs::is_directory(sofa / "examples")) {
    result.skipped = "SOFA's scenes are not at " + sofa.string();
    return result;
  }
  Runtime runtime;
  for (const std::string& plugin : plugins)
    if (std::string why = pluginLeftOut(runtime, plugin); !why.empty()) {
      result.skipped = "this build left the " + plugin + " plugin out: " + why;
      return result;
    }
  runtime.addDataDirectory(sofa / "share");
  runtime.addDataDirectory(sofa / "examples");
  std::vector<Vec3d> expected;
  std::ifstream in(fs::path(STROMA_SOURCE_DIR) / reference);
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream numbers(line);
    Vec3d p;
    numbers >> p.x() >> p.y() >> p.z();
    expected.push_back(p);
  }
  Scene loaded(runtime);
  loaded.setThreadCount(1);
  if (!loaded.loadFile(sofa / "examples" / scene)) {
    ADD_FAILURE() << scene << " does not load:\n" << describe(loaded.log());
    return result;
  }
  std::string why;
  const auto* state = dynamic_cast<const MechanicalState<Vec3Types>*>(
      resolveObjectPath(loaded.root(), "@" + statePath, why));
  if (!state) {
    ADD_FAILURE() << statePath << ": " << why;
    return result;
  }
  const std::vector<Vec3d> start = state->readCoord(VecId::position());
  for (int i = 0; i < steps; ++i)
    if (!loaded.step()) {
      ADD_FAILURE() << "step " << i + 1 << " failed:\n" << describe(loaded.log());
      return result;
    }
  const std::vector<Vec3d>& x = state->readCoord(VecId::position());
  if (x.size() != expected.size()) {
    ADD_FAILURE() << statePath << " has " << x.size() << " points, " << reference << " "
                  << expected.size();
    return result;
  }
  result.difference = result.moved = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    result.difference = std::max(result.difference, (x[i] - expected[i]).cwiseAbs().maxCoeff());
    result.moved = std::max(result.moved, (x[i] - start[i]).cwiseAbs().maxCoeff());
  }
  return result;
}

}  // namespace stroma::test
