// SPDX-License-Identifier: MIT
#pragma once

#include <string>
#include <vector>

#include "core/StateTypes.h"
#include "simulation/ForceField.h"

namespace stroma {

/// Forces on joint values (Vec1d): a PD drive toward position targets over time, viscous
/// damping and (smoothed) Coulomb friction,
///   tau_j = -stiffness_j (q_j - target_j(t)) - damping_j qdot_j - friction_j tanh(qdot_j / v0),
/// v0 = 1e-3 rad/s (or m/s) so that friction stays smooth for the implicit solvers. The targets
/// are a key-time table (keyTimes, keyTargets) or a CSV file (targetFile: lines "t, q_0, q_1,
/// ..."; lines that are not numbers, as a header, are skipped), interpolated linearly and held
/// before the first and after the last key; without targets the drive holds the values at 0.
/// The target is taken at the start of the step. Output `torques`: the drive's tau of each
/// joint value at the last force evaluation (N m or N).
class JointActuatorForceField final : public ForceField<Vec1Types> {
 public:
  Data<std::vector<double>> d_stiffness{this, "stiffness", {},
                                        "PD stiffness of each joint value (nbJoints, or one for "
                                        "all); empty: no spring.",
                                        {.unit = "N m/rad"}};
  Data<std::vector<double>> d_damping{this, "damping", {},
                                      "Viscous damping of each joint value (nbJoints, or one "
                                      "for all).",
                                      {.unit = "N m s/rad"}};
  Data<std::vector<double>> d_friction{this, "friction", {},
                                       "Coulomb friction torque of each joint value (nbJoints, "
                                       "or one for all).",
                                       {.unit = "N m"}};
  Data<std::vector<double>> d_keyTimes{this, "keyTimes", {}, "Times of the targets (nbKeys).",
                                       {.unit = "s"}};
  Data<std::vector<double>> d_keyTargets{this, "keyTargets", {},
                                         "Target joint values at each key time (nbKeys x "
                                         "nbJoints)."};
  Data<FileName> d_targetFile{this, "targetFile", {},
                              "CSV file of targets: 't, q_0, ..., q_{nbJoints-1}' per line."};
  Data<std::vector<double>> d_torques{this, "torques", {},
                                      "Drive torque of each joint value at the last evaluation "
                                      "(output).",
                                      {.output = true}};

  void init() override;
  void addForce(const MechanicalParams& mp, VecDeriv& f, const VecCoord& x,
                const VecDeriv& v) override;
  void addDForce(const MechanicalParams& mp, VecDeriv& df, const VecDeriv& dx) override;
  void addKToMatrix(const MechanicalParams& mp, MatrixAccumulator& matrix,
                    std::size_t offset) override;
  double potentialEnergy(const MechanicalParams& mp, const VecCoord& x) const override;

  /// The target of joint value j at time t.
  double target(std::size_t j, double t) const;

 private:
  bool readTargetFile();
  bool perJoint(const Data<std::vector<double>>& data, std::vector<double>& out);

  std::vector<double> m_stiffness, m_damping, m_friction, m_times, m_targets;
  std::vector<double> m_lastVelocity;
  bool m_ready = false;
};

}  // namespace stroma
