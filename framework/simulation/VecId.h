// SPDX-License-Identifier: MIT
#pragma once

namespace stroma {

/// Names a state vector of every mechanical state at once: a position-like (coord) or a
/// velocity-like (deriv) vector. Standard vectors have fixed ids; solvers allocate temporaries
/// (MechanicalOperations::allocDeriv) with ids from kFirstTemporary on.
struct VecId {
  enum class Type { none, coord, deriv };
  Type type = Type::none;
  int index = 0;

  constexpr bool isNull() const { return type == Type::none; }
  constexpr bool isCoord() const { return type == Type::coord; }
  constexpr bool isDeriv() const { return type == Type::deriv; }
  constexpr bool operator==(const VecId&) const = default;

  static constexpr VecId null() { return {}; }
  static constexpr VecId coord(int i) { return {Type::coord, i}; }
  static constexpr VecId deriv(int i) { return {Type::deriv, i}; }

  // Standard coord vectors.
  static constexpr VecId position() { return coord(0); }
  static constexpr VecId restPosition() { return coord(1); }
  static constexpr VecId freePosition() { return coord(2); }
  static constexpr VecId resetPosition() { return coord(3); }
  // Standard deriv vectors.
  static constexpr VecId velocity() { return deriv(0); }
  static constexpr VecId force() { return deriv(1); }
  static constexpr VecId dx() { return deriv(2); }
  static constexpr VecId freeVelocity() { return deriv(3); }
  static constexpr VecId externalForce() { return deriv(4); }
  /// The force of the Lagrangian constraints at the last step (FreeMotionAnimationLoop).
  static constexpr VecId constraintForce() { return deriv(5); }

  static constexpr int kFirstTemporary = 8;
};

/// Factors and vectors of one mechanical operation: which positions and velocities a force is
/// evaluated at, and the factors of M, B (damping) and K in a combination m M + b B + k K.
struct MechanicalParams {
  double dt = 0;
  double mFactor = 0;
  double bFactor = 0;
  double kFactor = 1;
  VecId x = VecId::position();
  VecId v = VecId::velocity();
};

}  // namespace stroma
