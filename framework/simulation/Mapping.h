// SPDX-License-Identifier: MIT
#pragma once

#include <Eigen/Sparse>

#include "core/Link.h"
#include "core/Node.h"
#include "simulation/MechanicalState.h"
#include "simulation/VecId.h"

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

  Link<InState> l_input{this, "input", "Input state (default: the parent node's)."};
  Link<Base> l_output{this, "output",
                      "Output: a state (default: this node's) or a visual model."};

  InState* input() const { return l_input.get(); }
  OutState* output() const { return dynamic_cast<OutState*>(l_output.get()); }
  BaseMechanicalState* fromState() const final { return input(); }
  BaseMechanicalState* toState() const final { return output(); }

  /// Finds the input and output. Components that override init() call this first.
  void init() override {
    Node* node = this->node();
    if (!l_input && node && node->parent()) l_input.set(node->parent()->template getUp<InState>());
    if (!l_output && node) l_output.set(node->template get<OutState>());
    if (!l_input)
      this->msgError(std::string("no input state of template ") + In::name +
                     " in the parent nodes", "input");
    if (!l_output) this->msgError("no output state in this node", "output");
  }

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
