// SPDX-License-Identifier: MIT
// Node: the graph (children, objects, lookups by type and name, removal) and the context that
// children inherit (time step, gravity) or share with the root (time).
#include "core/Node.h"

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <utility>

namespace stroma {
namespace {

struct Solver : Base {};
struct ImplicitSolver : Solver {};
struct State : Base {};

template <class T>
T& addNamed(Node& node, std::string name) {
  auto object = std::make_unique<T>();
  object->setName(std::move(name));
  return static_cast<T&>(node.addObject(std::move(object)));
}

TEST(Node, NameClassAndPath) {
  Node root;
  EXPECT_EQ(root.name(), "root");
  EXPECT_EQ(root.className(), "Node");
  EXPECT_EQ(root.path(), "/root");
  Node& a = root.createChild("A");
  Node& b = a.createChild("B");
  EXPECT_EQ(b.path(), "/root/A/B");
  EXPECT_EQ(b.parent(), &a);
  EXPECT_EQ(b.node(), &a);
  EXPECT_EQ(root.parent(), nullptr);
  EXPECT_EQ(&b.root(), &root);
  EXPECT_EQ(&std::as_const(b).root(), &root);
  auto& s = addNamed<State>(b, "dofs");
  EXPECT_EQ(s.path(), "/root/A/B/dofs");
  EXPECT_EQ(s.node(), &b);
}

TEST(Node, ChildrenAndObjectsKeepSceneOrder) {
  Node root;
  root.createChild("first");
  root.addChild(std::make_unique<Node>("second"));
  addNamed<State>(root, "s1");
  addNamed<Solver>(root, "s2");
  ASSERT_EQ(root.children().size(), 2u);
  EXPECT_EQ(root.children()[0]->name(), "first");
  EXPECT_EQ(root.children()[1]->name(), "second");
  ASSERT_EQ(root.objects().size(), 2u);
  EXPECT_EQ(root.objects()[1]->name(), "s2");
  EXPECT_EQ(root.findChild("second"), root.children()[1].get());
  EXPECT_EQ(root.findChild("s1"), nullptr);  // objects are not children
  EXPECT_EQ(root.findObject("s1"), root.objects()[0].get());
  EXPECT_EQ(root.findObject("first"), nullptr);
}

TEST(Node, GetFindsObjectsByType) {
  Node root;
  auto& state = addNamed<State>(root, "dofs");
  auto& plain = addNamed<Solver>(root, "plain");
  auto& implicit = addNamed<ImplicitSolver>(root, "implicit");
  EXPECT_EQ(root.get<State>(), &state);
  EXPECT_EQ(root.get<Solver>(), &plain);  // the first one, in scene order
  EXPECT_EQ(root.get<ImplicitSolver>(), &implicit);
  EXPECT_EQ(root.getAll<Solver>(), (std::vector<Solver*>{&plain, &implicit}));
  EXPECT_TRUE(root.getAll<Node>().empty());
  Node& child = root.createChild("child");
  EXPECT_EQ(child.get<State>(), nullptr);
  EXPECT_TRUE(child.getAll<Base>().empty());
}

TEST(Node, GetUpSearchesTheNearestAncestor) {
  Node root;
  auto& rootSolver = addNamed<Solver>(root, "rootSolver");
  Node& a = root.createChild("A");
  auto& aState = addNamed<State>(a, "aState");
  Node& b = a.createChild("B");
  EXPECT_EQ(b.getUp<State>(), &aState);
  EXPECT_EQ(b.getUp<Solver>(), &rootSolver);
  EXPECT_EQ(b.getUp<ImplicitSolver>(), nullptr);
  auto& bSolver = addNamed<Solver>(b, "bSolver");
  EXPECT_EQ(b.getUp<Solver>(), &bSolver);
  EXPECT_EQ(a.getUp<Solver>(), &rootSolver);  // never downwards
}

TEST(Node, RemoveObjectDetachesIt) {
  Node root;
  auto& first = addNamed<State>(root, "first");
  auto& second = addNamed<State>(root, "second");
  std::unique_ptr<Base> removed = root.removeObject(&first);
  ASSERT_EQ(removed.get(), &first);
  EXPECT_EQ(removed->node(), nullptr);
  EXPECT_EQ(removed->path(), "/first");
  ASSERT_EQ(root.objects().size(), 1u);
  EXPECT_EQ(root.objects()[0].get(), &second);
  EXPECT_EQ(root.removeObject(&first), nullptr);  // not there any more
  State stranger;
  EXPECT_EQ(root.removeObject(&stranger), nullptr);
  EXPECT_EQ(root.objects().size(), 1u);
}

TEST(Node, RemoveChildDetachesTheSubtree) {
  Node root;
  Node& a = root.createChild("A");
  Node& b = root.createChild("B");
  auto& inA = addNamed<State>(a.createChild("A1"), "deep");
  std::unique_ptr<Node> removed = root.removeChild(&a);
  ASSERT_EQ(removed.get(), &a);
  EXPECT_EQ(removed->parent(), nullptr);
  EXPECT_EQ(&removed->root(), &a);
  EXPECT_EQ(inA.path(), "/A/A1/deep");
  ASSERT_EQ(root.children().size(), 1u);
  EXPECT_EQ(root.children()[0].get(), &b);
  EXPECT_EQ(root.removeChild(&a), nullptr);
  EXPECT_EQ(root.removeChild(&root), nullptr);
}

TEST(NodeContext, ChildInheritsTheTimeStepItDoesNotSet) {
  Node root;
  Node& a = root.createChild("A");
  Node& b = a.createChild("B");
  EXPECT_EQ(b.dt(), 0.01);  // the root's default
  root.d_dt.setValue(0.02);
  EXPECT_EQ(a.dt(), 0.02);
  EXPECT_EQ(b.dt(), 0.02);
  a.d_dt.setValue(0.005);
  EXPECT_EQ(root.dt(), 0.02);
  EXPECT_EQ(a.dt(), 0.005);
  EXPECT_EQ(b.dt(), 0.005);
  std::string error;
  ASSERT_TRUE(b.d_dt.read("0.001", error)) << error;
  EXPECT_EQ(b.dt(), 0.001);
  EXPECT_EQ(a.dt(), 0.005);
}

TEST(NodeContext, ChildInheritsTheGravityItDoesNotSet) {
  Node root;
  Node& a = root.createChild("A");
  Node& b = a.createChild("B");
  EXPECT_EQ(b.gravity(), Vec3d(0, -9.81, 0));
  root.d_gravity.setValue(Vec3d(0, 0, -10));
  EXPECT_EQ(b.gravity(), Vec3d(0, 0, -10));
  a.d_gravity.setValue(Vec3d::Zero());
  EXPECT_EQ(a.gravity(), Vec3d::Zero());
  EXPECT_EQ(b.gravity(), Vec3d::Zero());
  EXPECT_EQ(root.gravity(), Vec3d(0, 0, -10));
}

TEST(NodeContext, AChildSettingTheDefaultValueStillOverrides) {
  // "Set" means given by the scene or the code, even to the default value.
  Node root;
  Node& a = root.createChild("A");
  root.d_dt.setValue(0.1);
  a.d_dt.setValue(0.01);
  EXPECT_EQ(a.dt(), 0.01);
}

TEST(NodeContext, TimeIsKeptByTheRoot) {
  Node root;
  Node& a = root.createChild("A");
  Node& b = a.createChild("B");
  EXPECT_EQ(b.time(), 0.0);
  b.setTime(1.5);
  EXPECT_EQ(root.d_time.value(), 1.5);
  EXPECT_EQ(root.time(), 1.5);
  EXPECT_EQ(a.time(), 1.5);
  EXPECT_EQ(b.d_time.value(), 0.0);  // a child's own Data is not used
  b.d_time.setValue(7.0);
  EXPECT_EQ(b.time(), 1.5);
}

TEST(NodeContext, DtRefusesNegativeValues) {
  Node root;
  std::string error;
  EXPECT_FALSE(root.d_dt.read("-0.01", error));
  EXPECT_EQ(error, "expected a value >= 0, got -0.01");
  EXPECT_EQ(root.dt(), 0.01);
}

TEST(NodeLog, MessagesGoToTheSceneLogOfTheRoot) {
  Node root;
  MessageLog log;
  root.setMessageLog(&log);
  Node& a = root.createChild("A");
  auto& state = addNamed<State>(a, "dofs");
  state.setClassName("MechanicalObject", "Vec3d");
  state.setSourceLocation({"scene.scn", 12});
  EXPECT_EQ(a.sceneLog(), &log);
  EXPECT_EQ(&state.messageLog(), &log);
  EXPECT_EQ(&root.messageLog(), &log);
  EXPECT_EQ(&a.messageLog(), &log);
  state.msgWarning("few points", "position");
  state.msgError("no points");
  const std::vector<Message> messages = log.messages();
  ASSERT_EQ(messages.size(), 2u);
  const Message& m = messages[0];
  EXPECT_EQ(m.level, MessageLevel::warning);
  EXPECT_EQ(m.text, "few points");
  EXPECT_EQ(m.componentPath, "/root/A/dofs");
  EXPECT_EQ(m.componentClass, "MechanicalObject");
  EXPECT_EQ(m.field, "position");
  EXPECT_EQ(m.where.file, "scene.scn");
  EXPECT_EQ(m.where.line, 12);
  EXPECT_EQ(log.errorCount(), 1u);
  EXPECT_FALSE(state.isValid());
}

TEST(NodeLog, ObjectsOutsideASceneKeepTheirOwnLog) {
  State loose;
  loose.setName("loose");
  EXPECT_TRUE(loose.isValid());
  loose.msgInfo("hello");
  EXPECT_TRUE(loose.isValid());
  EXPECT_EQ(loose.messageLog().count(MessageLevel::info), 1u);
  EXPECT_EQ(loose.messageLog().messages()[0].componentPath, "/loose");

  Node root;  // no scene log set
  root.msgWarning("lonely");
  EXPECT_EQ(root.messageLog().count(MessageLevel::warning), 1u);
}

TEST(Base, DataFieldsInDeclarationOrder) {
  Node node;
  ASSERT_GE(node.dataFields().size(), 5u);
  EXPECT_EQ(node.dataFields()[0]->name(), "name");
  EXPECT_EQ(node.dataFields()[1]->name(), "printLog");
  EXPECT_EQ(node.findData("gravity"), &node.d_gravity);
  EXPECT_EQ(node.findData("dt")->typeName(), "real");
  node.setClassName("Node", "");
  EXPECT_EQ(node.templateName(), "");
}

}  // namespace
}  // namespace stroma
