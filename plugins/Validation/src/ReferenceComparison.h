// SPDX-License-Identifier: MIT
#pragma once

#include <array>
#include <string_view>
#include <vector>

#include "Mapping/src/BarycentricCoordinates.h"
#include "core/Data.h"
#include "core/DataTraits.h"
#include "core/Link.h"
#include "core/StateTypes.h"
#include "simulation/AnimationLoop.h"
#include "simulation/MechanicalState.h"
#include "simulation/RunSummary.h"
#include "simulation/StateFile.h"
#include "topology/Topology.h"

namespace stroma {

/// The analytic references of plugins/Validation/kernels.
enum class AnalyticReference {
  none,
  cantileverTip,
  cantileverCurve,
  uniaxialBlock,
  patch,
  torsion,
  lame
};
enum class ReferenceBeamTheory { timoshenko, eulerBernoulli };
enum class ReferenceMaterial { linear, StVenantKirchhoff, NeoHookean };

template <>
struct EnumKeywords<AnalyticReference> {
  static constexpr std::array<std::string_view, 7> names{
      "none", "cantileverTip", "cantileverCurve", "uniaxialBlock", "patch", "torsion", "lame"};
};
template <>
struct EnumKeywords<ReferenceBeamTheory> {
  static constexpr std::array<std::string_view, 2> names{"timoshenko", "eulerBernoulli"};
};
template <>
struct EnumKeywords<ReferenceMaterial> {
  static constexpr std::array<std::string_view, 3> names{"linear", "StVenantKirchhoff",
                                                         "NeoHookean"};
};

/// Compares the positions of a 3-D mechanical state with a reference and reports the error:
/// the largest and the root-mean-square distance between simulated and reference points, in
/// scene units and relative to `referenceLength`, at the simulated `times` (or, without times,
/// whenever the outputs are read: at the end of a run). `stroma run` prints the result after
/// its timing summary (RunSummaryProvider); a study reads the outputs.
///
/// One reference, among:
/// - `analytic`: a displacement field of plugins/Validation/kernels evaluated at the rest
///   positions (cantilever deflection along `loadDirection` only, other fields whole);
/// - `referenceState`: positions of a state file (docs/state-format.md), by index when the
///   counts agree; otherwise its first snapshot gives the rest positions of its points, which
///   are located in this node's mesh at rest (barycentric in tetrahedra, trilinear in
///   hexahedra) and compared with the interpolated simulation (a fine reference run against a
///   coarse one);
/// - `markers`: a CSV of positions (the Truth Cube beads), matched by `markerIndices` or
///   located in the mesh from rest positions in `restMarkerColumns` of the same file.
///
/// Errors naming the field: referenceLength <= 0, no or two references, files missing or
/// malformed (file and line), counts that disagree, indices out of range, a zero axis.
class ReferenceComparison final : public BehaviorModel,
                                  public DataEngine,
                                  public RunSummaryProvider {
 public:
  using State = MechanicalState<Vec3Types>;

  // Reference and comparison.
  Link<State> l_state{this, "state", "The compared mechanical state (default: the node's)."};
  Link<Topology> l_topology{this, "topology",
                            "Mesh whose tetrahedra or hexahedra locate reference points that are "
                            "not state points (default: the node's or above)."};
  Data<double> d_referenceLength{this,
                                 "referenceLength",
                                 0.0,
                                 "Length the relative errors are divided by (> 0, required).",
                                 {.unit = "length"}};
  Data<std::vector<double>> d_times{this,
                                    "times",
                                    {},
                                    "Simulated times of the comparisons (s); empty: whenever the "
                                    "outputs are read (the end of a run)."};
  Data<std::vector<unsigned>> d_indices{
      this,
      "indices",
      {},
      "Compared subset: state points (analytic, or a state file matched by index) or reference "
      "points (markers, located state-file points); empty: all."};
  Data<AnalyticReference> d_analytic{this, "analytic", AnalyticReference::none,
                                     "Analytic reference: none, cantileverTip, cantileverCurve, "
                                     "uniaxialBlock, patch, torsion or lame."};
  Data<FileName> d_referenceState{this,
                                  "referenceState",
                                  {},
                                  "State file (docs/state-format.md) holding the reference "
                                  "positions.",
                                  {.mustExist = false}};
  Data<double> d_referenceTime{this,
                               "referenceTime",
                               -1.0,
                               "Time of the snapshot of referenceState to compare with; < 0: "
                               "the snapshot at the compared time, else the last one.",
                               {.unit = "s"}};
  Data<std::string> d_referencePath{this, "referencePath", "",
                                    "Path of the state in referenceState (default: this "
                                    "state's path, else its only 3-D state)."};
  Data<FileName> d_markers{this,
                           "markers",
                           {},
                           "Marker file: comma-separated positions, one marker per line ('#' "
                           "comments, an optional header line).",
                           {.mustExist = false}};
  Data<std::vector<int>> d_markerColumns{this,
                                         "markerColumns",
                                         {0, 1, 2},
                                         "Columns (0-based) of x, y, z of the reference marker "
                                         "positions (3 numbers)."};
  Data<std::vector<int>> d_restMarkerColumns{
      this,
      "restMarkerColumns",
      {},
      "Columns of the markers' rest positions, located in the mesh at rest (3 numbers); empty: "
      "match by markerIndices."};
  Data<double> d_markerScale{this,
                             "markerScale",
                             1.0,
                             "Factor from the marker file's unit to the scene's (1e-3: mm to "
                             "m).",
                             {.min = 0.0}};
  Data<std::vector<unsigned>> d_markerIndices{
      this, "markerIndices", {}, "State point of each marker (one per marker)."};

  // Parameters of the analytic references (unused ones are ignored).
  Data<Vec3d> d_origin{this,
                       "origin",
                       Vec3d::Zero(),
                       "Clamped end centre (beam, cylinder), fixed point (block), axis point "
                       "(lame).",
                       {.unit = "length"}};
  Data<Vec3d> d_axis{this, "axis", Vec3d(1, 0, 0),
                     "Axis of the beam, block stretch or cylinder (normalized; not zero)."};
  Data<Vec3d> d_loadDirection{this, "loadDirection", Vec3d(0, -1, 0),
                              "Direction of the beam's load and deflection (normalized)."};
  Data<double> d_length{
      this, "length", 1.0, "Beam or cylinder length.", {.unit = "length", .min = 0.0}};
  Data<double> d_sectionHeight{this,
                               "sectionHeight",
                               0.1,
                               "Beam section size along the load.",
                               {.unit = "length", .min = 0.0}};
  Data<double> d_sectionWidth{this,
                              "sectionWidth",
                              0.1,
                              "Beam section size across the load.",
                              {.unit = "length", .min = 0.0}};
  Data<double> d_tipForce{this,
                          "tipForce",
                          0.0,
                          "Total beam load at the free end, along "
                          "loadDirection.",
                          {.unit = "N"}};
  Data<double> d_lineLoad{this,
                          "lineLoad",
                          0.0,
                          "Beam load per unit length along loadDirection (gravity: rho g A).",
                          {.unit = "N/length"}};
  Data<ReferenceBeamTheory> d_beamTheory{this, "beamTheory", ReferenceBeamTheory::timoshenko,
                                         "timoshenko or eulerBernoulli."};
  Data<double> d_shearCorrection{this,
                                 "shearCorrection",
                                 0.0,
                                 "Timoshenko's kappa; 0: Cowper's rectangle, 10 (1 + nu) / (12 "
                                 "+ 11 nu).",
                                 {.min = 0.0}};
  Data<double> d_youngModulus{
      this, "youngModulus", 1e6, "Young's modulus of the reference.", {.unit = "Pa"}};
  Data<double> d_poissonRatio{this, "poissonRatio", 0.3,
                              "Poisson's ratio of the reference (lame: up to 0.5)."};
  Data<ReferenceMaterial> d_material{this, "material", ReferenceMaterial::linear,
                                     "Block material: linear, StVenantKirchhoff or NeoHookean."};
  Data<double> d_stretch{this, "stretch", 1.0, "Block stretch along axis (1: none).", {.min = 0.0}};
  Data<double> d_nominalStress{this,
                               "nominalStress",
                               0.0,
                               "Block load per undeformed area along axis; when given, the "
                               "stretch is solved from it.",
                               {.unit = "Pa"}};
  Data<std::vector<double>> d_displacementGradient{
      this,
      "displacementGradient",
      {1e-3, 5e-4, 5e-4, 5e-4, 1e-3, 5e-4, 5e-4, 5e-4, 1e-3},
      "Patch: du/dX, 9 numbers row by row (default MacNeal-Harder's)."};
  Data<Vec3d> d_translation{
      this, "translation", Vec3d::Zero(), "Patch: displacement at X = 0.", {.unit = "length"}};
  Data<double> d_radius{
      this, "radius", 0.1, "Torsion: cylinder radius.", {.unit = "length", .min = 0.0}};
  Data<double> d_torque{
      this, "torque", 0.0, "Torsion: torque at the free end, about axis.", {.unit = "N length"}};
  Data<double> d_innerRadius{
      this, "innerRadius", 1.0, "Lame: inner radius.", {.unit = "length", .min = 0.0}};
  Data<double> d_outerRadius{
      this, "outerRadius", 2.0, "Lame: outer radius.", {.unit = "length", .min = 0.0}};
  Data<double> d_pressure{this, "pressure", 0.0, "Lame: internal pressure.", {.unit = "Pa"}};

  // Outputs: the latest comparison.
  Data<double> d_maxError{this,
                          "maxError",
                          0.0,
                          "Largest point error / referenceLength (NaN before a comparison).",
                          {.allowNonFinite = true, .output = true}};
  Data<double> d_rmsError{this,
                          "rmsError",
                          0.0,
                          "RMS point error / referenceLength.",
                          {.allowNonFinite = true, .output = true}};
  Data<double> d_meanError{this,
                           "meanError",
                           0.0,
                           "Mean point error / referenceLength (the Truth Cube's 'mean bead "
                           "error').",
                           {.allowNonFinite = true, .output = true}};
  Data<double> d_maxErrorAbsolute{this,
                                  "maxErrorAbsolute",
                                  0.0,
                                  "Largest point error.",
                                  {.unit = "length", .allowNonFinite = true, .output = true}};
  Data<double> d_rmsErrorAbsolute{this,
                                  "rmsErrorAbsolute",
                                  0.0,
                                  "RMS point error.",
                                  {.unit = "length", .allowNonFinite = true, .output = true}};
  Data<double> d_meanErrorAbsolute{this,
                                   "meanErrorAbsolute",
                                   0.0,
                                   "Mean point error.",
                                   {.unit = "length", .allowNonFinite = true, .output = true}};
  Data<double> d_comparedTime{this,
                              "comparedTime",
                              0.0,
                              "Simulated time of that comparison.",
                              {.unit = "s", .allowNonFinite = true, .output = true}};
  Data<int> d_worstIndex{this,
                         "worstIndex",
                         -1,
                         "Point (or marker) of the largest error; -1 before a comparison.",
                         {.output = true}};

  ReferenceComparison();
  void init() override;
  void bwdInit() override;
  void reinit() override {
    init();
    bwdInit();
  }
  void updatePosition(double dt) override;
  std::vector<std::string> runSummaryLines() const override;

 protected:
  void doUpdate() override;

 private:
  struct Comparison {
    double time, maxAbsolute, rmsAbsolute, meanAbsolute;
    int worst;
  };
  bool checkParameters();
  bool prepareAnalytic(const State::VecCoord& rest);
  bool prepareStateFile(const State::VecCoord& rest);
  bool prepareMarkers(const State::VecCoord& rest);
  /// `indices` checked against `count` (what they index, for the message), or all of them.
  bool selectIndices(std::size_t count, const std::string& what, std::vector<unsigned>& selected);
  bool locateInMesh(const State::VecCoord& rest, const std::vector<Vec3d>& points,
                    const std::string& field);
  /// Reference target of reference point k at time t (state-file references may change).
  bool updateTargets(double time);
  void compareNow(double time);
  void publish(const Comparison& c);

  bool m_checked = false;          ///< init found the parameters usable
  std::size_t m_requiredSize = 0;  ///< state points the comparison reads
  bool m_sizeWarned = false;
  bool m_ready = false;
  /// Reference points: the state point each compares with (by index), or its location.
  std::vector<unsigned> m_pointIndex;
  std::vector<unsigned> m_reportIndex;  ///< how outputs name each point (state, file or marker)
  std::vector<barycentric::EmbeddedPoint> m_location;
  std::vector<Vec3d> m_rest;               ///< rest position of each reference point
  std::vector<Vec3d> m_target;             ///< its reference position
  std::vector<StateSnapshot> m_snapshots;  ///< referenceState, whole
  bool m_deflectionOnly = false;           ///< beams: error along loadDirection only
  std::vector<double> m_targetDeflection;  ///< beams: w at each reference point
  std::vector<bool> m_done;                ///< per time of `times`
  std::vector<Comparison> m_history;
};

}  // namespace stroma
