// SPDX-License-Identifier: MIT
// The unstructured grid of a mechanical state, as `stroma run --export-vtk` and VTKExporter
// write it: the state's positions as points, cells from a topology, and the state's fields.
#pragma once

#include <string>
#include <vector>

#include "VtkFiles.h"

namespace stroma {

class BaseMechanicalState;
class Node;
class StressField;
class Topology;

namespace vtk {

/// Which element lists of a topology become cells.
struct CellSelection {
  bool edges = false, triangles = false, quads = false, tetrahedra = false, hexahedra = false;
  bool any() const { return edges || triangles || quads || tetrahedra || hexahedra; }
};

/// The elements of highest dimension that `topology` has: its tetrahedra and hexahedra, else
/// its triangles and quads, else its edges; nothing for an empty topology or none.
CellSelection highestDimensionCells(const Topology* topology);

/// Appends the selected elements of `topology` as cells (edges, triangles, quads, tetrahedra,
/// hexahedra in that order, as SOFA's exporters). With nothing selected, or no topology, every point becomes
/// a vertex cell. False with `error` when an element uses a point past `pointCount`.
bool appendCells(const Topology* topology, const CellSelection& selection, std::size_t pointCount,
                 UnstructuredMesh& mesh, std::string& error);

/// The mesh an exporter component writes from its node: the `given` points when there are
/// some, else the node's state's, else the positions of the topology above; the selected
/// elements of that topology as cells (appendCells). False with `error` as appendCells.
bool nodeMesh(const Node* node, const std::vector<Vec3d>& given, const CellSelection& selection,
              UnstructuredMesh& mesh, std::string& error);

/// The positions of `state` as points: x y z of a Vec3d state, the centre of a Rigid3d frame,
/// zeros in the missing coordinates of Vec1d and Vec2d states.
std::vector<Vec3d> statePoints(const BaseMechanicalState& state);

/// The stress fields of the graph under `root` whose stressState() is `state`.
std::vector<const StressField*> findStressFields(const Node& root,
                                                 const BaseMechanicalState& state);

/// Adds the point fields "displacement" (positions - rest positions; Vec3d states),
/// "velocity" (its first three numbers), and with a stress field, "vonMises" per point and,
/// when the cells are exactly the field's elements, per cell (the first field that gives
/// values; counts are checked). The mesh's cells must be set first.
void addStateFields(const BaseMechanicalState& state,
                    const std::vector<const StressField*>& stresses, UnstructuredMesh& mesh);

}  // namespace vtk
}  // namespace stroma
