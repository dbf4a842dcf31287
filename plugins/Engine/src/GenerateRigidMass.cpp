// SPDX-License-Identifier: MIT
#include "GenerateRigidMass.h"

#include <cmath>
#include <string>

#include "PolyhedronMassProperties.h"

namespace stroma {

namespace {

template <std::size_t N>
std::string elementText(const std::array<Index, N>& element) {
  std::string text;
  for (std::size_t k = 0; k < N; ++k) text += (k ? " " : "") + std::to_string(element[k]);
  return text;
}

/// The first element using a point past `nbPoints`, as "triangle 3 (0 1 12) uses point 12".
template <std::size_t N>
std::string findIndexOutOfRange(const std::vector<std::array<Index, N>>& elements,
                                std::size_t nbPoints, const char* what) {
  for (std::size_t e = 0; e < elements.size(); ++e)
    for (const Index p : elements[e])
      if (p >= nbPoints)
        return std::string(what) + " " + std::to_string(e) + " (" + elementText(elements[e]) +
               ") uses point " + std::to_string(p) + ", out of range of the " +
               std::to_string(nbPoints) + " points of position";
  return {};
}

std::string numberText(double value) {
  std::string text;
  ElementTraits<double>::print(text, value);
  return text;
}

}  // namespace

GenerateRigidMass::GenerateRigidMass() {
  for (BaseData* input :
       std::initializer_list<BaseData*>{&d_density, &d_position, &d_triangles, &d_quads, &d_scale})
    addInput(input);
  for (BaseData* output : std::initializer_list<BaseData*>{
           &d_rigidMass, &d_mass, &d_volume, &d_inertiaMatrix, &d_massCenter, &d_centerToOrigin})
    addOutput(output);
}

void GenerateRigidMass::init() {
  // Compute now, so that a bad surface is reported by this engine even when nothing reads it.
  d_rigidMass.value();
}

void GenerateRigidMass::clearOutputs() {
  d_rigidMass.setValue(RigidMass3{0.0, 0.0, Mat3d::Zero()});
  d_mass.setValue(0.0);
  d_volume.setValue(0.0);
  d_inertiaMatrix.setValue(Vec<9>::Zero());
  d_massCenter.setValue(Vec3d::Zero());
  d_centerToOrigin.setValue(Vec3d::Zero());
}

void GenerateRigidMass::doUpdate() {
  const std::vector<Vec3d>& position = d_position.value();
  const std::vector<Triangle>& triangles = d_triangles.value();
  const std::vector<Quad>& quads = d_quads.value();
  // The field that holds the faces, for the messages about the surface.
  const char* facesField = triangles.empty() && !quads.empty() ? "quads" : "triangles";
  auto fail = [&](const std::string& text, const char* field) {
    msgError(text, field);
    clearOutputs();
  };

  // The surface: points, faces, indices in range, closed and consistently oriented.
  if (position.empty())
    return fail(
        "no points: expected the points of the closed surface (e.g. "
        "position=\"@loader.position\")",
        "position");
  if (triangles.empty() && quads.empty())
    return fail(
        "no triangles nor quads: expected the faces of the closed surface (e.g. "
        "triangles=\"@loader.triangles\" quads=\"@loader.quads\")",
        "triangles");
  if (std::string bad = findIndexOutOfRange(triangles, position.size(), "triangle"); !bad.empty())
    return fail(bad, "triangles");
  if (std::string bad = findIndexOutOfRange(quads, position.size(), "quad"); !bad.empty())
    return fail(bad, "quads");
  if (const std::optional<UnmatchedEdge> open = findUnmatchedEdge(position, triangles, quads)) {
    const std::string element =
        open->inQuad ? elementText(quads[open->face]) : elementText(triangles[open->face]);
    return fail("the surface is not closed: no face runs the edge from point " +
                    std::to_string(open->from) + " to point " + std::to_string(open->to) + " of " +
                    (open->inQuad ? "quad " : "triangle ") + std::to_string(open->face) + " (" +
                    element + ") the other way (a hole, or a face oriented against its neighbours)",
                open->inQuad ? "quads" : "triangles");
  }

  // The integrals, on the scaled points. A mirror reverses the faces' orientation.
  const Vec3d scale = d_scale.value();
  std::vector<Vec3d> scaled(position.size());
  for (std::size_t i = 0; i < position.size(); ++i) scaled[i] = position[i].cwiseProduct(scale);
  PolyhedronMassProperties properties = computePolyhedronMassProperties(scaled, triangles, quads);
  if (scale.prod() < 0) {
    properties.volume = -properties.volume;
    properties.inertia = -properties.inertia;
  }

  // The volume: positive, and not lost in rounding (relative to the bounding box).
  Vec3d low = scaled.front(), high = scaled.front();
  for (const Vec3d& p : scaled) {
    low = low.cwiseMin(p);
    high = high.cwiseMax(p);
  }
  const double extent = (high - low).norm();
  const double volume = properties.volume;
  if (!(std::abs(volume) > 1e-12 * extent * extent * extent))
    return fail("the surface encloses no volume (" + numberText(volume) +
                    " m^3 for a bounding box of diagonal " + numberText(extent) +
                    " m): a flat or degenerate surface",
                facesField);
  if (volume < 0)
    return fail("the surface is inverted: its volume is negative (" + numberText(volume) +
                    " m^3), its faces are oriented inwards; reverse them (flipNormals=\"1\" on "
                    "the loader)",
                facesField);

  // Outputs: per unit mass, as SOFA's Rigid3Mass.
  const double density = d_density.value();
  const Mat3d perUnitMass = properties.inertia / volume;
  d_rigidMass.setValue(RigidMass3{density * volume, volume, perUnitMass});
  d_mass.setValue(density * volume);
  d_volume.setValue(volume);
  Vec<9> rows;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) rows[3 * r + c] = perUnitMass(r, c);
  d_inertiaMatrix.setValue(rows);
  d_massCenter.setValue(properties.center);
  d_centerToOrigin.setValue(-properties.center);
}

}  // namespace stroma
