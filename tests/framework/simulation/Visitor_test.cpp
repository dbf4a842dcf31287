// SPDX-License-Identifier: MIT
// traverse(): top-down calls before the children, bottom-up after them, in scene order;
// pruning and deactivated nodes.
#include "simulation/Visitor.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/Node.h"

namespace stroma {
namespace {

using Calls = std::vector<std::string>;

// Records "down X" and "up X" for every call, and prunes at the nodes it is told.
class Recorder final : public Visitor {
 public:
  explicit Recorder(std::vector<std::string> pruneAt = {}) : m_pruneAt(std::move(pruneAt)) {}
  Result processNodeTopDown(Node& node) override {
    calls.push_back("down " + node.name());
    for (const auto& name : m_pruneAt)
      if (name == node.name()) return Result::prune;
    return Result::carryOn;
  }
  void processNodeBottomUp(Node& node) override { calls.push_back("up " + node.name()); }
  std::string_view name() const override { return "recorder"; }
  Calls calls;

 private:
  std::vector<std::string> m_pruneAt;
};

// root
// |- A
// |  |- A1
// |  `- A2
// `- B
//    `- B1
class VisitorTest : public ::testing::Test {
 protected:
  VisitorTest() : a(root.createChild("A")), b(root.createChild("B")) {
    a.createChild("A1");
    a.createChild("A2");
    b.createChild("B1");
  }
  Node root{"root"};
  Node& a;
  Node& b;
};

TEST_F(VisitorTest, TopDownBeforeChildrenBottomUpAfterInSceneOrder) {
  Recorder r;
  traverse(root, r);
  EXPECT_EQ(r.calls, (Calls{"down root", "down A", "down A1", "up A1", "down A2", "up A2", "up A",
                            "down B", "down B1", "up B1", "up B", "up root"}));
  EXPECT_EQ(r.name(), "recorder");
}

TEST_F(VisitorTest, TraversesTheSubtreeOfTheGivenNodeOnly) {
  Recorder r;
  traverse(a, r);
  EXPECT_EQ(r.calls, (Calls{"down A", "down A1", "up A1", "down A2", "up A2", "up A"}));
}

TEST_F(VisitorTest, PruneSkipsTheSubtreeButNotTheBottomUpCall) {
  Recorder r({"A"});
  traverse(root, r);
  EXPECT_EQ(r.calls, (Calls{"down root", "down A", "up A", "down B", "down B1", "up B1", "up B",
                            "up root"}));
  Recorder atRoot({"root"});
  traverse(root, atRoot);
  EXPECT_EQ(atRoot.calls, (Calls{"down root", "up root"}));
  Recorder atLeaf({"A1", "B1"});
  traverse(root, atLeaf);
  EXPECT_EQ(atLeaf.calls, (Calls{"down root", "down A", "down A1", "up A1", "down A2", "up A2",
                                 "up A", "down B", "down B1", "up B1", "up B", "up root"}));
}

TEST_F(VisitorTest, DeactivatedNodesAreSkippedEntirely) {
  b.d_activated.setValue(false);
  Recorder r;
  traverse(root, r);
  EXPECT_EQ(r.calls, (Calls{"down root", "down A", "down A1", "up A1", "down A2", "up A2", "up A",
                            "up root"}));
  std::string error;
  ASSERT_TRUE(a.findChild("A2")->d_activated.read("false", error)) << error;
  r.calls.clear();
  traverse(root, r);
  EXPECT_EQ(r.calls, (Calls{"down root", "down A", "down A1", "up A1", "up A", "up root"}));
  root.d_activated.setValue(false);
  r.calls.clear();
  traverse(root, r);
  EXPECT_TRUE(r.calls.empty());
}

TEST_F(VisitorTest, DefaultCallsDoNothing) {
  struct Silent final : Visitor {
    std::string_view name() const override { return "silent"; }
  } silent;
  EXPECT_EQ(silent.processNodeTopDown(root), Visitor::Result::carryOn);
  traverse(root, silent);  // must not throw or crash
}

}  // namespace
}  // namespace stroma
