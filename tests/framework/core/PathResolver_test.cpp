// SPDX-License-Identifier: MIT
// Link paths, SOFA's syntax: "@name" searched upwards, relative "@../x" and "@./child/x",
// absolute "@/A/B" (with or without the root's name), Data paths "@obj.field", and the
// errors, with suggestions, for paths that lead nowhere.
#include "core/PathResolver.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "core/Node.h"

namespace stroma {
namespace {

struct Spring : Base {
  Data<double> d_stiffness{this, "stiffness", 100.0, "Stiffness", {.unit = "N/m"}};
  Data<double> d_damping{this, "damping", 0.0, "Damping"};
  explicit Spring(std::string name) {
    setName(std::move(name));
    setClassName("Spring");
  }
};

// root
// |- dofs, solver
// |- A
// |  |- dofs, spring
// |  `- B
// |     |- force
// |     `- C
// |        `- leaf
// `- Other
//    `- far
class PathResolverTest : public ::testing::Test {
 protected:
  PathResolverTest()
      : a(root.createChild("A")),
        b(a.createChild("B")),
        c(b.createChild("C")),
        other(root.createChild("Other")) {
    rootDofs = add(root, "dofs");
    add(root, "solver");
    aDofs = add(a, "dofs");
    spring = add(a, "spring");
    force = add(b, "force");
    leaf = add(c, "leaf");
    far = add(other, "far");
  }

  static Spring* add(Node& node, std::string name) {
    return static_cast<Spring*>(&node.addObject(std::make_unique<Spring>(std::move(name))));
  }

  Base* resolve(const Node& from, std::string_view path) {
    error.clear();
    Base* found = resolveObjectPath(from, path, error);
    if (found) {
      EXPECT_EQ(error, "") << path;
    }
    return found;
  }

  // The error of a path that must not resolve.
  std::string failure(const Node& from, std::string_view path) {
    error.clear();
    EXPECT_EQ(resolveObjectPath(from, path, error), nullptr) << path;
    return error;
  }

  std::string dataFailure(const Node& from, std::string_view path) {
    error.clear();
    EXPECT_EQ(resolveDataPath(from, path, error), nullptr) << path;
    return error;
  }

  Node root{"root"};
  Node& a;
  Node& b;
  Node& c;
  Node& other;
  Spring* rootDofs = nullptr;
  Spring* aDofs = nullptr;
  Spring* spring = nullptr;
  Spring* force = nullptr;
  Spring* leaf = nullptr;
  Spring* far = nullptr;
  std::string error;
};

TEST_F(PathResolverTest, GraphPathsAreAbsolute) {
  EXPECT_EQ(root.path(), "/root");
  EXPECT_EQ(c.path(), "/root/A/B/C");
  EXPECT_EQ(leaf->path(), "/root/A/B/C/leaf");
}

TEST_F(PathResolverTest, BareNameIsFoundInThisNodeFirst) {
  EXPECT_EQ(resolve(b, "@force"), force);
  EXPECT_EQ(resolve(a, "@dofs"), aDofs);
  EXPECT_EQ(resolve(root, "@dofs"), rootDofs);
  EXPECT_EQ(resolve(root, "@A"), &a);  // a child node by name
  EXPECT_EQ(resolve(b, "  @force\t"), force);
  EXPECT_EQ(resolve(b, "force"), force);  // the '@' is optional
}

TEST_F(PathResolverTest, BareNameIsThenSearchedInTheAncestors) {
  EXPECT_EQ(resolve(c, "@dofs"), aDofs);  // the nearest ancestor's, not the root's
  EXPECT_EQ(resolve(c, "@spring"), spring);
  EXPECT_EQ(resolve(c, "@solver"), root.findObject("solver"));
  EXPECT_EQ(resolve(other, "@dofs"), rootDofs);
  EXPECT_EQ(resolve(c, "@Other"), &other);
}

TEST_F(PathResolverTest, BareNameIsNotSearchedInSiblingsOrChildren) {
  EXPECT_EQ(failure(a, "@leaf"), "no object or node named 'leaf' in /root/A nor in its ancestors");
  EXPECT_THAT(
      failure(b, "@far"),
      ::testing::StartsWith("no object or node named 'far' in /root/A/B nor in its ancestors"));
}

TEST_F(PathResolverTest, RelativePaths) {
  EXPECT_EQ(resolve(b, "@../spring"), spring);
  EXPECT_EQ(resolve(b, "@../dofs"), aDofs);
  EXPECT_EQ(resolve(b, "@../../dofs"), rootDofs);
  EXPECT_EQ(resolve(b, "@./C/leaf"), leaf);
  EXPECT_EQ(resolve(b, "@./C"), &c);
  EXPECT_EQ(resolve(b, "@C/leaf"), leaf);
  EXPECT_EQ(resolve(b, "@./force"), force);
  EXPECT_EQ(resolve(b, "@.."), &a);
  EXPECT_EQ(resolve(b, "@."), &b);
  EXPECT_EQ(resolve(c, "@../../../Other/far"), far);
  EXPECT_EQ(resolve(b, "@.//C//leaf"), leaf);  // empty segments are ignored
}

TEST_F(PathResolverTest, AbsolutePathsWithOrWithoutTheRootName) {
  EXPECT_EQ(resolve(c, "@/A/B"), &b);
  EXPECT_EQ(resolve(c, "@/root/A/B"), &b);
  EXPECT_EQ(resolve(other, "@/A/B/force"), force);
  EXPECT_EQ(resolve(other, "@/root/A/B/C/leaf"), leaf);
  EXPECT_EQ(resolve(c, "@/dofs"), rootDofs);
  EXPECT_EQ(resolve(c, "@/"), &root);
  EXPECT_EQ(resolve(c, "@/root"), &root);
}

TEST_F(PathResolverTest, AbsolutePathPrefersAChildNamedLikeTheRoot) {
  Node& inner = root.createChild("root");
  Spring* w = add(inner, "w");
  EXPECT_EQ(resolve(a, "@/root/w"), w);
  EXPECT_EQ(resolve(a, "@/root"), &inner);
}

TEST_F(PathResolverTest, GoingAboveTheRootIsAnError) {
  EXPECT_EQ(failure(root, "@../spring"), "'..' goes above the root node in '../spring'");
  EXPECT_EQ(failure(b, "@../../../dofs"), "'..' goes above the root node in '../../../dofs'");
  EXPECT_EQ(failure(c, "@/.."), "'..' goes above the root node in '/..'");
}

TEST_F(PathResolverTest, EmptyPathIsAnError) {
  EXPECT_EQ(failure(b, "@"), "empty link path");
  EXPECT_EQ(failure(b, ""), "empty link path");
  EXPECT_EQ(failure(b, "  "), "empty link path");
}

TEST_F(PathResolverTest, UnknownNamesSuggestTheNearest) {
  EXPECT_EQ(failure(b, "@../dosf"),
            "no object or node named 'dosf' in /root/A; did you mean 'dofs'?");
  EXPECT_EQ(failure(root, "@/A/Bx"), "no object or node named 'Bx' in /root/A; did you mean 'B'?");
  EXPECT_EQ(failure(root, "@/Ax/B"), "no child node named 'Ax' in /root; did you mean 'A'?");
  EXPECT_EQ(failure(root, "@/Qqqq/B"), "no child node named 'Qqqq' in /root");
  EXPECT_EQ(failure(b, "@./C/lef"),
            "no object or node named 'lef' in /root/A/B/C; did you mean 'leaf'?");
  // An object is not a node: no path goes through it.
  EXPECT_EQ(failure(root, "@/A/spring/far"), "no child node named 'spring' in /root/A");
}

TEST_F(PathResolverTest, UnknownBareNameSuggestsNamesOfTheAncestorsToo) {
  EXPECT_EQ(failure(c, "@dosf"),
            "no object or node named 'dosf' in /root/A/B/C nor in its ancestors; did you mean "
            "'dofs'?");
  EXPECT_EQ(failure(b, "@forc"),
            "no object or node named 'forc' in /root/A/B nor in its ancestors; did you mean "
            "'force'?");
}

TEST_F(PathResolverTest, DataPaths) {
  error.clear();
  EXPECT_EQ(resolveDataPath(b, "@force.stiffness", error), &force->d_stiffness) << error;
  EXPECT_EQ(resolveDataPath(c, "@../../spring.damping", error), &spring->d_damping) << error;
  EXPECT_EQ(resolveDataPath(other, "@/A/B/C/leaf.stiffness ", error), &leaf->d_stiffness) << error;
  EXPECT_EQ(resolveDataPath(c, "@spring.name", error), &spring->d_name) << error;
  EXPECT_EQ(resolveDataPath(root, "@A.dt", error), &a.d_dt) << error;  // a node's Data
}

TEST_F(PathResolverTest, DataPathErrors) {
  EXPECT_EQ(dataFailure(b, "@force.stifness"),
            "/root/A/B/force (Spring) has no field 'stifness'; did you mean 'stiffness'?");
  EXPECT_EQ(dataFailure(b, "@force.zzzzzz"), "/root/A/B/force (Spring) has no field 'zzzzzz'");
  EXPECT_EQ(dataFailure(b, "@force"),
            "a Data link names an object and a field, as '@object.field'; got '@force'");
  EXPECT_EQ(dataFailure(b, "@../spring"),
            "a Data link names an object and a field, as '@object.field'; got '@../spring'");
  EXPECT_EQ(dataFailure(b, "@force."),
            "a Data link names an object and a field, as '@object.field'; got '@force.'");
  EXPECT_EQ(dataFailure(b, "@..stiffness"),
            "a Data link names an object and a field, as '@object.field'; got '@..stiffness'");
  EXPECT_EQ(dataFailure(b, "@.stiffness"),
            "a Data link names an object before the field, as '@object.field'; got "
            "'@.stiffness'");
  EXPECT_EQ(dataFailure(b, "@nothing.stiffness"),
            "no object or node named 'nothing' in /root/A/B nor in its ancestors");
}

TEST(IsLinkText, OnlyTextsStartingWithAnAtAndSomethingAfter) {
  EXPECT_TRUE(isLinkText("@x"));
  EXPECT_TRUE(isLinkText("  @../dofs.position"));
  EXPECT_TRUE(isLinkText("\t@/A"));
  EXPECT_FALSE(isLinkText("@"));
  EXPECT_FALSE(isLinkText("  @"));
  EXPECT_FALSE(isLinkText(""));
  EXPECT_FALSE(isLinkText("x@y"));
  EXPECT_FALSE(isLinkText("1 2 3"));
}

}  // namespace
}  // namespace stroma

namespace stroma {
namespace {

TEST_F(PathResolverTest, RelativeIndexNamesAnEarlierObjectOfTheOwnersNode) {
  EXPECT_EQ(resolveObjectPath(a, "@[-1]", error, spring), aDofs) << error;
  BaseData* stiffness = resolveDataPath(a, "@[-1].stiffness", error, spring);
  ASSERT_NE(stiffness, nullptr) << error;
  EXPECT_EQ(stiffness->owner(), aDofs);
  EXPECT_EQ(resolveObjectPath(a, "@[-2]", error, spring), nullptr);
  EXPECT_NE(error.find("before the first object"), std::string::npos) << error;
  EXPECT_EQ(resolveObjectPath(a, "@[1]", error, spring), nullptr);
  EXPECT_NE(error.find("expected '@[-k]'"), std::string::npos) << error;
  EXPECT_EQ(resolveObjectPath(a, "@[-1]", error), nullptr);  // no owner given
}

}  // namespace
}  // namespace stroma
