// SPDX-License-Identifier: MIT
// What DiagonalMass and MeshMatrixMass share: finding the topology, checking its elements
// against the state, the unit-density mass matrix, and the density that a total mass implies.
#pragma once

#include <span>

#include "MeshMassKernels.h"
#include "core/Base.h"
#include "core/Link.h"
#include "topology/Topology.h"
#include "topology/TopologyChange.h"

namespace stroma {

/// The topology of `link`, else the nearest one from the owner's node up (as SOFA); reports
/// an error on `owner` (field "topology") when there is none.
const Topology* findMassTopology(Base& owner, const Link<Topology>& link);

/// Checks that the topology's elements use points < points.size() and that it has elements to
/// carry mass, then assembles the unit-density matrix. Reports errors on `owner`; returns false
/// after one.
bool computeMeshMass(Base& owner, const Topology& topology, std::span<const Vec3d> points,
                     MeshMassMatrix& out);

/// Follows the removal of tetrahedra (cutting) on a unit-density mass computed on the
/// tetrahedra of `points` (the points the mass was computed on): subtracts each removed
/// tetrahedron's element matrix from `matrix` (when given: the consistent matrix), V/4 from the
/// lumped mass of each of its points and V from `measure`. A point left without tetrahedra gets
/// exactly zero (no round-off residue), and the measure is exactly zero once no tetrahedron
/// remains. The result equals an assembly on the remaining tetrahedra to round-off; the cost is
/// proportional to the removed tetrahedra.
void removeTetrahedronMasses(const TopologyChange& change, std::span<const Vec3d> points,
                             Eigen::SparseMatrix<double, Eigen::RowMajor>* matrix,
                             Eigen::VectorXd& lumped, double& measure);

/// The density: totalMass / measure when totalMass > 0, else massDensity.
inline double massDensityOf(double totalMass, double massDensity, double measure) {
  return totalMass > 0 ? (measure > 0 ? totalMass / measure : 0.0) : massDensity;
}

}  // namespace stroma
