// SPDX-License-Identifier: MIT
#include "CubeCollisionModel.h"

namespace stroma {

// No primitive: the pipeline leaves out models without primitives.
void CubeCollisionModel::init() { m_geometry.kind = PrimitiveKind::box; }

}  // namespace stroma
