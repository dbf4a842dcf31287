// SPDX-License-Identifier: MIT
// TopologicalChangeProcessor: a SOFA change file removes tetrahedra at its times, leaving
// exactly the expected elements (SOFA's renumbering); the mass drops by the removed elements'
// mass and the cut body's forces equal a rebuild's; triangles of a surface likewise; the Data
// inputs; SOFA's short index lines; malformed files and unsupported commands are errors naming
// the file and the line.
#include "../../../plugins/Cutting/src/TopologicalChangeProcessor.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

#include "plugins/Spring/MechanicsTestSupport.h"
#include "topology/MeshGeometry.h"
#include "topology/Topology.h"

namespace stroma::test {
namespace {

/// A beam 0.4 x 0.1 x 0.1 of 4 x 2 x 2 cubes, six tetrahedra each (96), clamped at x = 0,
/// under gravity, with a TopologicalChangeProcessor given PROCESSOR's attributes.
std::string beam(const std::string& processor) {
  return R"(
<Node name="root" dt="0.01" gravity="0 -9.81 0">
  <Node name="Beam">
    <EulerImplicitSolver name="odeSolver"/>
    <CGLinearSolver iterations="300" tolerance="1e-8" threshold="1e-30"/>
    <RegularGridTopology name="grid" min="0 -0.05 -0.05" max="0.4 0.05 0.05" n="5 3 3"/>
    <MechanicalObject name="dofs" template="Vec3" position="@grid.position"/>
    <TetrahedronSetTopologyContainer name="topology"/>
    <TetrahedronSetTopologyModifier name="modifier"/>
    <Hexa2TetraTopologicalMapping input="@grid" output="@topology"/>
    <DiagonalMass name="mass" massDensity="1000" topology="@topology"/>
    <TetrahedronFEMForceField name="FEM" method="large" youngModulus="2e5" poissonRatio="0.45"/>
    <BoxROI name="clampedEnd" box="-0.001 -0.06 -0.06  0.001 0.06 0.06"
            position="@dofs.rest_position"/>
    <FixedConstraint indices="@clampedEnd.indices"/>
    <TopologicalChangeProcessor name="changes" )" +
         processor + R"(/>
  </Node>
</Node>)";
}

std::string fileAttribute(const std::filesystem::path& file) {
  return "filename=\"" + file.string() + "\"";
}

/// The beam's mass: the sum of the entries of its mass matrix over the 3 directions.
double totalMass(SceneHolder& s) {
  ForceFieldChecker checker(s.scene(), *s.root().findChild("Beam"));
  return checker.matrixFreeMass().sum() / 3;
}

/// The same beam built from scratch with the given tetrahedra (the grid's points), no changes.
std::string rebuiltBeam(const std::string& tetrahedra) {
  std::string xml = beam("");
  const std::string container = R"(<TetrahedronSetTopologyContainer name="topology"/>)";
  xml.replace(xml.find(container), container.size(),
              R"(<TetrahedronSetTopologyContainer name="topology" position="@grid.position" )"
              R"(tetrahedra=")" +
                  tetrahedra + R"("/>)");
  const std::string mapping = R"(<Hexa2TetraTopologicalMapping input="@grid" output="@topology"/>)";
  xml.erase(xml.find(mapping), mapping.size());
  xml.erase(xml.find("<TopologicalChangeProcessor"),
            xml.find("/>", xml.find("<TopologicalChangeProcessor")) + 2 -
                xml.find("<TopologicalChangeProcessor"));
  return xml;
}

double volume(const std::vector<Vec3d>& x, const Tetrahedron& t) {
  return std::abs(signedVolume(x, t));
}

/// The processor, reached by path: its class is checked by name, since the plugin's type
/// information is not visible to the test.
TopologicalChangeProcessor* processor(SceneHolder& s) {
  Base* b = s.get<Base>("@Beam/changes");
  EXPECT_TRUE(b && b->className() == "TopologicalChangeProcessor");
  return b && b->className() == "TopologicalChangeProcessor"
             ? static_cast<TopologicalChangeProcessor*>(b)
             : nullptr;
}

TEST(TopologicalChangeProcessor, RemovesTheListedTetrahedraAtTheirTimes) {
  TempDir dir;
  // SOFA's layout: indented commands, a trailing space after a time, blank lines.
  const auto file = dir.write("changes.txt",
                              "T= 0.01 \n"
                              "  REMOVE= 3\n"
                              "0 1 2\n"
                              "\n"
                              "T= 0.035\n"
                              "  REMOVE= 2\n"
                              "92 0\n");
  SceneHolder s;
  ASSERT_TRUE(s.load(beam(fileAttribute(file))));
  const Topology* topology = s.get<Topology>("@Beam/topology");
  ASSERT_EQ(topology->tetrahedra().size(), 96u);
  const std::vector<Tetrahedron> initial = topology->tetrahedra();
  const std::vector<Vec3d> rest =
      s.get<MechanicalState<Vec3Types>>("@Beam/dofs")->readCoord(VecId::restPosition());
  const double mass0 = totalMass(s);
  EXPECT_NEAR(mass0, 1000 * 0.4 * 0.1 * 0.1, 1e-12);

  ASSERT_TRUE(s.step());  // [0, 0.01): time 0.01 is the next step's
  EXPECT_EQ(topology->tetrahedra().size(), 96u);
  ASSERT_TRUE(s.step());  // [0.01, 0.02)
  ASSERT_EQ(topology->tetrahedra().size(), 93u);
  // SOFA's renumbering: 95 moved into 2, 94 into 1, 93 into 0; the others stay.
  std::vector<Tetrahedron> expected = initial;
  for (Index r : {2, 1, 0}) {
    expected[r] = expected.back();
    expected.pop_back();
  }
  EXPECT_EQ(topology->tetrahedra(), expected);
  // The mass drops by exactly the removed tetrahedra's mass.
  const double removed1 =
      1000 * (volume(rest, initial[0]) + volume(rest, initial[1]) + volume(rest, initial[2]));
  EXPECT_NEAR(totalMass(s), mass0 - removed1, 1e-12 * mass0);

  ASSERT_TRUE(s.step(2));  // [0.02, 0.04): the second block, in the numbering of that time
  for (Index r : {92, 0}) {
    expected[r] = expected.back();
    expected.pop_back();
  }
  EXPECT_EQ(topology->tetrahedra(), expected);
  const double removed2 = 1000 * (volume(rest, initial[92]) + volume(rest, initial[95]));
  EXPECT_NEAR(totalMass(s), mass0 - removed1 - removed2, 1e-12 * mass0);
  EXPECT_EQ(processor(s)->removedCount(), 5u);

  // The cut body goes on; at its deformed positions its forces and stiffness are those of the
  // same mesh built from scratch, and its matrix-free and assembled stiffness agree.
  ASSERT_TRUE(s.step(10));
  SceneHolder rebuilt;
  ASSERT_TRUE(rebuilt.load(rebuiltBeam(s.text("@Beam/topology.tetrahedra")), true));
  rebuilt.set("@Beam/dofs.position", s.text("@Beam/dofs.position"));
  ForceFieldChecker a(s.scene(), *s.root().findChild("Beam"));
  ForceFieldChecker b(rebuilt.scene(), *rebuilt.root().findChild("Beam"));
  const Eigen::VectorXd fa = a.force(), fb = b.force();
  EXPECT_GT((fa - fb).size(), 0);
  EXPECT_LT((fa - fb).cwiseAbs().maxCoeff(), 1e-12 * fb.cwiseAbs().maxCoeff());
  const Eigen::MatrixXd Ka = a.assembled(0, 0, 1), Kb = b.assembled(0, 0, 1);
  const double scale = Kb.cwiseAbs().maxCoeff();
  EXPECT_LT((Ka - Kb).cwiseAbs().maxCoeff(), 1e-12 * scale);
  EXPECT_NEAR(a.matrixFreeMass().sum(), b.matrixFreeMass().sum(), 1e-12);
}

TEST(TopologicalChangeProcessor, DataInputsRemoveAtTimeToRemove) {
  SceneHolder s;
  ASSERT_TRUE(
      s.load(beam(R"(useDataInputs="true" timeToRemove="0.02" tetrahedraToRemove="5 6 7 8")")));
  const Topology* topology = s.get<Topology>("@Beam/topology");
  ASSERT_TRUE(s.step(2));
  EXPECT_EQ(topology->tetrahedra().size(), 96u);
  ASSERT_TRUE(s.step());
  EXPECT_EQ(topology->tetrahedra().size(), 92u);
}

TEST(TopologicalChangeProcessor, ShortIndexLinesReadAsSofaReadsThem) {
  // "REMOVE= 4" over three indices: the fourth reads as 0 (SOFA's shipped files do this);
  // "REMOVE= 1" over two: the second is ignored. Each with a warning naming the line.
  TempDir dir;
  const auto file = dir.write("short.txt", "T= 0\nREMOVE= 4\n1 2 3\nT= 0.01\nREMOVE= 1\n7 8\n");
  SceneHolder s;
  ASSERT_TRUE(s.load(beam(fileAttribute(file)), true));
  std::size_t warnings = 0;
  for (const Message& m : s.scene().log().messages())
    if (m.level == MessageLevel::warning) {
      ++warnings;
      EXPECT_EQ(m.field, "filename");
      EXPECT_TRUE(
          m.text.find("short.txt:3: 'REMOVE= 4' is followed by 3 indices") != std::string::npos ||
          m.text.find("short.txt:6: 'REMOVE= 1' is followed by 2 indices") != std::string::npos)
          << m.text;
    }
  EXPECT_EQ(warnings, 2u);
  ASSERT_TRUE(processor(s));
  const auto& removals = processor(s)->removals();
  ASSERT_EQ(removals.size(), 2u);
  EXPECT_EQ(removals[0].indices, (std::vector<Index>{1, 2, 3, 0}));
  EXPECT_EQ(removals[1].indices, (std::vector<Index>{7}));
  ASSERT_TRUE(s.scene().step());
  ASSERT_TRUE(s.scene().step());
  EXPECT_EQ(s.get<Topology>("@Beam/topology")->tetrahedra().size(), 91u);
}

TEST(TopologicalChangeProcessor, MalformedFilesAreErrorsNamingFileAndLine) {
  struct Case {
    const char* text;
    std::vector<std::string_view> needles;
  };
  const std::vector<Case> cases = {
      {"T= 0.1\n  REMOVE= 2\n0 x\n", {"bad.txt:3:", "expected element indices", "'x'"}},
      {"T= soon\nREMOVE= 1\n0\n", {"bad.txt:1:", "expected a time after 'T='"}},
      {"REMOVE= 1\n0\n", {"bad.txt:1:", "before the first 'T= time'"}},
      {"T= 0.1\nREMOVE= -3\n0\n", {"bad.txt:2:", "'REMOVE= n'"}},
      {"T= 0.1\nDELETE= 1\n0\n", {"bad.txt:2:", "unknown command 'DELETE='"}},
      {"T= 0.2\nREMOVE= 1\n0\nT= 0.1\nREMOVE= 1\n0\n", {"bad.txt:4:", "times must increase"}},
      {"T= 0.1\nREMOVE= 2\n", {"bad.txt:2:", "the file ends"}},
      // Unsupported commands name themselves and the line.
      {"T= 0.1\n  ADD= Tetrahedra 1\n0 1 2 3\n", {"bad.txt:2:", "'ADD= Tetrahedra 1'"}},
      {"T= 0.1\n\tINCISE= 2\n5 6 0 6 6 0\n", {"bad.txt:2:", "'INCISE= 2'", "not supported"}},
      // An index past the tetrahedra left by the removals before it.
      {"T= 0.1\nREMOVE= 2\n0 1\nT= 0.2\nREMOVE= 1\n94\n",
       {"bad.txt:6:", "tetrahedron 94", "has 94 tetrahedra then"}},
  };
  for (const Case& c : cases) {
    TempDir dir;
    const auto file = dir.write("bad.txt", c.text);
    SceneHolder s;
    EXPECT_FALSE(s.scene().loadString(beam(fileAttribute(file)))) << c.text;
    const std::vector<Message> found = errors(s.scene().log());
    const Message* m = nullptr;
    for (const Message& e : found) {
      bool all = true;
      for (std::string_view n : c.needles) all &= e.text.find(n) != std::string::npos;
      if (all) m = &e;
    }
    ASSERT_TRUE(m) << c.text << "\n" << describe(s.scene().log());
    EXPECT_EQ(m->field, "filename") << c.text;
    EXPECT_EQ(s.get<Topology>("@Beam/topology")->tetrahedra().size(), 96u);
  }
  {
    SceneHolder s;
    s.loadFailing(beam(R"(filename="no-such-changes.txt")"), {"no-such-changes.txt"});
  }
  {
    // A kind Stroma cannot remove yet.
    SceneHolder s;
    const Message m =
        s.loadFailing(beam(R"(useDataInputs="true" timeToRemove="0.1" hexahedraToRemove="0")"),
                      {"hexahedraToRemove is not supported"});
    EXPECT_EQ(m.field, "hexahedraToRemove");
  }
}

/// A 0.4 x 0.1 sheet of 4 x 1 squares, two triangles each (8), in a TriangleSetTopologyContainer
/// with its edges, pinned at x = 0, with a membrane and a lumped mass of 2 kg/m^2.
std::string sheet(const std::string& processor) {
  return R"(
<Node name="root" dt="0.01" gravity="0 0 -9.81">
  <Node name="Sheet">
    <EulerImplicitSolver/>
    <CGLinearSolver iterations="200" tolerance="1e-10" threshold="1e-30"/>
    <MechanicalObject name="dofs" template="Vec3"
        position="0 0 0  0.1 0 0  0.2 0 0  0.3 0 0  0.4 0 0
                  0 0.1 0  0.1 0.1 0  0.2 0.1 0  0.3 0.1 0  0.4 0.1 0"/>
    <TriangleSetTopologyContainer name="topology"
        triangles="0 1 6  0 6 5  1 2 7  1 7 6  2 3 8  2 8 7  3 4 9  3 9 8"
        edges="0 1  1 2  2 3  3 4  5 6  6 7  7 8  8 9  0 5  1 6  2 7  3 8  4 9  0 6  1 7  2 8  3 9"/>
    <TriangleSetTopologyModifier/>
    <DiagonalMass name="mass" massDensity="2"/>
    <TriangularFEMForceField name="FEM" youngModulus="1e4" poissonRatio="0.3" method="large"/>
    <FixedConstraint indices="0 5"/>
    <TopologicalChangeProcessor name="changes" )" +
         processor + R"(/>
  </Node>
</Node>)";
}

TEST(TopologicalChangeProcessor, RemovesTrianglesOfASurfaceAndTheirUnusedEdges) {
  TempDir dir;
  // The last square (triangles 6 and 7) at 0.02: the points 4 and 9 are left without triangles.
  const auto file = dir.write("triangles.txt", "T= 0.02\n  REMOVE= 2\n6 7\n");
  SceneHolder s;
  ASSERT_TRUE(s.load(sheet(fileAttribute(file))));
  const Topology* topology = s.get<Topology>("@Sheet/topology");
  const std::vector<Triangle> initial = topology->triangles();
  auto mass = [&] {
    ForceFieldChecker checker(s.scene(), *s.root().findChild("Sheet"));
    return checker.matrixFreeMass().sum() / 3;
  };
  EXPECT_NEAR(mass(), 2 * 0.4 * 0.1, 1e-14);
  ASSERT_TRUE(s.step(2));
  EXPECT_EQ(topology->triangles().size(), 8u);
  ASSERT_TRUE(s.scene().step());  // [0.02, 0.03): one warning, for the freed points
  ASSERT_EQ(topology->triangles().size(), 6u);
  EXPECT_EQ(topology->triangles(), std::vector<Triangle>(initial.begin(), initial.begin() + 6));
  // The edges 3-4, 8-9, 4-9 and the diagonal 3-9 went; 3-8 is still the side of triangle 5.
  EXPECT_EQ(topology->edges().size(), 13u);
  for (const Edge& e : topology->edges())
    for (Index v : e) EXPECT_TRUE(v != 4 && v != 9) << e[0] << " " << e[1];
  std::size_t warnings = 0;
  for (const Message& m : s.scene().log().messages())
    if (m.level == MessageLevel::warning) {
      ++warnings;
      EXPECT_NE(m.text.find("2 points belong to no triangle anymore"), std::string::npos) << m.text;
    }
  EXPECT_EQ(warnings, 1u);
  // The mass drops by the last square's; the membrane goes on without it.
  EXPECT_NEAR(mass(), 2 * 0.3 * 0.1, 1e-14);
  for (int i = 0; i < 20; ++i) ASSERT_TRUE(s.scene().step()) << describe(s.scene().log());
  for (double x : numbers(s.text("@Sheet/dofs.position"))) EXPECT_TRUE(std::isfinite(x));
}

TEST(TopologicalChangeProcessor, TriangleDataInputsAndKindMismatch) {
  {
    SceneHolder s;
    ASSERT_TRUE(
        s.load(sheet(R"(useDataInputs="true" timeToRemove="0" trianglesToRemove="0 1")"), true));
    ASSERT_TRUE(s.scene().step());
    EXPECT_EQ(s.get<Topology>("@Sheet/topology")->triangles().size(), 6u);
  }
  {
    SceneHolder s;
    const Message m =
        s.loadFailing(sheet(R"(useDataInputs="true" timeToRemove="0" tetrahedraToRemove="0")"),
                      {"/root/Sheet/topology", "removes its triangles", "give trianglesToRemove"});
    EXPECT_EQ(m.field, "tetrahedraToRemove");
  }
  {
    TempDir dir;
    const auto file = dir.write("triangles.txt", "T= 0.1\n  REMOVE= 1\n8\n");
    SceneHolder s;
    s.loadFailing(sheet(fileAttribute(file)),
                  {"triangles.txt:3:", "triangle 8", "has 8 triangles then"});
  }
}

TEST(TopologicalChangeProcessor, RemovingQuadsIsAnErrorNamingTheLine) {
  TempDir dir;
  const auto file = dir.write("quads.txt", "T= 0.1\n  REMOVE= 1\n0\n");
  SceneHolder s;
  s.loadFailing(
      R"(
<Node name="root" dt="0.01">
  <MechanicalObject name="dofs" position="0 0 0  1 0 0  1 1 0  0 1 0"/>
  <QuadSetTopologyContainer name="topology" quads="0 1 2 3"/>
  <TopologicalChangeProcessor )" +
          fileAttribute(file) +
          R"(/>
</Node>)",
      {"quads.txt:2:", "removes the quads of /root/topology", "only tetrahedra and triangles"});
}

}  // namespace
}  // namespace stroma::test
