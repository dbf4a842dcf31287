// SPDX-License-Identifier: MIT
// TetrahedraRemover and TetrahedronSetTopologyModifier: removals listed per time, in a box and
// swept by a moving tool, each at the step when it applies; a simulation that goes on after the
// cuts; bad input (an index that does not exist, cutting everything).
#include "../../../plugins/Cutting/src/TetrahedraRemover.h"

#include <gtest/gtest.h>

#include <cmath>

#include "../../../plugins/Cutting/src/CuttingGeometry.h"
#include "../../../plugins/Topology/src/TetrahedronSetTopologyModifier.h"
#include "plugins/Spring/MechanicsTestSupport.h"
#include "topology/Topology.h"

namespace stroma::test {
namespace {

/// A beam 0.4 x 0.1 x 0.1 of 4 x 2 x 2 cubes, six tetrahedra each (96), clamped at x = 0,
/// under gravity; REMOVER is replaced by the remover's attributes.
std::string beam(const std::string& remover, const std::string& solver = "EulerImplicitSolver") {
  return R"(
<Node name="root" dt="0.01" gravity="0 -9.81 0">
  <Node name="Beam">
    <)" + solver +
         R"( name="odeSolver"/>
    <CGLinearSolver iterations="300" tolerance="1e-8" threshold="1e-30"/>
    <RegularGridTopology name="grid" min="0 -0.05 -0.05" max="0.4 0.05 0.05" n="5 3 3"/>
    <MechanicalObject name="dofs" template="Vec3" position="@grid.position"/>
    <TetrahedronSetTopologyContainer name="topology"/>
    <TetrahedronSetTopologyModifier name="modifier"/>
    <Hexa2TetraTopologicalMapping input="@grid" output="@topology"/>
    <DiagonalMass name="mass" massDensity="1000"/>
    <TetrahedronFEMForceField name="FEM" method="large" youngModulus="2e5" poissonRatio="0.45"/>
    <BoxROI name="clampedEnd" box="-0.001 -0.06 -0.06  0.001 0.06 0.06"
            position="@dofs.rest_position"/>
    <FixedConstraint indices="@clampedEnd.indices"/>
    <TetrahedraRemover name="cut" )" +
         remover + R"(/>
  </Node>
</Node>)";
}

/// A plugin component reached by path: its class is checked by name, since the plugin's type
/// information is not visible to the test.
template <class T>
T* component(SceneHolder& s, const std::string& path, const std::string& className) {
  Base* b = s.get<Base>(path);
  EXPECT_TRUE(b && b->className() == className) << path;
  return b && b->className() == className ? static_cast<T*>(b) : nullptr;
}

bool allFinite(SceneHolder& s) {
  for (double x : numbers(s.text("@Beam/dofs.position")))
    if (!std::isfinite(x)) return false;
  return true;
}

TEST(TetrahedraRemover, ListedRemovalsApplyDuringTheirStep) {
  SceneHolder s;
  ASSERT_TRUE(s.load(beam(R"(times="0.01 0.035" tetrahedra="0 1 2, 92 0")")));
  const Topology* topology = s.get<Topology>("@Beam/topology");
  ASSERT_EQ(topology->tetrahedra().size(), 96u);
  const std::vector<Tetrahedron> initial = topology->tetrahedra();
  ASSERT_TRUE(s.step());  // [0, 0.01): time 0.01 is the next step's
  EXPECT_EQ(topology->tetrahedra().size(), 96u);
  ASSERT_TRUE(s.step());  // [0.01, 0.02)
  EXPECT_EQ(topology->tetrahedra().size(), 93u);
  // SOFA's renumbering: 95 moved into 2, 94 into 1, 93 into 0.
  EXPECT_EQ(topology->tetrahedra()[0], initial[93]);
  EXPECT_EQ(topology->tetrahedra()[2], initial[95]);
  ASSERT_TRUE(s.step(2));  // [0.02, 0.04): the second group, in the numbering of that time
  EXPECT_EQ(topology->tetrahedra().size(), 91u);
  EXPECT_EQ(component<TetrahedraRemover>(s, "@Beam/cut", "TetrahedraRemover")->removedCount(), 5u);
  ASSERT_TRUE(s.step(20));
  EXPECT_TRUE(allFinite(s));
}

TEST(TetrahedraRemover, BoxRemovesTheTetrahedraWhoseBarycentreIsInside) {
  SceneHolder s;
  ASSERT_TRUE(s.load(beam(R"(box="0.2 -0.1 -0.1  0.3 0.1 0.1" startTime="0.02")")));
  const Topology* topology = s.get<Topology>("@Beam/topology");
  ASSERT_TRUE(s.step(2));
  EXPECT_EQ(topology->tetrahedra().size(), 96u);
  ASSERT_TRUE(s.step());
  // One slab of 2 x 2 cubes: 24 tetrahedra.
  EXPECT_EQ(topology->tetrahedra().size(), 72u);
  const auto x = s.get<MechanicalState<Vec3Types>>("@Beam/dofs")->readCoord(VecId::position());
  for (const Tetrahedron& t : topology->tetrahedra()) {
    const Vec3d centre = 0.25 * (x[t[0]] + x[t[1]] + x[t[2]] + x[t[3]]);
    EXPECT_FALSE(centre.x() >= 0.2 && centre.x() <= 0.3);
  }
  // The free end fell off: its points have no stiffness (one warning), the rest goes on.
  ASSERT_TRUE(s.step(30));
  EXPECT_TRUE(allFinite(s));
}

TEST(TetrahedraRemover, ToolRemovesWhatItsSweptSurfaceMeets) {
  SceneHolder s;
  // A vertical segment at x = 0.15 moving across the beam in z (from outside to the middle).
  // No solver: the points stay where the tool met them.
  std::string scene = beam(R"(toolStart="0.15 -0.2 -0.1  0.15 0.2 -0.1" )"
                           R"(toolEnd="0.15 -0.2 0.0  0.15 0.2 0.0" startTime="0" endTime="0.1")");
  scene.replace(scene.find("<EulerImplicitSolver"), std::string("<EulerImplicitSolver").size(),
                "<Node name=\"noSolver\"/><!--");
  scene.replace(scene.find("name=\"odeSolver\"/>"), std::string("name=\"odeSolver\"/>").size(),
                "-->");
  ASSERT_TRUE(s.load(scene));
  const Topology* topology = s.get<Topology>("@Beam/topology");
  auto* cut = component<TetrahedraRemover>(s, "@Beam/cut", "TetrahedraRemover");
  ASSERT_TRUE(cut);
  ASSERT_TRUE(s.step(4));  // the tool is still outside (z = -0.06)
  EXPECT_EQ(cut->removedCount(), 0u);
  ASSERT_TRUE(s.step(3));
  const std::size_t halfway = cut->removedCount();
  EXPECT_GT(halfway, 0u);
  ASSERT_TRUE(s.step(8));
  EXPECT_GT(cut->removedCount(), halfway);
  EXPECT_EQ(topology->tetrahedra().size(), 96u - cut->removedCount());
  // No remaining tetrahedron meets the tool where it stopped; the beam is not cut through.
  const auto x = s.get<MechanicalState<Vec3Types>>("@Beam/dofs")->readCoord(VecId::position());
  for (const Tetrahedron& t : topology->tetrahedra())
    EXPECT_FALSE(cutting::segmentMeetsTetrahedron(Vec3d(0.15, -0.2, 0), Vec3d(0.15, 0.2, 0),
                                                  {x[t[0]], x[t[1]], x[t[2]], x[t[3]]}));
  EXPECT_LT(cut->removedCount(), 24u);
}

TEST(TetrahedraRemover, ExplicitSimulationGoesOnAfterTheCuts) {
  SceneHolder s;
  ASSERT_TRUE(s.load(
      beam(R"(times="0.02 0.05" tetrahedra="10 11 12 13, 40 41 42")", "EulerExplicitSolver")));
  // dt = 1e-2 is above the explicit limit of this beam: step with 1e-4.
  for (int i = 0; i < 1000; ++i) ASSERT_TRUE(s.scene().step(1e-4)) << describe(s.scene().log());
  s.expectNoWarning();
  EXPECT_EQ(s.get<Topology>("@Beam/topology")->tetrahedra().size(), 89u);
  EXPECT_TRUE(allFinite(s));
}

TEST(TetrahedraRemover, AnIndexThatDoesNotExist) {
  {
    SceneHolder s;
    s.loadFailing(beam(R"(times="0.1" tetrahedra="3 96")"),
                  {"tetrahedron 96 (group 0, time 0.1", "has 96 tetrahedra"});
  }
  {
    // Valid at init, gone by its time: an error at that step, nothing removed, no crash.
    SceneHolder s;
    ASSERT_TRUE(s.load(beam(R"(times="0 0.01" tetrahedra="0-9, 90")")));
    ASSERT_TRUE(s.scene().step());
    EXPECT_FALSE(s.scene().step());
    bool found = false;
    for (const Message& m : s.scene().log().messages())
      found |= m.level == MessageLevel::error && m.field == "tetrahedra" &&
               m.text.find("tetrahedron 90 does not exist (there are 86") != std::string::npos;
    EXPECT_TRUE(found) << describe(s.scene().log());
    EXPECT_EQ(s.get<Topology>("@Beam/topology")->tetrahedra().size(), 86u);
  }
  {
    SceneHolder s;
    s.loadFailing(beam(R"(times="0.1 0.2" tetrahedra="3")"), {"1 groups of tetrahedra for 2"});
  }
  {
    SceneHolder s;
    s.loadFailing(beam(R"(times="0.1" tetrahedra="3 x")"), {"got 'x'"});
  }
  {
    // Through the modifier, from C++.
    SceneHolder s;
    ASSERT_TRUE(s.load(beam("")));
    auto* modifier = component<TetrahedronSetTopologyModifier>(s, "@Beam/modifier",
                                                               "TetrahedronSetTopologyModifier");
    ASSERT_TRUE(modifier);
    const std::vector<Index> bad{5, 1000};
    EXPECT_FALSE(modifier->removeTetrahedra(bad));
    const std::vector<Message> messages = s.scene().log().messages();
    ASSERT_FALSE(messages.empty());
    const Message& m = messages.back();
    EXPECT_EQ(m.field, "tetrahedra");
    EXPECT_NE(m.text.find("tetrahedron 1000 does not exist"), std::string::npos) << m.text;
    EXPECT_NE(m.text.find("/Beam/topology"), std::string::npos) << m.text;
    EXPECT_EQ(s.get<Topology>("@Beam/topology")->tetrahedra().size(), 96u);
  }
}

TEST(TetrahedraRemover, CuttingAPartAwayFreesItsPointsWithOneWarning) {
  SceneHolder s;
  // The last cubes along x (barycentres beyond x = 0.3): the points at x = 0.4 lose every
  // tetrahedron.
  ASSERT_TRUE(s.load(beam(R"(box="0.3 -1 -1  1 1 1" startTime="0.02")")));
  ASSERT_TRUE(s.step(2));
  ASSERT_TRUE(s.scene().step()) << describe(s.scene().log());
  const Topology* topology = s.get<Topology>("@Beam/topology");
  EXPECT_EQ(topology->tetrahedra().size(), 72u);
  for (int i = 0; i < 20; ++i) ASSERT_TRUE(s.scene().step()) << describe(s.scene().log());
  std::size_t warnings = 0;
  for (const Message& m : s.scene().log().messages())
    if (m.level == MessageLevel::warning) {
      ++warnings;
      EXPECT_NE(m.text.find("9 points belong to no tetrahedron anymore"), std::string::npos)
          << m.text;
    }
  EXPECT_EQ(warnings, 1u);
  EXPECT_TRUE(allFinite(s));
  // The points keep their number.
  EXPECT_EQ(numbers(s.text("@Beam/dofs.position")).size(), 45u * 3);
}

TEST(TetrahedraRemover, CuttingEverythingFreesThePointsWithOneWarning) {
  SceneHolder s;
  ASSERT_TRUE(s.load(beam(R"(box="-1 -1 -1  1 1 1" startTime="0.02")")));
  ASSERT_TRUE(s.step(2));
  ASSERT_TRUE(s.scene().step()) << describe(s.scene().log());
  const Topology* topology = s.get<Topology>("@Beam/topology");
  EXPECT_TRUE(topology->tetrahedra().empty());
  EXPECT_TRUE(topology->triangles().empty());
  EXPECT_TRUE(topology->edges().empty());
  // Nothing holds the points anymore (no mass, no stiffness): they keep their velocity.
  for (int i = 0; i < 20; ++i) ASSERT_TRUE(s.scene().step()) << describe(s.scene().log());
  std::size_t warnings = 0;
  for (const Message& m : s.scene().log().messages())
    if (m.level == MessageLevel::warning) {
      ++warnings;
      EXPECT_NE(m.text.find("45 points belong to no tetrahedron anymore"), std::string::npos)
          << m.text;
    }
  EXPECT_EQ(warnings, 1u);
  EXPECT_TRUE(allFinite(s));
}

}  // namespace
}  // namespace stroma::test
