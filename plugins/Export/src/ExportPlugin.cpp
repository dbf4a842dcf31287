// SPDX-License-Identifier: MIT
#include "MeshExporter.h"
#include "ReadState.h"
#include "VTKExporter.h"
#include "VisualModelOBJExporter.h"
#include "WriteState.h"
#include "core/Plugin.h"

namespace {

void registerComponents(stroma::PluginRegistry& registry) {
  using namespace stroma;
  registry
      .add("VTKExporter",
           "Writes the node's topology and chosen Data as VTK files (.vtu or legacy .vtk) "
           "during the run")
      .with<VTKExporter>();
  registry
      .add("MeshExporter",
           "Writes the node's mesh as VTK XML, legacy VTK, Gmsh or TetGen files during the run")
      .with<MeshExporter>();
  registry
      .add("VisualModelOBJExporter",
           "Writes the surfaces of the visual models below it as a Wavefront OBJ file and its "
           "material library")
      .with<VisualModelOBJExporter>()
      .alias("OBJExporter");
  registry
      .add("WriteState",
           "Writes a mechanical state's positions, velocities and forces to a text file (SOFA's "
           "state format) at given times")
      .with<WriteState>()
      .sofaOptions({"stopAt", "keperiod"});
  registry
      .add("ReadState",
           "Sets a mechanical state's positions and velocities from a state file (SOFA's "
           "format) as the time passes")
      .with<ReadState>();
}

}  // namespace

extern "C" STROMA_PLUGIN_EXPORT const stroma::PluginEntry* stroma_plugin_entry() {
  static const stroma::PluginEntry entry = stroma::makePluginEntry(
      "Export", "0.1.0",
      "Exports for ParaView and other tools (VTU/PVD, legacy VTK, Gmsh, TetGen, OBJ) and "
      "SOFA's state files (issue 17)",
      registerComponents);
  return &entry;
}
