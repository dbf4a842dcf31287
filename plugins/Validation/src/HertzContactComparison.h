// SPDX-License-Identifier: MIT
#pragma once

#include <string>
#include <vector>

#include "Validation/kernels/HertzContact.h"
#include "core/Data.h"
#include "core/Link.h"
#include "core/StateTypes.h"
#include "simulation/AnimationLoop.h"
#include "simulation/MechanicalState.h"
#include "simulation/RunSummary.h"

namespace stroma {

/// Compares the contact force of an elastic sphere pressed on a rigid plane with Hertz's law
/// (kernels/HertzContact.h): the bench study bench/studies/Hertz.xml and its test.
///
/// The indentation delta is the approach of the driven points (`indices` of the node's state,
/// the flat face of a hemisphere) to the plane: their mean displacement against `normal`, less
/// `gap`. The force F is the sum, over the contact responses found in the scene (components of
/// the classes `responses`, created by CollisionResponse), of the normal part of their `force`
/// output, times `forceScale` (4 for a quarter model). Each comparison gives
///   hertzError     = F / F_H(delta) - 1,   F_H = 4/3 E* sqrt(R) delta^(3/2), Hertz's law with
///                    delta as the approach of distant points;
///   halfSpaceError = F / F_H(d) - 1,        d such that Hertz's half-space solution moves the
///                    axis point at `depth` below the contact by delta: the same law, with the
///                    finite depth at which the sphere is driven taken into account.
/// Comparisons happen at the start of each step (the state of the end of the previous one) and
/// when the outputs are read after the last step, whenever delta > minIndentation.
///
/// Errors naming the field: no 3-D state, no indices or one out of range, E, nu, R out of range,
/// a zero normal, depth < 0, forceScale <= 0.
class HertzContactComparison final : public BehaviorModel,
                                     public DataEngine,
                                     public RunSummaryProvider {
 public:
  using State = MechanicalState<Vec3Types>;

  Link<State> l_state{this, "state", "The sphere's mechanical state (default: the node's)."};
  Data<std::vector<unsigned>> d_indices{
      this, "indices", {}, "Driven points whose approach to the plane is the indentation."};
  Data<double> d_youngModulus{
      this, "youngModulus", 1e6, "Young's modulus of the sphere.", {.unit = "Pa", .min = 0.0}};
  Data<double> d_poissonRatio{this, "poissonRatio", 0.3,
                              "Poisson's ratio of the sphere (-1 < nu < 0.5)."};
  Data<double> d_radius{
      this, "radius", 1.0, "Radius of the sphere.", {.unit = "length", .min = 0.0}};
  Data<Vec3d> d_normal{this, "normal", Vec3d(0, 0, 1),
                       "Normal of the plane, towards the sphere (normalized; not zero)."};
  Data<double> d_gap{this,
                     "gap",
                     0.0,
                     "Approach of the driven points at which the sphere touches the plane.",
                     {.unit = "length"}};
  Data<double> d_depth{this,
                       "depth",
                       0.0,
                       "Depth of the driven points below the contact point, for the "
                       "half-space reference; 0: the radius (a hemisphere driven at its centre).",
                       {.unit = "length", .min = 0.0}};
  Data<double> d_forceScale{this,
                            "forceScale",
                            1.0,
                            "Factor on the measured force: 4 for a quarter of the sphere "
                            "(two symmetry planes).",
                            {.min = 0.0}};
  Data<double> d_minIndentation{this,
                                "minIndentation",
                                0.0,
                                "Comparisons only when the indentation is above this.",
                                {.unit = "length"}};
  Data<std::vector<std::string>> d_responses{
      this,
      "responses",
      {"PenalityContactForceField", "FrictionContactConstraint", "StickContactConstraint"},
      "Class names of the contact responses whose 'force' outputs are summed."};

  // Outputs: the latest comparison, and the largest and RMS errors over all of them.
  Data<double> d_indentation{
      this, "indentation", 0.0, "Latest indentation.", {.unit = "length", .output = true}};
  Data<double> d_force{this,
                       "force",
                       0.0,
                       "Latest contact force (normal part, scaled).",
                       {.unit = "N", .output = true}};
  Data<double> d_hertzForce{
      this, "hertzForce", 0.0, "Hertz's F_H(delta).", {.unit = "N", .output = true}};
  Data<double> d_halfSpaceForce{this,
                                "halfSpaceForce",
                                0.0,
                                "Hertz's force at the approach delta of the point at depth.",
                                {.unit = "N", .allowNonFinite = true, .output = true}};
  Data<double> d_hertzError{this,
                            "hertzError",
                            0.0,
                            "Latest F / F_H(delta) - 1.",
                            {.allowNonFinite = true, .output = true}};
  Data<double> d_halfSpaceError{this,
                                "halfSpaceError",
                                0.0,
                                "Latest F / halfSpaceForce - 1.",
                                {.allowNonFinite = true, .output = true}};
  Data<double> d_maxHertzError{this,
                               "maxHertzError",
                               0.0,
                               "Largest |hertzError| of the comparisons (NaN before one).",
                               {.allowNonFinite = true, .output = true}};
  Data<double> d_rmsHertzError{
      this, "rmsHertzError", 0.0, "RMS of hertzError.", {.allowNonFinite = true, .output = true}};
  Data<double> d_maxHalfSpaceError{this,
                                   "maxHalfSpaceError",
                                   0.0,
                                   "Largest |halfSpaceError| of the comparisons.",
                                   {.allowNonFinite = true, .output = true}};
  Data<double> d_rmsHalfSpaceError{this,
                                   "rmsHalfSpaceError",
                                   0.0,
                                   "RMS of halfSpaceError.",
                                   {.allowNonFinite = true, .output = true}};
  Data<int> d_comparisons{this, "comparisons", 0, "Comparisons so far.", {.output = true}};

  HertzContactComparison();
  void init() override;
  void updatePosition(double dt) override;
  std::vector<std::string> runSummaryLines() const override;

 protected:
  void doUpdate() override;

 private:
  struct Comparison {
    double time, indentation, force, hertzForce, halfSpaceForce;
  };
  double measureForce() const;
  void compareNow();
  void publish();

  reference::HertzContact m_hertz;
  bool m_ready = false;
  std::vector<Comparison> m_history;
};

}  // namespace stroma
