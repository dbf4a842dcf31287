// SPDX-License-Identifier: MIT
#pragma once

#include <type_traits>
#include <vector>

#include <Eigen/Sparse>

#include "core/Link.h"
#include "core/Node.h"
#include "simulation/MechanicalState.h"
#include "simulation/VecId.h"
#include "simulation/VisualModel.h"

namespace stroma {

/// Maps the degrees of freedom of an input state to those of an output: x_out = phi(x_in),
/// v_out = J v_in, and forces back f_in += J^T f_out. The output may be a mechanical state
/// (mapped degrees of freedom that carry forces) or a visual model, which batch runs skip.
class BaseMapping : public Base {
 public:
  virtual BaseMechanicalState* fromState() const = 0;
  /// The mechanical output, or nullptr when the output only draws.
  virtual BaseMechanicalState* toState() const = 0;

  virtual void applyPositions(VecId outX, VecId inX) = 0;
  virtual void applyVelocities(VecId outV, VecId inV) = 0;
  /// inF += J^T outF.
  virtual void applyTransposed(VecId inF, VecId outF) = 0;
  /// J, (output matrixSize) x (input matrixSize), at the current positions.
  virtual const Eigen::SparseMatrix<double>& jacobian() = 0;

  /// A visual output (OglModel, ...), or nullptr. Batch runs never map it.
  virtual Base* visualOutput() const = 0;
  /// Maps the input's current positions onto the points of a visual output; renderers only.
  /// On the first call `points` holds the output's points as the scene places them (its rest
  /// shape), from which the mapping prepares what init() prepares for a state output (the
  /// barycentric coordinates, the local coordinates in a frame...); every call then overwrites
  /// them. Returns false when there is no visual output or it cannot be mapped (the reason is
  /// reported once, as an error of the mapping).
  virtual bool applyToVisual(std::vector<Vec3d>& points) = 0;
};

template <class In, class Out>
class Mapping : public BaseMapping {
 public:
  using InState = MechanicalState<In>;
  using OutState = MechanicalState<Out>;
  using InVecCoord = std::vector<typename In::Coord>;
  using InVecDeriv = std::vector<typename In::Deriv>;
  using OutVecCoord = std::vector<typename Out::Coord>;
  using OutVecDeriv = std::vector<typename Out::Deriv>;

  // Links to Base, so that SOFA's `input="@.."` (a node: its state) resolves as in SOFA.
  Link<Base> l_input{this, "input",
                     "Input state, or the node holding it (default: the parent nodes' state)."};
  Link<Base> l_output{this, "output",
                      "Output: a state or a visual model, or the node holding it (default: "
                      "this node's state, else its visual model)."};

  /// The states, found by init().
  InState* input() const { return m_input; }
  /// The mechanical output, or nullptr when the output is a visual model.
  OutState* output() const { return m_output; }
  Base* visualOutput() const final { return m_visualOutput; }
  BaseMechanicalState* fromState() const final { return input(); }
  BaseMechanicalState* toState() const final { return output(); }

  /// Finds the input and output. Components that override init() call this first and stop
  /// when it returns false (after it reported the error).
  void init() override { findStates(); }

  bool applyToVisual(std::vector<Vec3d>& points) final {
    if constexpr (std::is_same_v<OutVecCoord, std::vector<Vec3d>>) {
      if (!m_visualOutput || !m_input || m_visualState == VisualState::failed) return false;
      if (m_visualState == VisualState::unprepared) {
        const bool ready = prepareVisual(points);
        m_visualState = ready ? VisualState::ready : VisualState::failed;
        if (!ready) return false;
      }
      apply(points, m_input->readCoord(VecId::position()));
      return true;
    } else {
      (void)points;
      return false;
    }
  }

 protected:
  /// Prepares the mapping for a visual output whose points at rest are `points`, as init()
  /// does for a state output; false (after reporting why) when it cannot. Mappings onto Vec3d
  /// points that can drive a drawn surface override it.
  virtual bool prepareVisual(const OutVecCoord& points) {
    (void)points;
    this->msgError("cannot map a visual output", "output");
    return false;
  }

  bool findStates() {
    Node* node = this->node();
    m_input = nullptr;
    m_output = nullptr;
    m_visualOutput = nullptr;
    m_visualState = VisualState::unprepared;
    Base* in = l_input.get();
    if (auto* n = dynamic_cast<Node*>(in)) in = n->template get<BaseMechanicalState>();
    if (!l_input && node && node->parent()) in = node->parent()->template getUp<InState>();
    m_input = dynamic_cast<InState*>(in);
    if (!m_input) {
      this->msgError(in ? in->path() + " is a " + in->className() + " " + in->templateName() +
                              ", not a mechanical state of template " + In::name
                        : std::string("no mechanical state of template ") + In::name +
                              (l_input ? " in " + l_input->path()
                                       : std::string(" in the parent nodes")),
                     "input");
    }
    Base* out = l_output.get();
    if (auto* n = dynamic_cast<Node*>(out)) out = outputIn(*n);
    if (!l_output && node) out = outputIn(*node);
    m_output = dynamic_cast<OutState*>(out);
    if (!m_output && dynamic_cast<VisualModel*>(out)) m_visualOutput = out;
    if (!m_output && !m_visualOutput)
      this->msgError(out ? out->path() + " is a " + out->className() + " " +
                               out->templateName() + ", not a mechanical state of template " +
                               Out::name + " nor a visual model"
                         : std::string("no output state of template ") + Out::name +
                               " nor visual model in " +
                               (l_output ? l_output->path() : std::string("this node")),
                     "output");
    return m_input && (m_output || m_visualOutput);
  }

 private:
  static Base* outputIn(const Node& node) {
    if (auto* s = node.template get<BaseMechanicalState>()) return s;
    return node.template get<VisualModel>();
  }

  enum class VisualState { unprepared, ready, failed };
  InState* m_input = nullptr;
  OutState* m_output = nullptr;
  Base* m_visualOutput = nullptr;
  VisualState m_visualState = VisualState::unprepared;

 public:
  virtual void apply(OutVecCoord& out, const InVecCoord& in) = 0;
  virtual void applyJ(OutVecDeriv& out, const InVecDeriv& in) = 0;
  virtual void applyJT(InVecDeriv& in, const OutVecDeriv& out) = 0;

  void applyPositions(VecId outX, VecId inX) final {
    if (OutState* out = output()) apply(out->writeCoord(outX), input()->readCoord(inX));
  }
  void applyVelocities(VecId outV, VecId inV) final {
    if (OutState* out = output()) applyJ(out->writeDeriv(outV), input()->readDeriv(inV));
  }
  void applyTransposed(VecId inF, VecId outF) final {
    if (OutState* out = output()) applyJT(input()->writeDeriv(inF), out->readDeriv(outF));
  }
};

}  // namespace stroma
