// SPDX-License-Identifier: MIT
// Link<T>: a typed pointer to another object, registered on its owner, that refuses a target
// of the wrong type with a message naming both.
#include "core/Link.h"

#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "core/Node.h"
#include "core/PathResolver.h"

namespace stroma {

struct LinkTestState : Base {
  LinkTestState() { setClassName("LinkTestState"); }
};
struct LinkTestSolver : Base {
  LinkTestSolver() { setClassName("LinkTestSolver"); }
};
struct LinkTestDerivedState : LinkTestState {
  LinkTestDerivedState() { setClassName("LinkTestDerivedState"); }
};

struct LinkTestMapping : Base {
  Link<LinkTestState> l_input{this, "input", "State the mapping reads"};
  Link<LinkTestState> l_output{this, "output", "State the mapping writes"};
  LinkTestMapping() { setClassName("LinkTestMapping"); }
};

namespace {

template <class T>
T& addNamed(Node& node, std::string name) {
  auto object = std::make_unique<T>();
  object->setName(std::move(name));
  return static_cast<T&>(node.addObject(std::move(object)));
}

TEST(Link, IsRegisteredOnItsOwnerByName) {
  LinkTestMapping mapping;
  ASSERT_EQ(mapping.links().size(), 2u);
  EXPECT_EQ(mapping.links()[0], &mapping.l_input);
  EXPECT_EQ(mapping.findLink("output"), &mapping.l_output);
  EXPECT_EQ(mapping.findLink("nothing"), nullptr);
  EXPECT_EQ(mapping.l_input.owner(), &mapping);
  EXPECT_EQ(mapping.l_input.name(), "input");
  EXPECT_EQ(mapping.l_input.help(), "State the mapping reads");
  EXPECT_EQ(mapping.l_input.targetTypeName(), "LinkTestState");
}

TEST(Link, StartsEmpty) {
  LinkTestMapping mapping;
  EXPECT_FALSE(mapping.l_input);
  EXPECT_EQ(mapping.l_input.get(), nullptr);
  EXPECT_EQ(mapping.l_input.targetBase(), nullptr);
  EXPECT_EQ(mapping.l_input.path(), "");
}

TEST(Link, KeepsThePathWrittenInTheScene) {
  LinkTestMapping mapping;
  mapping.l_input.setPath("@../dofs");
  EXPECT_EQ(mapping.l_input.path(), "@../dofs");
}

TEST(Link, SetTargetAcceptsTheTypeAndItsSubclasses) {
  Node root;
  auto& state = addNamed<LinkTestState>(root, "dofs");
  auto& derived = addNamed<LinkTestDerivedState>(root, "rigid");
  auto& mapping = addNamed<LinkTestMapping>(root, "map");
  std::string error;
  ASSERT_TRUE(mapping.l_input.setTarget(&state, error)) << error;
  EXPECT_TRUE(mapping.l_input);
  EXPECT_EQ(mapping.l_input.get(), &state);
  EXPECT_EQ(mapping.l_input.targetBase(), &state);
  ASSERT_TRUE(mapping.l_output.setTarget(&derived, error)) << error;
  EXPECT_EQ(mapping.l_output.get(), &derived);
  EXPECT_EQ(mapping.l_output->name(), "rigid");
}

TEST(Link, SetTargetRefusesAnotherTypeAndKeepsTheOldTarget) {
  Node root;
  auto& state = addNamed<LinkTestState>(root, "dofs");
  auto& solver = addNamed<LinkTestSolver>(root, "solver");
  auto& mapping = addNamed<LinkTestMapping>(root, "map");
  std::string error;
  ASSERT_TRUE(mapping.l_input.setTarget(&state, error)) << error;
  EXPECT_FALSE(mapping.l_input.setTarget(&solver, error));
  EXPECT_EQ(error, "/root/solver is a LinkTestSolver, not a LinkTestState");
  EXPECT_EQ(mapping.l_input.get(), &state);

  EXPECT_FALSE(mapping.l_output.setTarget(&root, error));
  EXPECT_EQ(error, "/root is a Node, not a LinkTestState");
}

TEST(Link, NullTargetClearsTheLink) {
  Node root;
  auto& state = addNamed<LinkTestState>(root, "dofs");
  LinkTestMapping mapping;
  std::string error;
  ASSERT_TRUE(mapping.l_input.setTarget(&state, error));
  ASSERT_TRUE(mapping.l_input.setTarget(nullptr, error));
  EXPECT_FALSE(mapping.l_input);
  mapping.l_input.set(&state);
  EXPECT_EQ(mapping.l_input.get(), &state);
}

TEST(Link, ResolvedPathThenSetTarget) {
  // What the scene loader does with input="@../dofs".
  Node root;
  auto& state = addNamed<LinkTestState>(root, "dofs");
  Node& child = root.createChild("Child");
  auto& mapping = addNamed<LinkTestMapping>(child, "map");
  mapping.l_input.setPath("@../dofs");
  std::string error;
  Base* target = resolveObjectPath(child, mapping.l_input.path(), error);
  ASSERT_NE(target, nullptr) << error;
  ASSERT_TRUE(mapping.l_input.setTarget(target, error)) << error;
  EXPECT_EQ(mapping.l_input.get(), &state);
}

TEST(Link, TargetTypeNamesDropOnlyTheStromaNamespace) {
  EXPECT_EQ(internal::demangledName(typeid(LinkTestState).name()), "LinkTestState");
  EXPECT_EQ(internal::demangledName(typeid(Node).name()), "Node");
  EXPECT_EQ(internal::demangledName(typeid(int).name()), "int");
  EXPECT_EQ(internal::demangledName("not a mangled name"), "not a mangled name");
}

}  // namespace
}  // namespace stroma
