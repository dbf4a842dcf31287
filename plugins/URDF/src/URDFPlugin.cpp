// SPDX-License-Identifier: MIT
#include "ArticulatedBodyMass.h"
#include "ArticulatedMapping.h"
#include "JointActuatorForceField.h"
#include "JointLimitConstraint.h"
#include "JointLimitLagrangianConstraint.h"
#include "URDFLoader.h"
#include "core/Plugin.h"

namespace {

void registerComponents(stroma::PluginRegistry& registry) {
  using namespace stroma;
  registry.add("URDFLoader", "A robot from a URDF file, as an articulated body (urdfdom)")
      .with<URDFLoader>();
  registry.add("ArticulatedMapping", "Frames of the links of an articulated body from its joints")
      .with<ArticulatedMapping>("Vec1d,Rigid3d");
  registry.add("ArticulatedBodyMass", "Masses of the links of an articulated body, in its joints")
      .with<ArticulatedBodyMass>("Vec1d");
  registry.add("JointActuatorForceField",
               "PD drive of joint values toward targets over time, damping and friction")
      .with<JointActuatorForceField>("Vec1d");
  registry.add("JointLimitConstraint", "Joint values clamped to their range (an inelastic stop)")
      .with<JointLimitConstraint>("Vec1d");
  registry.add("JointLimitLagrangianConstraint",
               "Joint values kept in their range by Lagrange multipliers (the stop's torque out)")
      .with<JointLimitLagrangianConstraint>();
}

}  // namespace

extern "C" STROMA_PLUGIN_EXPORT const stroma::PluginEntry* stroma_plugin_entry() {
  static const stroma::PluginEntry entry = stroma::makePluginEntry(
      "URDF", "0.1.0", "Robots from URDF files (urdfdom) as articulated bodies in joint coordinates",
      registerComponents);
  return &entry;
}
