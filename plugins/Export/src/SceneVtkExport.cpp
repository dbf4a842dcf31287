// SPDX-License-Identifier: MIT
#include "SceneVtkExport.h"

#include <cstdio>
#include <fstream>
#include <set>

#include "StateMesh.h"
#include "core/Node.h"
#include "simulation/MechanicalState.h"
#include "topology/Topology.h"

namespace stroma {

namespace fs = std::filesystem;

namespace {

void collectStates(const Node& node, std::vector<const BaseMechanicalState*>& states) {
  for (const auto& object : node.objects())
    if (const auto* state = dynamic_cast<const BaseMechanicalState*>(object.get()))
      states.push_back(state);
  for (const auto& child : node.children()) collectStates(*child, states);
}

}  // namespace

std::string SceneVtkExport::fileStem(const std::string& statePath) {
  std::string stem;
  for (char c : statePath) {
    const bool plain = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                       c == '-' || c == '_';
    stem += plain ? c : '_';
  }
  while (stem.starts_with('_')) stem.erase(0, 1);
  return stem.empty() ? "state" : stem;
}

SceneVtkExport::SceneVtkExport(const Node& root, fs::path directory)
    : m_directory(std::move(directory)) {
  std::vector<const BaseMechanicalState*> states;
  collectStates(root, states);
  std::set<std::string> stems;
  for (const BaseMechanicalState* state : states) {
    Target t;
    t.state = state;
    t.topology = state->node() ? state->node()->get<Topology>() : nullptr;
    t.stresses = vtk::findStressFields(root, *state);
    t.stem = fileStem(state->path());
    // Two paths that differ only by replaced characters keep distinct files.
    for (int k = 2; stems.count(t.stem); ++k)
      t.stem = fileStem(state->path()) + "-" + std::to_string(k);
    stems.insert(t.stem);
    m_targets.push_back(std::move(t));
  }
}

bool SceneVtkExport::open(std::string& error) {
  std::error_code ec;
  fs::create_directories(m_directory, ec);
  if (!fs::is_directory(m_directory, ec)) {
    error = "cannot make the folder '" + m_directory.string() + "'" +
            (ec ? " (" + ec.message() + ")" : "");
    return false;
  }
  // A folder that exists may still refuse files (permissions): find out before the run.
  const fs::path probe = m_directory / ".stroma-write-test";
  {
    std::ofstream test(probe);
    if (!test) {
      error = "cannot write files in '" + m_directory.string() + "'";
      return false;
    }
  }
  fs::remove(probe, ec);
  return true;
}

bool SceneVtkExport::writeStep(long long step, double time, std::string& error) {
  char number[32];
  std::snprintf(number, sizeof number, "_%06lld", step);
  for (Target& t : m_targets) {
    vtk::UnstructuredMesh mesh;
    mesh.points = vtk::statePoints(*t.state);
    std::string why;
    if (!vtk::appendCells(t.topology, vtk::highestDimensionCells(t.topology), mesh.points.size(),
                          mesh, why)) {
      // A topology that does not describe this state (a mapped state beside it): points only.
      mesh.cellTypes.clear();
      mesh.connectivity.clear();
      vtk::appendCells(nullptr, {}, mesh.points.size(), mesh, why);
    }
    vtk::addStateFields(*t.state, t.stresses, mesh);
    const std::string name = t.stem + number + ".vtu";
    if (!vtk::writeVtu(m_directory / name, mesh, error)) return false;
    t.written.push_back({time, name});
    if (!vtk::writePvd(m_directory / (t.stem + ".pvd"), t.written, error)) return false;
  }
  return true;
}

}  // namespace stroma
