// SPDX-License-Identifier: MIT
// `stroma run SCENE --export-vtk DIR`: every mechanical state of a scene as a time series of
// VTU files and one ParaView collection (.pvd) per state. Part of the StromaExportFiles library,
// so that the stroma command writes the files without loading the Export plugin.
//
// For a state at /root/Liver/dofs, at step 20:
//   DIR/root_Liver_dofs_000020.vtu   points, cells of the state's topology (its node's: the
//                                    tetrahedra and hexahedra, else triangles and quads, else
//                                    edges, else one vertex per point), point fields
//                                    displacement, velocity, vonMises and cell field vonMises
//                                    where a StressField covers the state (StateMesh.h)
//   DIR/root_Liver_dofs.pvd          every file written so far with its time, rewritten after
//                                    each exported step (a stopped run leaves a valid one)
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "VtkFiles.h"

namespace stroma {

class BaseMechanicalState;
class Node;
class StressField;
class Topology;

class SceneVtkExport {
 public:
  /// The states to write are those under `root` now (found once).
  SceneVtkExport(const Node& root, std::filesystem::path directory);

  /// Creates the folder when missing. False with `error` when it cannot be made or written.
  bool open(std::string& error);
  /// Writes one VTU per state for `step` at `time`, and rewrites each state's .pvd.
  bool writeStep(long long step, double time, std::string& error);

  /// The file stem of a state path: "/root/Liver/dofs" -> "root_Liver_dofs" (characters other
  /// than letters, digits, '-' and '_' become '_').
  static std::string fileStem(const std::string& statePath);

  std::size_t stateCount() const { return m_targets.size(); }
  const std::filesystem::path& directory() const { return m_directory; }

 private:
  struct Target {
    const BaseMechanicalState* state = nullptr;
    const Topology* topology = nullptr;
    std::vector<const StressField*> stresses;
    std::string stem;
    std::vector<vtk::CollectionEntry> written;
  };
  std::filesystem::path m_directory;
  std::vector<Target> m_targets;
};

}  // namespace stroma
