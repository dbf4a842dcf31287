// SPDX-License-Identifier: MIT
#include "GridMeshCreator.h"
#include "MeshGmshLoader.h"
#include "MeshOBJLoader.h"
#include "MeshSTLLoader.h"
#include "MeshVTKLoader.h"
#include "SphereLoader.h"
#include "core/Plugin.h"

namespace {

void registerComponents(stroma::PluginRegistry& registry) {
  using namespace stroma;
  registry.add("MeshGmshLoader", "Reads a Gmsh .msh mesh (versions 1, 2 and 4.1, ASCII and binary)")
      .with<MeshGmshLoader>();
  registry.add("MeshVTKLoader", "Reads a VTK mesh (legacy .vtk, XML .vtu and .vtp)")
      .with<MeshVTKLoader>();
  registry.add("MeshOBJLoader", "Reads a Wavefront .obj surface mesh")
      .with<MeshOBJLoader>()
      .alias("MeshObjLoader");
  registry.add("MeshSTLLoader", "Reads an STL surface mesh (ASCII or binary)")
      .with<MeshSTLLoader>();
  registry.add("GridMeshCreator", "A flat grid mesh of quads or triangles on the unit square")
      .with<GridMeshCreator>();
  registry.add("SphereLoader", "Reads a sphere file (.sph): centers and radii of spheres")
      .with<SphereLoader>();
}

}  // namespace

extern "C" STROMA_PLUGIN_EXPORT const stroma::PluginEntry* stroma_plugin_entry() {
  static const stroma::PluginEntry entry = stroma::makePluginEntry(
      "MeshIO", "0.1.0", "Mesh file loaders (Gmsh, VTK, OBJ, STL) and sphere files (.sph)",
      registerComponents);
  return &entry;
}
