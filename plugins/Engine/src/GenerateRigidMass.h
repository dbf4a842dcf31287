// SPDX-License-Identifier: MIT
#pragma once

#include <vector>

#include "RigidMass.h"
#include "core/Base.h"
#include "core/Types.h"
#include "topology/TopologyTypes.h"

namespace stroma {

/// The rigid mass of a homogeneous solid given by its closed surface (SOFA's GenerateRigidMass,
/// template Rigid3d): mass, volume, center of mass and inertia from `density`, `position`,
/// `triangles` and `quads`, exact for the polyhedron (PolyhedronMassProperties.h). A data
/// engine: the outputs are recomputed when read after an input changed.
///
/// `rigidMass` is the text a Rigid3d UniformMass reads as `vertexMass`
/// (`vertexMass="@engine.rigidMass"`): "mass volume inertia", the inertia per unit mass about
/// the center of mass in the mesh's axes, 9 numbers row by row (m^2). It is the body-frame
/// inertia of a Rigid3d frame placed at `massCenter` with the identity orientation (SOFA's
/// scenes put the frame there with `translation="@engine.massCenter"` and move the surface by
/// `centerToOrigin`). `inertiaMatrix` is that same matrix per unit mass, as in SOFA; the
/// inertia of the body is mass * inertiaMatrix (kg m^2).
///
/// Errors, each on the field to fix: no points (`position`); no faces, a point index out of
/// range, a surface that is not closed or not consistently oriented (an edge no face runs back,
/// named with its face), an inverted surface (negative volume: faces oriented inwards) or one
/// that encloses no volume (`triangles`, or `quads` when the surface has only quads).
class GenerateRigidMass final : public Base, public DataEngine {
 public:
  Data<double> d_density{this,
                         "density",
                         1000.0,
                         "Mass per unit volume of the solid.",
                         {.unit = "kg/m^3", .min = 0.0}};
  Data<std::vector<Vec3d>> d_position{
      this,
      "position",
      {},
      "Points of the closed surface (nbPoints x 3), e.g. position=\"@loader.position\".",
      {.unit = "m"}};
  Data<std::vector<Triangle>> d_triangles{
      this,
      "triangles",
      {},
      "Triangles of the closed surface, oriented outwards (nbTriangles x 3 point indices)."};
  Data<std::vector<Quad>> d_quads{this,
                                  "quads",
                                  {},
                                  "Quads of the closed surface, oriented outwards (nbQuads x 4 "
                                  "point indices); each counts as the triangles (a b c), (a c d)."};
  Data<Vec3d> d_scale{this, "scale", Vec3d::Ones(),
                      "Scale of the points along x, y and z (about the origin) before the "
                      "integration; a mirror (an odd number of negative factors) is allowed."};

  Data<RigidMass3> d_rigidMass{
      this,
      "rigidMass",
      RigidMass3{},
      "Rigid mass 'mass volume inertia', as a Rigid3d UniformMass reads vertexMass: the "
      "inertia per unit mass about the center of mass in the mesh's axes (3x3 row by row, m^2).",
      {.output = true}};
  Data<double> d_mass{
      this, "mass", 0.0, "Mass: density times volume.", {.unit = "kg", .output = true}};
  Data<double> d_volume{
      this, "volume", 0.0, "Volume enclosed by the surface.", {.unit = "m^3", .output = true}};
  Data<Vec<9>> d_inertiaMatrix{
      this,
      "inertiaMatrix",
      Vec<9>::Zero(),
      "Inertia per unit mass about the center of mass in the mesh's axes (3x3 row by row), as "
      "in SOFA; times mass it is the body's inertia (kg m^2).",
      {.unit = "m^2", .output = true}};
  Data<Vec3d> d_massCenter{
      this, "massCenter", Vec3d::Zero(), "Center of mass.", {.unit = "m", .output = true}};
  Data<Vec3d> d_centerToOrigin{this,
                               "centerToOrigin",
                               Vec3d::Zero(),
                               "Vector from the center of mass to the origin (-massCenter): the "
                               "translation that centers the surface on the body frame.",
                               {.unit = "m", .output = true}};

  GenerateRigidMass();

  void init() override;
  void reinit() override { setDirty(); }

 protected:
  void doUpdate() override;

 private:
  void clearOutputs();
};

}  // namespace stroma
