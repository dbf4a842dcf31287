// SPDX-License-Identifier: MIT
#include "CGImplicitSolver.h"

#include <string>

namespace stroma {

namespace {

// Reports the messages of an owned object (not in the graph, so logging to a log of its own)
// as messages of its owner, with what the owned part is.
class ForwardToOwner final : public MessageSink {
 public:
  ForwardToOwner(Base& owner, std::string part) : m_owner(owner), m_part(std::move(part)) {}
  void receive(const Message& m) override {
    std::string text = m_part + ": " + m.text;
    switch (m.level) {
      case MessageLevel::info:
        m_owner.msgInfo(std::move(text), m.field);
        break;
      case MessageLevel::warning:
        if (m.failsRun)
          m_owner.msgRunFailure(std::move(text), m.field);
        else
          m_owner.msgWarning(std::move(text), m.field);
        break;
      case MessageLevel::error:
        m_owner.msgError(std::move(text), m.field);
        break;
    }
  }

 private:
  Base& m_owner;
  std::string m_part;
};

void follow(BaseData& owned, BaseData& mine) {
  std::string error;
  owned.setParent(&mine, error);  // same types: cannot fail
}

}  // namespace

CGImplicitSolver::CGImplicitSolver() {
  m_euler.setClassName("EulerImplicitSolver");
  m_cg.setClassName("CGLinearSolver", "GraphScattered");
  m_euler.messageLog().addSink(std::make_shared<ForwardToOwner>(*this, "its implicit Euler step"));
  m_cg.messageLog().addSink(std::make_shared<ForwardToOwner>(*this, "its conjugate gradient"));
  follow(m_cg.d_iterations, d_iterations);
  follow(m_cg.d_tolerance, d_tolerance);
  follow(m_cg.d_threshold, d_threshold);
  follow(m_cg.d_verbose, d_verbose);
  follow(m_euler.d_rayleighStiffness, d_rayleighStiffness);
  follow(m_euler.d_rayleighMass, d_rayleighMass);
  follow(m_euler.d_vdamping, d_vdamping);
}

void CGImplicitSolver::init() {
  m_euler.setName(name());
  m_cg.setName(name());
  follow(m_euler.d_printLog, d_printLog);
  m_cg.init();
  m_euler.l_linearSolver.set(&m_cg);  // its own CG, not the node's linear solver
  m_euler.init();
}

void CGImplicitSolver::solve(MechanicalOperations& mop, double dt) { m_euler.solve(mop, dt); }

bool CGImplicitSolver::constraintResponse(double dt, ConstraintResponse& response) const {
  return m_euler.constraintResponse(dt, response);
}

void CGImplicitSolver::cleanup() {
  m_cg.cleanup();
  m_euler.cleanup();
}

}  // namespace stroma
