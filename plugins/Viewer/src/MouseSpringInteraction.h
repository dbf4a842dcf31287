// SPDX-License-Identifier: MIT
// SOFA's mouse interaction: a point of the body grabbed with the mouse is pulled by a spring
// toward the point under the mouse, for as long as the button is held.
#pragma once

#include "MouseSpringForceField.h"
#include "ScenePicker.h"

namespace stroma::viewer {

/// Stiffness per kilogram of the grabbed body (N/m per kg = 1/s^2) when none is given: the
/// body then hangs on the spring with a natural frequency of sqrt(1000) = 32 rad/s (5 Hz),
/// whatever its size, and a 1 kg body is pulled with SOFA's 1000 N/m.
inline constexpr double kSpringStiffnessPerKilogram = 1000.0;
/// The stiffness when the grabbed state has no mass above it (SOFA's default, N/m).
inline constexpr double kDefaultSpringStiffness = 1000.0;

/// The total mass (kg) of the body whose state `state` is or is mapped from: the nearest mass
/// in its node or an ancestor's, measured as twice its kinetic energy at a uniform unit
/// velocity. 0 when there is none (or it is not on a Vec3d state).
double grabbedBodyMass(const Vec3State& state);

/// Adds the spring (a MouseSpringForceField named "mouseSpring") to the picked state's node
/// at grab(), moves its target, and removes it at release(): between two steps, so that every
/// solver of the scene sees it in the next one like any other force field.
class MouseSpringInteraction {
 public:
  MouseSpringInteraction() = default;
  ~MouseSpringInteraction() { release(); }
  MouseSpringInteraction(const MouseSpringInteraction&) = delete;
  MouseSpringInteraction& operator=(const MouseSpringInteraction&) = delete;

  /// Starts pulling `picked` toward `target` with `stiffness` (N/m; <= 0: the mass-scaled
  /// default above). Releases a spring held before. Returns false (nothing added) when the
  /// spring cannot work on that state (its init reported an error).
  bool grab(const PickedPoint& picked, const Vec3d& target, double stiffness);
  void moveTarget(const Vec3d& target);
  /// Removes the spring from the scene; nothing when none is held.
  void release();

  bool active() const { return m_spring != nullptr; }
  const PickedPoint& picked() const { return m_picked; }
  /// The spring while it is held, else nullptr.
  const MouseSpringForceField* spring() const { return m_spring; }

 private:
  PickedPoint m_picked;
  MouseSpringForceField* m_spring = nullptr;  // owned by its node while held
};

}  // namespace stroma::viewer
