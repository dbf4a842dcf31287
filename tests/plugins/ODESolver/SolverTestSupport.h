// SPDX-License-Identifier: MIT
// Scenes for the solver tests: a Runtime with the test force fields, a loaded scene, and
// access to the state and the energies of a node.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <sstream>
#include <string>

#include "TestSprings.h"
#include "core/Runtime.h"
#include "plugins/TestPlugin/TestSupport.h"
#include "simulation/MechanicalOperations.h"
#include "simulation/MechanicalState.h"
#include "simulation/Scene.h"

namespace stroma::test {

/// A scene loaded from XML with the test force fields available. The bodies are in child
/// nodes of the root; body(name) finds one.
class SolverScene {
 public:
  explicit SolverScene(const std::string& xml) : m_scene(std::make_unique<Scene>(m_runtime)) {
    registerTestSprings(m_runtime.factory());
    m_loaded = m_scene->loadString(xml);
  }

  bool loaded() const { return m_loaded; }
  Scene& scene() { return *m_scene; }
  std::string log() { return describe(m_scene->log()); }
  bool step(double dt = 0) { return m_scene->step(dt); }

  Node& body(const std::string& name = "Body") {
    Node* node = m_scene->root().findChild(name);
    EXPECT_NE(node, nullptr) << "no node " << name;
    return node ? *node : m_scene->root();
  }
  MechanicalState<Vec3Types>& state(const std::string& name = "Body") {
    auto* s = body(name).get<MechanicalState<Vec3Types>>();
    EXPECT_NE(s, nullptr);
    return *s;
  }
  const Vec3d& position(std::size_t i, const std::string& name = "Body") {
    return state(name).readCoord(VecId::position())[i];
  }
  const Vec3d& velocity(std::size_t i, const std::string& name = "Body") {
    return state(name).readDeriv(VecId::velocity())[i];
  }
  /// Kinetic plus potential energy of a node's system.
  double energy(const std::string& name = "Body") {
    MechanicalOperations mop(body(name), m_scene->timing());
    return mop.kineticEnergy() + mop.potentialEnergy(MechanicalParams{});
  }
  /// The value of an object's field, as text.
  std::string field(const std::string& object, const std::string& fieldName,
                    const std::string& name = "Body") {
    Base* o = body(name).findObject(object);
    if (!o) return "(no object " + object + ")";
    BaseData* d = o->findData(fieldName);
    return d ? d->valueText() : "(no field " + fieldName + ")";
  }

 private:
  Runtime m_runtime;  // declared first: outlives the scene
  std::unique_ptr<Scene> m_scene;
  bool m_loaded = false;
};

/// Points of mass m (one per three numbers of x0) on anchor springs k per axis to the origin (a
/// harmonic oscillator of omega = sqrt(k / m) on each axis), starting at x0 with velocity v0, no
/// gravity. `solvers` is the XML of the solver components.
inline std::string oscillatorScene(const std::string& solvers, double k, double m,
                                   const std::string& x0 = "1 0 0", const std::string& v0 = "0 0 0",
                                   double dt = 0.01, const std::string& extra = "") {
  // Every point is anchored at the origin.
  std::istringstream numbers(x0);
  std::string rest, token;
  while (numbers >> token) rest += "0 ";
  std::ostringstream xml;
  xml.precision(17);
  xml << "<Node name=\"root\" dt=\"" << dt << "\" gravity=\"0 0 0\">\n"
      << "  <Node name=\"Body\">\n    " << solvers << "\n"
      << "    <MechanicalObject name=\"dofs\" position=\"" << x0 << "\" rest_position=\"" << rest
      << "\""
      << " velocity=\"" << v0 << "\"/>\n"
      << "    <UniformMass name=\"mass\" vertexMass=\"" << m << "\"/>\n"
      << "    <TestAnchorForceField name=\"spring\" stiffness=\"" << k << " " << k << " " << k
      << "\"/>\n    " << extra << "\n  </Node>\n</Node>\n";
  return xml.str();
}

}  // namespace stroma::test
