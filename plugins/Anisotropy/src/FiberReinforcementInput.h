// SPDX-License-Identifier: MIT
// What TetrahedralFiberReinforcementForceField needs besides its physics: finding and checking
// the tetrahedra, finding the isotropic force fields beside it, and writing numbers and element
// lists into messages.
#pragma once

#include <string>
#include <vector>

#include "SolidMechanics/kernels/LinearTetrahedron.h"
#include "core/Base.h"
#include "core/Link.h"
#include "core/StateTypes.h"
#include "simulation/ForceField.h"
#include "topology/Topology.h"

namespace stroma::reinforcement {

/// "3, 17, 42" or "3, 17, 42, ... (12 in all)": element indices for messages, the first 10.
std::string describeElements(const std::vector<std::size_t>& indices);

/// The rest shape of each tetrahedron of `topology` from the state's rest positions. Points out of
/// range and flat tetrahedra are errors on `owner`, field "topology", naming the elements;
/// returns false after one. Both orientations are accepted.
bool computeRestShapes(Base& owner, const Topology& topology,
                       const std::vector<Vec3d>& restPositions,
                       std::vector<fem::TetrahedronShape>& shapes);

/// A force field of the same node on the same state with one youngModulus and one poissonRatio
/// (an isotropic elastic field, as its Data say).
struct IsotropicPartner {
  const BaseForceField* field = nullptr;
  double youngModulus = 0;
  double poissonRatio = 0;
  const BaseData* method = nullptr;  ///< its `method` Data, when it has one
};

/// The isotropic partners of `self` in `node` acting on `state` (after their init).
std::vector<IsotropicPartner> findIsotropicPartners(const Node& node, const Base& self,
                                                    const BaseMechanicalState* state);

}  // namespace stroma::reinforcement
