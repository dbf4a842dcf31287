// SPDX-License-Identifier: MIT
#pragma once

#include "core/Types.h"
#include "topology/Topology.h"

namespace stroma {

/// The element lists a container keeps, as a bit set (SOFA's container family: an edge set
/// keeps edges, a triangle set triangles and their edges, a tetrahedron set tetrahedra, their
/// triangles and edges...).
namespace kinds {
inline constexpr unsigned edges = 1, triangles = 2, quads = 4, tetrahedra = 8, hexahedra = 16;
inline constexpr unsigned all = edges | triangles | quads | tetrahedra | hexahedra;
}  // namespace kinds

/// What MeshTopology, the *SetTopologyContainer components and RegularGridTopology share: SOFA's
/// other attribute names, reading the elements from a file, and the checks at init.
///
/// init(), and reinit() after the elements changed (a topological mapping calls it):
/// 1. SOFA's other names (`points`, `lines`, `tetras`, `hexas`) fill the main lists;
/// 2. a `filename` given here is read (Gmsh, VTK, OBJ, STL), for the lists the scene left empty;
/// 3. lists this kind of container does not keep are emptied (when the scene wrote them, with a
///    warning): a TetrahedronSetTopologyContainer that takes `src="@loader"` keeps the
///    loader's tetrahedra, triangles and edges, not its quads or hexahedra;
/// 4. the elements are checked (Topology::checkElements);
/// 5. set containers create their missing sub-elements, as SOFA's do on first request: the
///    unique triangles of the tetrahedra, the unique quads of the hexahedra, every edge.
class TopologyContainer : public Topology {
 public:
  Data<FileName> d_filename{this,
                            "filename",
                            {},
                            "Mesh file to read the points and elements from (Gmsh, VTK, OBJ or "
                            "STL), for those not given otherwise.",
                            {.autoLink = false}};
  Data<FileName> d_fileTopology{
      this, "fileTopology", {}, "SOFA's other name for filename.", {.autoLink = false}};
  Data<std::vector<Vec3d>> d_points{
      this, "points", {}, "SOFA's other name for position.", {.unit = "m", .autoLink = false}};

  void init() override;
  void reinit() override;

  /// True when this container keeps this kind of element (a `kinds::` bit).
  bool holds(unsigned kind) const { return (m_kinds & kind) != 0; }

 protected:
  /// `held`: the kinds:: this container keeps; `createsSubElements`: fill the missing faces and
  /// edges (set containers) or keep the lists as given (MeshTopology, grids).
  TopologyContainer(unsigned held, bool createsSubElements);

  /// Fills `main` from the SOFA alias `alias` when the scene gave the alias (a value or a link)
  /// and did not give `main` itself.
  template <class T>
  void adoptAlias(Data<T>& alias, Data<T>& main);
  /// Subclasses adopt their own aliases here (called first by init()).
  virtual void adoptAliases() {}

 private:
  void readFile();
  void dropUnheldKinds();
  void createSubElements();

  unsigned m_kinds;
  bool m_createsSubElements;
  bool m_fileRead = false;
  // Which lists this container filled itself, so that reinit() recomputes them.
  bool m_madeEdges = false, m_madeTriangles = false, m_madeQuads = false;
};

/// True when the scene itself gave this Data (a value or a link written on the component), not
/// when it only follows `src="@..."`.
bool givenInScene(const BaseData& data);

template <class T>
void TopologyContainer::adoptAlias(Data<T>& alias, Data<T>& main) {
  if (!givenInScene(alias)) return;
  if (givenInScene(main)) {
    msgWarning("both '" + main.name() + "' and its other name '" + alias.name() + "' are given; '" +
                   alias.name() + "' is ignored",
               alias.name());
    return;
  }
  std::string ignored;
  if (alias.parent()) {
    main.setParent(alias.parent(), ignored);
  } else {
    main.setParent(nullptr, ignored);
    main.setValue(alias.value());
  }
}

}  // namespace stroma
