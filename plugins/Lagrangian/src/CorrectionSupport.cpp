// SPDX-License-Identifier: MIT
#include "CorrectionSupport.h"

#include "simulation/MechanicalOperations.h"

namespace stroma::lagrangian {

Eigen::VectorXd massRowSums(MechanicalOperations& mop) {
  const VecId ones = mop.allocDeriv(), product = mop.allocDeriv();
  mop.scatter(Eigen::VectorXd::Ones(static_cast<Eigen::Index>(mop.systemSize())), ones);
  MechanicalParams mass;
  mass.mFactor = 1.0;
  mass.kFactor = 0.0;
  mop.computeMBKdx(mass, product, ones);
  Eigen::VectorXd sums;
  mop.gather(product, sums);
  mop.freeVec(ones);
  mop.freeVec(product);
  return sums;
}

void moveStates(MechanicalOperations& mop, const ConstraintResponse& response,
                const Eigen::VectorXd& u) {
  const VecId d = mop.allocDeriv();
  mop.scatter(u, d);
  mop.vOp(VecId::position(), VecId::position(), d, response.positionFactor);
  if (response.velocityFactor != 0)
    mop.vOp(VecId::velocity(), VecId::velocity(), d, response.velocityFactor);
  mop.freeVec(d);
  mop.propagate(VecId::position(), VecId::velocity());
}

}  // namespace stroma::lagrangian
