// SPDX-License-Identifier: MIT
// The "did you mean" of every unknown-name error: edit distance, and the choice and order of
// the nearest names.
#include "core/NameSuggestions.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace stroma {
namespace {

using Names = std::vector<std::string>;

TEST(EditDistance, CountsInsertionsDeletionsAndSubstitutions) {
  EXPECT_EQ(editDistance("kitten", "sitting"), 3u);
  EXPECT_EQ(editDistance("flaw", "lawn"), 2u);
  EXPECT_EQ(editDistance("abc", "abc"), 0u);
  EXPECT_EQ(editDistance("", "abc"), 3u);
  EXPECT_EQ(editDistance("abc", ""), 3u);
  EXPECT_EQ(editDistance("", ""), 0u);
  EXPECT_EQ(editDistance("dofs", "dosf"), 2u);  // a transposition is two substitutions
  EXPECT_EQ(editDistance("MechanicalObjet", "MechanicalObject"), 1u);
}

TEST(EditDistance, IgnoresCaseAndIsSymmetric) {
  EXPECT_EQ(editDistance("YoungModulus", "youngmodulus"), 0u);
  EXPECT_EQ(editDistance("ABC", "abd"), 1u);
  for (const auto& [a, b] : std::vector<std::pair<std::string, std::string>>{
           {"kitten", "sitting"}, {"", "xyz"}, {"Tetra", "tetrahedron"}, {"ab", "ba"}}) {
    EXPECT_EQ(editDistance(a, b), editDistance(b, a)) << a << " / " << b;
  }
}

TEST(NearestNames, BestFirstThenAlphabetical) {
  const Names candidates{"TetrahedronFEMForceField", "TetrahedronSetTopologyContainer",
                         "HexahedronFEMForceField", "Tetrahedra", "MeshTopology"};
  // 'Tetrahedra' is 2 edits away; the two that contain the name count as a third of its length.
  EXPECT_EQ(nearestNames("Tetrahedron", candidates),
            (Names{"Tetrahedra", "TetrahedronFEMForceField", "TetrahedronSetTopologyContainer"}));
  EXPECT_EQ(nearestNames("abc", {"abd", "xbc", "abcd", "zzz", "ab", "a"}),
            (Names{"ab", "abcd", "abd"}));
}

TEST(NearestNames, KeepsAtMostTheRequestedCount) {
  const Names candidates{"abd", "xbc", "abcd", "zzz", "ab", "a"};
  EXPECT_EQ(nearestNames("abc", candidates, 2), (Names{"ab", "abcd"}));
  EXPECT_EQ(nearestNames("abc", candidates, 1), (Names{"ab"}));
  EXPECT_TRUE(nearestNames("abc", candidates, 0).empty());
  EXPECT_EQ(nearestNames("abc", candidates, 10).size(), 5u);  // all but 'zzz'
}

TEST(NearestNames, LeavesOutFarNamesAndTheNameItself) {
  EXPECT_TRUE(nearestNames("Xyzzy", {"MechanicalObject", "Gravity"}).empty());
  EXPECT_TRUE(nearestNames("dofs", {"dofs"}).empty());
  EXPECT_TRUE(nearestNames("anything", {}).empty());
  EXPECT_EQ(nearestNames("dofs", {"dofs", "dof"}), (Names{"dof"}));
}

TEST(NearestNames, ANameDifferingOnlyByCaseComesFirst) {
  EXPECT_EQ(nearestNames("youngmodulus", {"poissonRatio", "youngModulusX", "youngModulus"}),
            (Names{"youngModulus", "youngModulusX"}));
  EXPECT_EQ(nearestNames("gravity", {"Gravity", "dt"}), (Names{"Gravity"}));
}

TEST(NearestNames, ShortNamesAllowTwoEdits) {
  EXPECT_EQ(nearestNames("dt", {"dx", "t", "gravity", "time"}), (Names{"dx", "t"}));
  EXPECT_EQ(nearestNames("stiffnes", {"stiffness", "damping", "stiff"}),
            (Names{"stiffness", "stiff"}));
}

TEST(NearestNames, ContainmentNeedsFourLetters) {
  // 'FEM' is in 'TetrahedronFEMForceField' but three letters are too few to count.
  EXPECT_TRUE(nearestNames("FEM", {"TetrahedronFEMForceField"}).empty());
  EXPECT_EQ(nearestNames("Force", {"TetrahedronFEMForceField"}),
            (Names{"TetrahedronFEMForceField"}));
  // A candidate contained in the name counts only from four letters too.
  EXPECT_EQ(nearestNames("MeshObjLoader2", {"Mesh", "Obj"}), (Names{"Mesh"}));
}

TEST(NearestNames, DuplicateCandidatesAppearOnce) {
  EXPECT_EQ(nearestNames("dosf", {"dofs", "dofs", "dofs"}), (Names{"dofs"}));
}

TEST(QuotedList, JoinsWithCommasAndOr) {
  EXPECT_EQ(quotedList({}), "");
  EXPECT_EQ(quotedList({"a"}), "'a'");
  EXPECT_EQ(quotedList({"a", "b"}), "'a' or 'b'");
  EXPECT_EQ(quotedList({"a", "b", "c"}), "'a', 'b' or 'c'");
}

}  // namespace
}  // namespace stroma
