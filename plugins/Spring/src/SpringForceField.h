// SPDX-License-Identifier: MIT
#pragma once

#include <vector>

#include "LinearSpring.h"
#include "core/StateTypes.h"
#include "simulation/ForceField.h"

namespace stroma {

/// Linear springs between the points of two states, or inside one (SOFA's SpringForceField,
/// which took over StiffSpringForceField: both names are accepted). Springs are given by
/// `spring` ("index1 index2 stiffness damping restLength" each), and/or by `indices1`,
/// `indices2` and `lengths` with the common `stiffness` and `damping`. `object1` and `object2`
/// name the two states (a state or a node holding one); without them both ends are in the
/// node's state. Forces, exact tangent stiffness and damping: SpringKernel.h.
///
/// Templated on the kind of points: Vec3d, Vec2d, Vec1d (both states of that kind).
///
/// The assembled path adds the blocks of both states, each at its own rows; a spring to a state
/// outside the assembled system (mapped from another solver's) contributes nothing there, which
/// is reported once.
template <class DataTypes>
class SpringForceField final : public BaseForceField {
 public:
  using State = MechanicalState<DataTypes>;
  static constexpr int kDimension = DataTypes::derivSize;

  Data<std::vector<LinearSpring>> d_springs{
      this,
      "spring",
      {},
      "Springs, 'index1 index2 stiffness damping restLength' each (index1 in object1, index2 in "
      "object2)."};
  Data<double> d_stiffness{this,
                           "stiffness",
                           100.0,
                           "Stiffness of the springs given by indices1/indices2.",
                           {.unit = "N/m", .min = 0.0}};
  Data<double> d_damping{this,
                         "damping",
                         5.0,
                         "Damping of the springs given by indices1/indices2.",
                         {.unit = "N s/m", .min = 0.0}};
  Data<std::vector<unsigned>> d_indices1{this,
                                         "indices1",
                                         {},
                                         "First ends of springs made with the common "
                                         "stiffness and damping (n)."};
  Data<std::vector<unsigned>> d_indices2{this, "indices2", {}, "Second ends of those springs (n)."};
  Data<std::vector<double>> d_lengths{this,
                                      "lengths",
                                      {},
                                      "Rest lengths of those springs: n values, one for all, "
                                      "or none for 0 (as SOFA).",
                                      {.unit = "m", .min = 0.0}};
  Data<FileName> d_fileSprings{this,
                               "fileSprings",
                               {},
                               "SOFA's spring files: not supported (an error when given).",
                               {.mustExist = false}};
  Data<FileName> d_filename{this, "filename", {}, "Same as fileSprings.", {.mustExist = false}};
  Data<double> d_showArrowSize{this, "showArrowSize", 0.01, "Viewers only."};
  Data<int> d_drawMode{this, "drawMode", 0, "Viewers only."};
  Link<Base> l_object1{this, "object1",
                       "State of the first ends (a mechanical state, or a node holding one); "
                       "default: the node's."};
  Link<Base> l_object2{this, "object2", "State of the second ends; default: object1's."};

  void init() override;
  void reinit() override { init(); }

  State* state1() const { return m_state1; }
  State* state2() const { return m_state2; }
  /// Every spring: `spring` then those made from indices1/indices2.
  const std::vector<LinearSpring>& springs() const;

  void accumulateForce(const MechanicalParams& mp, VecId f) override;
  void accumulateDForce(const MechanicalParams& mp, VecId df, VecId dx) override;
  void accumulateKMatrix(const MechanicalParams& mp, MatrixAccumulator& matrix,
                         const StateOffsets& offsets) override;
  double energy(const MechanicalParams& mp) const override;
  std::vector<BaseMechanicalState*> states() const override;

 private:
  State* resolveState(const Link<Base>& link);
  bool validate(const std::vector<LinearSpring>& springs, const std::string& field);

  State* m_state1 = nullptr;
  State* m_state2 = nullptr;
  mutable std::vector<LinearSpring> m_all;  ///< spring + indices-made springs
  mutable std::uint64_t m_springsVersion = ~0ull;
  std::vector<LinearSpring> m_fromIndices;
  bool m_reportedOutside = false;
};

}  // namespace stroma
