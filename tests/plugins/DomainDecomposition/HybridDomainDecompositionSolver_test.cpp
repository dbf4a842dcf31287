// SPDX-License-Identifier: MIT
// HybridDomainDecompositionSolver in scenes: the bar of seed 000 (share/mesh/bar.msh) reaches
// the single-domain static solution, a cut converts its zone and the bar follows, and bad
// input is reported with the field to change.
#include "../../../plugins/DomainDecomposition/src/HybridDomainDecompositionSolver.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "DomainDecomposition/kernels/SingleDomainReference.h"
#include "plugins/Spring/MechanicsTestSupport.h"

namespace stroma::test {
namespace {

using namespace domaindecomposition;

const std::string kBar = (std::filesystem::path(STROMA_SOURCE_DIR) / "share/mesh/bar.msh").string();

/// The bar with its z = 0 face fixed; SOLVER is the solver's extra attributes.
std::string barScene(const std::string& solver, const std::string& extra = "") {
  return R"(
<Node name="root" dt="0.02" gravity="0 0 0">
  <Node name="Bar">
    <MeshGmshLoader name="loader" filename=")" +
         kBar + R"(" />
    <TetrahedronSetTopologyContainer name="topology" src="@loader" />
    <TetrahedronSetTopologyModifier name="modifier" />
    <MechanicalObject name="dofs" template="Vec3" src="@loader" />
    <BoxROI name="base" box="-1 -1 -0.001  1 1 0.001" position="@dofs.rest_position" />
    <HybridDomainDecompositionSolver name="hybrid" youngModulus="5000" poissonRatio="0.3"
        fixedIndices="@base.indices" )" +
         solver + R"( />
    )" + extra +
         R"(
  </Node>
</Node>)";
}

const std::string kThreeZones =
    R"(zoneBoxes="-1 -1 -1 1 1 0.05  -1 -1 0.05 1 1 0.08  -1 -1 0.08 1 1 1" )"
    R"(forceIndices="189" forces="0 -0.01 0" )";

/// The single-domain solution of the scene's current mesh and the mean edge length.
Eigen::VectorXd reference(SceneHolder& s, double& edge) {
  const Topology* topology = s.get<Topology>("@Bar/topology");
  const auto& rest =
      s.get<MechanicalState<Vec3Types>>("@Bar/dofs")->readCoord(VecId::restPosition());
  ElasticProblem bar;
  bar.points.assign(rest.begin(), rest.end());
  for (const Tetrahedron& t : topology->tetrahedra())
    bar.tetrahedra.push_back({t[0], t[1], t[2], t[3]});
  bar.youngModulus = 5000;
  bar.poissonRatio = 0.3;
  for (double p : numbers(s.text("@Bar/base.indices")))
    bar.fixedNodes.push_back(static_cast<int>(p));
  Loads loads;
  loads.forceNodes = {189};
  loads.forces = {Vec3(0, -0.01, 0)};
  Eigen::VectorXd u;
  std::string error;
  EXPECT_TRUE(solveSingleDomain(bar, loads, u, error)) << error;
  edge = computeMeanEdgeLength(bar.points, bar.tetrahedra);
  return u;
}

/// The state's displacement from rest (3 n).
Eigen::VectorXd displacement(SceneHolder& s) {
  auto* state = s.get<MechanicalState<Vec3Types>>("@Bar/dofs");
  const auto& x = state->readCoord(VecId::position());
  const auto& rest = state->readCoord(VecId::restPosition());
  Eigen::VectorXd u(3 * x.size());
  for (std::size_t p = 0; p < x.size(); ++p) u.segment<3>(3 * p) = x[p] - rest[p];
  return u;
}

TEST(HybridDomainDecompositionSolver, TheBarReachesTheSingleDomainSolution) {
  SceneHolder s;
  ASSERT_TRUE(s.load(barScene(kThreeZones + R"(iterationsPerStep="100")")));
  ASSERT_TRUE(s.step(7));  // 700 iterations: 601 reach 1e-6 of the edge
  double edge = 0;
  const Eigen::VectorXd u = reference(s, edge);
  EXPECT_LT(compareDisplacements(displacement(s), u).max, 1e-6 * edge);
  EXPECT_LT(std::stod(s.text("@Bar/hybrid.interfaceResidual")), 1e-8 * edge);
  EXPECT_EQ(s.text("@Bar/hybrid.currentZoneModels"), "precomputed precomputed precomputed");
}

TEST(HybridDomainDecompositionSolver, SchurIsExactInOneIterationAndMetisZonesConverge) {
  SceneHolder s;
  ASSERT_TRUE(
      s.load(barScene(kThreeZones + R"(interfaceIteration="schur" iterationsPerStep="1")")));
  ASSERT_TRUE(s.step());
  double edge = 0;
  const Eigen::VectorXd u = reference(s, edge);
  EXPECT_LT(compareDisplacements(displacement(s), u).max, 1e-9 * edge);

  SceneHolder t;
  ASSERT_TRUE(t.load(barScene(R"(partition="metis" zoneCount="3" forceIndices="189" )"
                              R"(forces="0 -0.01 0" iterationsPerStep="500")")));
  ASSERT_TRUE(t.step(4));
  EXPECT_LT(compareDisplacements(displacement(t), u).max, 1e-6 * edge);
}

TEST(HybridDomainDecompositionSolver, ACutConvertsItsZoneAndTheBarFollows) {
  SceneHolder s;
  ASSERT_TRUE(s.load(barScene(kThreeZones + R"(iterationsPerStep="100")",
                              R"(<TetrahedraRemover name="scalpel" )"
                              R"(box="0.01 0.01 0.06  0.02 0.02 0.07" startTime="0.1" />)")));
  const int storedBefore = std::stoi(s.text("@Bar/hybrid.storedTensors"));
  ASSERT_TRUE(s.step(5));
  EXPECT_EQ(s.text("@Bar/hybrid.currentZoneModels"), "precomputed precomputed precomputed");
  ASSERT_TRUE(s.step(1));
  EXPECT_EQ(s.get<Topology>("@Bar/topology")->tetrahedra().size(), 588u);
  EXPECT_EQ(s.text("@Bar/hybrid.currentZoneModels"), "precomputed tensorMass precomputed");
  EXPECT_LT(std::stoi(s.text("@Bar/hybrid.storedTensors")), storedBefore);
  ASSERT_TRUE(s.step(10));
  double edge = 0;
  const Eigen::VectorXd u = reference(s, edge);
  EXPECT_LT(compareDisplacements(displacement(s), u).max, 1e-6 * edge);
}

TEST(HybridDomainDecompositionSolver, AnElementInNoZoneIsNamed) {
  SceneHolder s;
  const Message m = s.loadFailing(
      barScene(R"(zoneBoxes="-1 -1 -1 1 1 0.1" forceIndices="189" forces="0 -0.01 0")"),
      {"54 tetrahedra are in no zone: elements 540, 541"});
  EXPECT_EQ(m.field, "zoneBoxes");
}

/// A copy of bar.msh whose physical groups are `groupOfLayer[layer]` instead of layer + 1, and
/// the bar scene reading it.
std::string barSceneWithGroups(const std::vector<int>& groupOfLayer, const std::string& solver) {
  std::ifstream in(kBar);
  const auto temp = std::filesystem::temp_directory_path() / "stroma_bar_groups.msh";
  std::ofstream out(temp);
  bool elements = false;
  for (std::string line; std::getline(in, line);) {
    if (line == "$Elements") elements = true;
    std::istringstream fields(line);
    std::vector<long long> v;
    for (long long x; fields >> x;) v.push_back(x);
    if (elements && v.size() == 9 && v[1] == 4) {  // number, type 4, 2 tags, 4 nodes
      const int group = groupOfLayer.at(static_cast<std::size_t>(v[3] - 1));
      line = std::to_string(v[0]) + " 4 2 " + std::to_string(group) + " " + std::to_string(v[4]);
      for (int k = 5; k < 9; ++k) line += " " + std::to_string(v[k]);
    }
    out << line << '\n';
  }
  std::string scene = barScene(solver);
  scene.replace(scene.find(kBar), kBar.size(), temp.string());
  return scene;
}

TEST(HybridDomainDecompositionSolver, ZonesFromTheGroupsOfTheMeshFile) {
  // The groups of the file (MeshGmshLoader's tetrahedraPhysicalGroups) as zones: layers 1-5 in
  // group 10, 6-8 in group 20, 9-11 in group 30 make the zones of kThreeZones' boxes, in the
  // order of the group numbers, so the iterations are the same to the bit.
  const std::string loads = R"(forceIndices="189" forces="0 -0.01 0" iterationsPerStep="50" )";
  SceneHolder groups, boxes;
  ASSERT_TRUE(groups.load(barSceneWithGroups(
      {10, 10, 10, 10, 10, 20, 20, 20, 30, 30, 30},
      loads + R"(partition="groups" elementGroups="@loader.tetrahedraPhysicalGroups")")));
  ASSERT_TRUE(boxes.load(barScene(kThreeZones + R"(iterationsPerStep="50")")));
  ASSERT_TRUE(groups.step(2));
  ASSERT_TRUE(boxes.step(2));
  EXPECT_EQ(compareDisplacements(displacement(groups), displacement(boxes)).max, 0.0);
  EXPECT_EQ(groups.text("@Bar/hybrid.currentZoneModels"), "precomputed precomputed precomputed");

  // An element of no group (0) is named; a group list of the wrong size too.
  SceneHolder none;
  const Message m = none.loadFailing(
      barSceneWithGroups({1, 1, 1, 1, 1, 2, 2, 2, 0, 2, 2},
                         loads + R"(partition="groups" elementGroups="@loader.tetrahedraPhysicalGroups")"),
      {"54 tetrahedra are in no zone: elements 432, 433"});
  EXPECT_EQ(m.field, "elementGroups");
  SceneHolder wrong;
  EXPECT_EQ(wrong.loadFailing(barScene(loads + R"(partition="groups" elementGroups="1 2 3")"),
                              {"expected one group per tetrahedron", "(594), got 3"})
                .field,
            "elementGroups");
}

TEST(HybridDomainDecompositionSolver, WithoutForceIndicesTheForceFieldsLoadTheBar) {
  // A ConstantForceField on node 189 instead of forceIndices/forces: the same iterations.
  const std::string zones =
      R"(zoneBoxes="-1 -1 -1 1 1 0.05  -1 -1 0.05 1 1 0.08  -1 -1 0.08 1 1 1" )"
      R"(iterationsPerStep="50")";
  SceneHolder fields, listed;
  ASSERT_TRUE(fields.load(
      barScene(zones, R"(<ConstantForceField indices="189" forces="0 -0.01 0" />)")));
  ASSERT_TRUE(listed.load(barScene(kThreeZones + R"(iterationsPerStep="50")")));
  ASSERT_TRUE(fields.step(2));
  ASSERT_TRUE(listed.step(2));
  EXPECT_EQ(compareDisplacements(displacement(fields), displacement(listed)).max, 0.0);
  EXPECT_GT(displacement(fields).norm(), 0.0);
}

TEST(HybridDomainDecompositionSolver, NoFixedNodeAndOnlyForcesIsRefused) {
  SceneHolder s;
  std::string scene = barScene(kThreeZones);
  scene.replace(scene.find(R"(fixedIndices="@base.indices")"), 28, "");
  s.loadFailing(scene, {"zones 0, 1, 2 (connected) have no fixed node", "only forces"});
}

TEST(HybridDomainDecompositionSolver, ZoneModelsMustMatchTheZones) {
  SceneHolder s;
  EXPECT_EQ(s.loadFailing(barScene(kThreeZones + R"(zoneModels="precomputed tensorMass")"),
                          {"2 zone models for 3 zones"})
                .field,
            "zoneModels");
  SceneHolder t;
  EXPECT_EQ(t.loadFailing(barScene(kThreeZones + R"(zoneModels="precalc")"),
                          {"unknown zone model 'precalc'"})
                .field,
            "zoneModels");
}

}  // namespace
}  // namespace stroma::test
