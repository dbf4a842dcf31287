// SPDX-License-Identifier: MIT
// The first loading stage alone: XML text to elements, with lines, includes and SOFA's forms.
#include "simulation/SceneXml.h"

#include <gtest/gtest.h>

#include "plugins/TestPlugin/TestSupport.h"

namespace stroma::test {
namespace {

namespace fs = std::filesystem;

class SceneXmlTest : public ::testing::Test {
 protected:
  /// Parses `xml` as the file `scene.scn` of the test's folder; includes are looked up
  /// relative to the including file's folder only.
  bool parse(std::string_view xml) {
    file = folder.path() / "scene.scn";
    const IncludeResolver resolve = [](const std::string& href, const fs::path& from) {
      std::error_code ec;
      const fs::path candidate = (from / href).lexically_normal();
      return fs::exists(candidate, ec) ? candidate : fs::path();
    };
    return parseSceneXml(xml, file, resolve, log, root);
  }
  std::string firstErrorText() const {
    const auto all = errors(log);
    return all.empty() ? std::string() : all.front().text;
  }

  TempDir folder;
  fs::path file;
  MessageLog log;
  SceneElement root;
};

TEST_F(SceneXmlTest, ElementsKeepTheirTagsAttributesAndLines) {
  ASSERT_TRUE(parse(R"(<?xml version="1.0"?>
<Node name="root" dt="0.02">

  <MechanicalObject name="dofs"
                    position="0 0 0"/>
  <Node name="Child">
    <TestCounter/>
  </Node>
</Node>
)")) << describe(log);
  EXPECT_EQ(root.tag, "Node");
  EXPECT_EQ(root.where.file, file.string());
  EXPECT_EQ(root.where.line, 2);
  ASSERT_NE(root.attribute("dt"), nullptr);
  EXPECT_EQ(*root.attribute("dt"), "0.02");
  EXPECT_EQ(root.attribute("gravity"), nullptr);
  ASSERT_EQ(root.children.size(), 2u);
  const SceneElement& dofs = root.children[0];
  EXPECT_EQ(dofs.tag, "MechanicalObject");
  EXPECT_EQ(dofs.where.line, 4);
  ASSERT_EQ(dofs.attributes.size(), 2u);
  EXPECT_EQ(dofs.attributes[1].name, "position");  // document order is kept
  ASSERT_EQ(root.children[1].children.size(), 1u);
  EXPECT_EQ(root.children[1].children[0].tag, "TestCounter");
  EXPECT_EQ(root.children[1].children[0].where.line, 7);
}

TEST_F(SceneXmlTest, MalformedXmlIsOneErrorWithItsLine) {
  EXPECT_FALSE(parse("<Node>\n  <A>\n  <B/>\n</Node>\n"));
  ASSERT_EQ(log.errorCount(), 1u);
  const Message m = errors(log).front();
  EXPECT_NE(m.text.find("malformed XML"), std::string::npos) << m.text;
  EXPECT_EQ(m.where.line, 2);
  EXPECT_EQ(m.where.file, file.string());
}

TEST_F(SceneXmlTest, EmptyDocumentIsAnError) {
  EXPECT_FALSE(parse(""));
  EXPECT_EQ(log.errorCount(), 1u) << describe(log);
}

TEST_F(SceneXmlTest, SofaObjectElementTakesItsClassFromType) {
  ASSERT_TRUE(parse(R"(<Node><Object type="TestCounter" name="c" increment="2"/></Node>)"))
      << describe(log);
  ASSERT_EQ(root.children.size(), 1u);
  const SceneElement& c = root.children[0];
  EXPECT_EQ(c.tag, "TestCounter");
  EXPECT_EQ(c.attribute("type"), nullptr);
  ASSERT_NE(c.attribute("increment"), nullptr);
  EXPECT_EQ(*c.attribute("increment"), "2");
}

TEST_F(SceneXmlTest, SofaObjectElementWithoutTypeIsAnError) {
  EXPECT_FALSE(parse("<Node>\n  <Object name=\"c\"/>\n</Node>"));
  ASSERT_EQ(log.errorCount(), 1u);
  EXPECT_NE(firstErrorText().find("needs a 'type' attribute"), std::string::npos)
      << firstErrorText();
  EXPECT_EQ(errors(log).front().where.line, 2);
}

TEST_F(SceneXmlTest, SofaAttributeElementsBecomeAttributes) {
  ASSERT_TRUE(parse(R"(<Node>
  <TestCounter name="c">
    <Attribute type="increment"><Data value="4"/></Attribute>
    <Attribute type="failAtStep">
      <Data value="7"/>
    </Attribute>
  </TestCounter>
</Node>
)")) << describe(log);
  const SceneElement& c = root.children.at(0);
  EXPECT_TRUE(c.children.empty());
  ASSERT_NE(c.attribute("increment"), nullptr);
  EXPECT_EQ(*c.attribute("increment"), "4");
  ASSERT_NE(c.attribute("failAtStep"), nullptr);
  EXPECT_EQ(*c.attribute("failAtStep"), "7");
}

TEST_F(SceneXmlTest, AttributeElementWithoutDataIsAnError) {
  EXPECT_FALSE(parse(R"(<Node>
  <TestCounter>
    <Attribute type="increment"/>
  </TestCounter>
</Node>)"));
  EXPECT_NE(firstErrorText().find("<Attribute> element needs"), std::string::npos) << describe(log);
  EXPECT_EQ(errors(log).at(0).where.line, 3);
}

TEST_F(SceneXmlTest, CommentsAndDeclarationsAreSkipped) {
  ASSERT_TRUE(parse(R"(<?xml version="1.0" encoding="UTF-8"?>
<!-- header -->
<Node>
  <!-- <Hidden/> -->
  <A/><!-- between --><B/>
</Node>
<!-- footer -->
)")) << describe(log);
  ASSERT_EQ(root.children.size(), 2u);
  EXPECT_EQ(root.children[0].tag, "A");
  EXPECT_EQ(root.children[1].tag, "B");
}

TEST_F(SceneXmlTest, IncludeReplacesItselfWithTheFragmentChildren) {
  const fs::path fragment = folder.write("part.xml", R"(<Node name="Group">
  <A name="first" src="@" value="1"/>
  <Node name="Sub"><B name="second" src="@" other="x"/></Node>
</Node>
)");
  ASSERT_TRUE(parse(R"(<Node>
  <Before/>
  <include href="part.xml" src="@loader" second.other="y" first.extra="z"/>
  <After/>
</Node>
)")) << describe(log);
  ASSERT_EQ(root.children.size(), 4u);
  EXPECT_EQ(root.children[0].tag, "Before");
  const SceneElement& first = root.children[1];
  EXPECT_EQ(first.tag, "A");
  EXPECT_EQ(first.where.file, fragment.string());
  EXPECT_EQ(first.where.line, 2);
  EXPECT_EQ(*first.attribute("src"), "@loader");  // a plain attribute replaces everywhere
  EXPECT_EQ(*first.attribute("value"), "1");
  EXPECT_EQ(*first.attribute("extra"), "z");  // obj.attr adds one that was not declared
  const SceneElement& sub = root.children[2];
  EXPECT_EQ(sub.tag, "Node");
  const SceneElement& second = sub.children.at(0);
  EXPECT_EQ(*second.attribute("src"), "@loader");
  EXPECT_EQ(*second.attribute("other"), "y");
  EXPECT_EQ(root.children[3].tag, "After");
}

TEST_F(SceneXmlTest, PlainIncludeAttributeOnlyReplacesDeclaredOnes) {
  folder.write("part.xml",
               R"(<Node name="Group"><A name="a" position="0 0 0"/><B name="b"/></Node>)");
  ASSERT_TRUE(parse(R"(<Node><include href="part.xml" position="1 1 1"/></Node>)"))
      << describe(log);
  EXPECT_EQ(*root.children.at(0).attribute("position"), "1 1 1");
  EXPECT_EQ(root.children.at(1).attribute("position"), nullptr);
}

TEST_F(SceneXmlTest, IncludedRootNodeIsAChildUnlessItIsAGroup) {
  // SOFA's rule: only a root named Group stands for its children; `name` renames the root.
  folder.write("bowl.xml", R"(<Node name="Salad Bowl">
  <Loader name="meshLoader"/>
  <Model name="visual" src="@meshLoader" dx="0"/>
</Node>
)");
  ASSERT_TRUE(parse(R"(<Node>
  <include href="bowl.xml" name="Bowl1" dx="10"/>
  <include href="bowl.xml" name="Bowl2" dx="20"/>
  <include href="bowl.xml"/>
</Node>
)")) << describe(log);
  ASSERT_EQ(root.children.size(), 3u);
  const char* names[] = {"Bowl1", "Bowl2", "Salad Bowl"};
  for (int i = 0; i < 3; ++i) {
    const SceneElement& bowl = root.children[i];
    EXPECT_EQ(bowl.tag, "Node");
    EXPECT_EQ(*bowl.attribute("name"), names[i]);
    ASSERT_EQ(bowl.children.size(), 2u);
    EXPECT_EQ(*bowl.children[0].attribute("name"), "meshLoader");  // not renamed
    EXPECT_EQ(*bowl.children[1].attribute("name"), "visual");
  }
  EXPECT_EQ(*root.children[0].children[1].attribute("dx"), "10");
  EXPECT_EQ(*root.children[1].children[1].attribute("dx"), "20");
  EXPECT_EQ(*root.children[2].children[1].attribute("dx"), "0");
}

TEST_F(SceneXmlTest, SofaDoubleUnderscoreSetsAnAttributeOfANamedElement) {
  folder.write("part.xml", R"(<Node name="Group"><A name="springs" stiffness="1"/></Node>)");
  ASSERT_TRUE(parse(R"(<Node><include href="part.xml" springs__stiffness="5"/></Node>)"))
      << describe(log);
  EXPECT_EQ(*root.children.at(0).attribute("stiffness"), "5");
}

TEST_F(SceneXmlTest, MergeFragmentMergesIntoTheIncludingNode) {
  folder.write("base.xml", R"(<Node name="root" dt="0.04">
  <Node name="Snake"><A name="dofs"/></Node>
</Node>
)");
  folder.write("more.xml", R"(<Node name="_Merge_">
  <Node name="Snake"><B name="fem"/></Node>
  <Node name="Other"/>
</Node>
)");
  ASSERT_TRUE(parse(R"(<Node name="top">
  <include href="base.xml" name="_Merge_"/>
  <include href="more.xml"/>
</Node>
)")) << describe(log);
  EXPECT_EQ(*root.attribute("name"), "top");
  ASSERT_NE(root.attribute("dt"), nullptr);
  EXPECT_EQ(*root.attribute("dt"), "0.04");
  ASSERT_EQ(root.children.size(), 2u);
  const SceneElement& snake = root.children[0];
  EXPECT_EQ(*snake.attribute("name"), "Snake");
  ASSERT_EQ(snake.children.size(), 2u);
  EXPECT_EQ(snake.children[0].tag, "A");
  EXPECT_EQ(snake.children[1].tag, "B");
  EXPECT_EQ(*root.children[1].attribute("name"), "Other");
}

TEST_F(SceneXmlTest, IncludeSettingAMissingObjectIsAnError) {
  folder.write("part.xml", R"(<Node><A name="a"/></Node>)");
  EXPECT_FALSE(parse("<Node>\n<include href=\"part.xml\" nope.value=\"1\"/>\n</Node>"));
  EXPECT_NE(firstErrorText().find("no element named 'nope'"), std::string::npos) << describe(log);
  EXPECT_EQ(errors(log).at(0).where.line, 2);
}

TEST_F(SceneXmlTest, IncludeWithoutHrefIsAnError) {
  EXPECT_FALSE(parse("<Node>\n  <include/>\n</Node>"));
  EXPECT_NE(firstErrorText().find("needs an href"), std::string::npos) << describe(log);
  EXPECT_EQ(errors(log).at(0).where.line, 2);
}

TEST_F(SceneXmlTest, MissingIncludeIsAnError) {
  EXPECT_FALSE(parse("<Node>\n\n  <include href=\"missing.xml\"/>\n</Node>"));
  EXPECT_NE(firstErrorText().find("included file 'missing.xml' not found"), std::string::npos)
      << describe(log);
  EXPECT_EQ(errors(log).at(0).where.line, 3);
  EXPECT_EQ(errors(log).at(0).where.file, file.string());
}

TEST_F(SceneXmlTest, IncludeCycleIsAnError) {
  folder.write("a.xml", R"(<Node><include href="b.xml"/></Node>)");
  folder.write("b.xml", R"(<Node><include href="a.xml"/></Node>)");
  EXPECT_FALSE(parse(R"(<Node><include href="a.xml"/></Node>)"));
  EXPECT_NE(firstErrorText().find("include cycle"), std::string::npos) << describe(log);
}

TEST_F(SceneXmlTest, SelfIncludeIsAnError) {
  folder.write("scene.scn", R"(<Node><include href="scene.scn"/></Node>)");
  EXPECT_FALSE(parse(R"(<Node><include href="scene.scn"/></Node>)"));
  EXPECT_NE(firstErrorText().find("include cycle"), std::string::npos) << describe(log);
}

TEST_F(SceneXmlTest, SameFragmentTwiceIsNotACycle) {
  folder.write("part.xml", R"(<A name="a"/>)");
  ASSERT_TRUE(parse(R"(<Node>
  <Node name="One"><include href="part.xml"/></Node>
  <Node name="Two"><include href="part.xml"/></Node>
</Node>)"))
      << describe(log);
  EXPECT_EQ(root.children.at(0).children.at(0).tag, "A");
  EXPECT_EQ(root.children.at(1).children.at(0).tag, "A");
}

}  // namespace
}  // namespace stroma::test
