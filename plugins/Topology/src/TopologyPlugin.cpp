// SPDX-License-Identifier: MIT
#include "Hexa2QuadTopologicalMapping.h"
#include "Hexa2TetraTopologicalMapping.h"
#include "MeshTopology.h"
#include "Quad2TriangleTopologicalMapping.h"
#include "RegularGridTopology.h"
#include "SetTopologyContainers.h"
#include "SetTopologyHelpers.h"
#include "Tetra2TriangleTopologicalMapping.h"
#include "TetrahedronSetTopologyModifier.h"
#include "core/Plugin.h"

namespace {

void registerComponents(stroma::PluginRegistry& registry) {
  using namespace stroma;
  registry.add("MeshTopology", "A mesh of any elements, kept as given")
      .with<MeshTopology>()
      .alias("Mesh");
  registry.add("PointSetTopologyContainer", "A set of points").with<PointSetTopologyContainer>();
  registry.add("EdgeSetTopologyContainer", "A mesh of edges").with<EdgeSetTopologyContainer>();
  registry.add("TriangleSetTopologyContainer", "A mesh of triangles, with their edges")
      .with<TriangleSetTopologyContainer>();
  registry.add("QuadSetTopologyContainer", "A mesh of quads, with their edges")
      .with<QuadSetTopologyContainer>();
  registry
      .add("TetrahedronSetTopologyContainer",
           "A mesh of tetrahedra, with their triangles and edges")
      .with<TetrahedronSetTopologyContainer>();
  registry.add("HexahedronSetTopologyContainer", "A mesh of hexahedra, with their quads and edges")
      .with<HexahedronSetTopologyContainer>();
  registry
      .add("TetrahedronSetTopologyModifier",
           "Removes tetrahedra at run time (cutting), logging the change for the components "
           "that follow the topology")
      .with<TetrahedronSetTopologyModifier>();
  for (const char* name :
       {"PointSetTopologyModifier", "EdgeSetTopologyModifier", "TriangleSetTopologyModifier",
        "QuadSetTopologyModifier", "HexahedronSetTopologyModifier"})
    registry.add(name, "SOFA's topology modifier: accepted, does nothing yet")
        .with<TopologyModifier>();
  const char* geometry =
      "SOFA's geometry algorithms (queries, drawing): accepted, does nothing yet";
  registry.add("PointSetGeometryAlgorithms", geometry).with<PointSetGeometryAlgorithms>();
  registry.add("EdgeSetGeometryAlgorithms", geometry).with<EdgeSetGeometryAlgorithms>();
  registry.add("TriangleSetGeometryAlgorithms", geometry).with<TriangleSetGeometryAlgorithms>();
  registry.add("QuadSetGeometryAlgorithms", geometry).with<QuadSetGeometryAlgorithms>();
  registry.add("TetrahedronSetGeometryAlgorithms", geometry)
      .with<TetrahedronSetGeometryAlgorithms>();
  registry.add("HexahedronSetGeometryAlgorithms", geometry).with<HexahedronSetGeometryAlgorithms>();
  registry.add("RegularGridTopology", "A regular grid of points and its hexahedra")
      .with<RegularGridTopology>()
      .alias("RegularGrid");
  registry.add("Hexa2TetraTopologicalMapping", "Splits hexahedra into tetrahedra (6 or 5 each)")
      .with<Hexa2TetraTopologicalMapping>();
  registry.add("Hexa2QuadTopologicalMapping", "The boundary quads of hexahedra")
      .with<Hexa2QuadTopologicalMapping>();
  registry.add("Tetra2TriangleTopologicalMapping", "The boundary triangles of tetrahedra")
      .with<Tetra2TriangleTopologicalMapping>();
  registry.add("Quad2TriangleTopologicalMapping", "Splits quads into two triangles each")
      .with<Quad2TriangleTopologicalMapping>();
  registry.add("Triangle2EdgeTopologicalMapping", "The border edges of triangles")
      .with<Triangle2EdgeTopologicalMapping>();
}

}  // namespace

extern "C" STROMA_PLUGIN_EXPORT const stroma::PluginEntry* stroma_plugin_entry() {
  static const stroma::PluginEntry entry = stroma::makePluginEntry(
      "Topology", "0.1.0", "Mesh topology containers, grids and topological mappings",
      registerComponents);
  return &entry;
}
