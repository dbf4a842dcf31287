// SPDX-License-Identifier: MIT
// What DiagonalMass and MeshMatrixMass share: finding the topology, checking its elements
// against the state, the unit-density mass matrix, and the density that a total mass implies.
#pragma once

#include <span>

#include "MeshMassKernels.h"
#include "core/Base.h"
#include "core/Link.h"
#include "topology/Topology.h"

namespace stroma {

/// The topology of `link`, else the nearest one from the owner's node up (as SOFA); reports
/// an error on `owner` (field "topology") when there is none.
const Topology* findMassTopology(Base& owner, const Link<Topology>& link);

/// Checks that the topology's elements use points < points.size() and that it has elements to
/// carry mass, then assembles the unit-density matrix. Reports errors on `owner`; returns false
/// after one.
bool computeMeshMass(Base& owner, const Topology& topology, std::span<const Vec3d> points,
                     MeshMassMatrix& out);

/// The density: totalMass / measure when totalMass > 0, else massDensity.
inline double massDensityOf(double totalMass, double massDensity, double measure) {
  return totalMass > 0 ? (measure > 0 ? totalMass / measure : 0.0) : massDensity;
}

}  // namespace stroma
