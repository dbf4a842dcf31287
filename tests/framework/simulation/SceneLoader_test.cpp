// SPDX-License-Identifier: MIT
// The scene loader on bad input (one test per kind of mistake: each must fail the load with an
// error naming file, line, component, field, what was expected and the nearest valid names)
// and on the scene forms it accepts (includes, SOFA's older syntax, links, templates).
#include "simulation/SceneLoader.h"

#include <gtest/gtest.h>

#include <string>

#include "core/BaseState.h"
#include "core/PathResolver.h"
#include "core/Runtime.h"
#include "plugins/TestPlugin/TestSupport.h"
#include "simulation/Scene.h"

namespace stroma::test {
namespace {

namespace fs = std::filesystem;

class SceneLoaderTest : public ::testing::Test {
 protected:
  SceneLoaderTest() { useTestPlugins(runtime); }

  /// Writes `xml` as `name` in the test's folder and loads it.
  bool load(std::string_view xml, const std::string& name = "scene.scn") {
    file = folder.write(name, xml);
    return scene.loadFile(file);
  }

  /// The error whose text contains every one of `needles`, after checking that there is one.
  Message error(std::initializer_list<std::string_view> needles) {
    for (const Message& m : errors(scene.log())) {
      bool all = true;
      for (std::string_view n : needles) all &= m.text.find(n) != std::string::npos;
      if (all) return m;
    }
    std::string wanted;
    for (std::string_view n : needles) wanted += " '" + std::string(n) + "'";
    ADD_FAILURE() << "no error containing" << wanted << " in:\n" << describe(scene.log());
    return {};
  }

  /// Checks where an error points: file and line, component path and class, field.
  void expectPlace(const Message& m, const fs::path& where, int line, const std::string& path,
                   const std::string& className, const std::string& field) {
    EXPECT_EQ(m.where.file, where.string()) << m.text;
    EXPECT_EQ(m.where.line, line) << m.text;
    EXPECT_EQ(m.componentPath, path) << m.text;
    EXPECT_EQ(m.componentClass, className) << m.text;
    EXPECT_EQ(m.field, field) << m.text;
  }

  Base* object(const std::string& path) {
    std::string why;
    Base* found = resolveObjectPath(scene.root(), path, why);
    EXPECT_NE(found, nullptr) << why;
    return found;
  }
  std::string value(const std::string& path, const std::string& field) {
    Base* o = object(path);
    if (!o) return "<no object>";
    const BaseData* d = o->findData(field);
    EXPECT_NE(d, nullptr) << path << " has no field " << field;
    return d ? d->valueText() : "<no field>";
  }
  void set(const std::string& path, const std::string& field, const std::string& text) {
    BaseData* d = object(path)->findData(field);
    ASSERT_NE(d, nullptr);
    std::string why;
    ASSERT_TRUE(d->read(text, why)) << why;
  }

  Runtime runtime;
  TempDir folder;
  Scene scene{runtime};
  fs::path file;
};

// --- Bad input --------------------------------------------------------------------------------

TEST_F(SceneLoaderTest, MalformedXmlNamesTheLineOfTheUnclosedTag) {
  EXPECT_FALSE(load(R"(<Node name="root">
  <TestCounter name="a">
  <TestCounter name="b"/>
</Node>
)"));
  EXPECT_FALSE(scene.isLoaded());
  ASSERT_EQ(scene.log().errorCount(), 1u) << describe(scene.log());
  const Message m = error({"malformed XML"});
  EXPECT_EQ(m.where.file, file.string());
  EXPECT_EQ(m.where.line, 2);
  EXPECT_EQ(formatForConsole(m).rfind(file.string() + ":2: error: malformed XML", 0), 0u)
      << formatForConsole(m);
}

TEST_F(SceneLoaderTest, MalformedXmlInAFragmentNamesTheFragment) {
  const fs::path fragment = folder.write("fragments/broken.xml", R"(<Node name="Group">

  <TestCounter name="a" increment="1
</Node>
)");
  EXPECT_FALSE(load(R"(<Node name="root">
  <include href="fragments/broken.xml"/>
</Node>
)"));
  const Message m = error({"malformed XML"});
  EXPECT_EQ(m.where.file, fragment.string());
  EXPECT_GE(m.where.line, 3);
}

TEST_F(SceneLoaderTest, UnknownComponentSuggestsTheClosestName) {
  EXPECT_FALSE(load(R"(<Node name="root">
  <Node name="Body">
    <MechanicalObjekt name="dofs" position="0 0 0"/>
  </Node>
</Node>
)"));
  const Message m =
      error({"unknown component 'MechanicalObjekt'", "did you mean", "'MechanicalObject'"});
  expectPlace(m, file, 3, "/root/Body/dofs", "MechanicalObjekt", "");
}

TEST_F(SceneLoaderTest, UnnamedUnknownComponentIsNamedAfterItsClass) {
  EXPECT_FALSE(load(R"(<Node name="root">
  <TestCountr/>
</Node>
)"));
  const Message m = error({"unknown component 'TestCountr'", "'TestCounter'"});
  expectPlace(m, file, 2, "/root/testCountr", "TestCountr", "");
}

TEST_F(SceneLoaderTest, SofaOptionsOfAClassAreAcceptedWithoutEffect) {
  // TestCounter accepts SOFA's "showCount" (a drawing option it has no Data for): an info
  // message, no error; another unknown attribute is still an error.
  EXPECT_TRUE(load(R"(<Node name="root"><TestCounter name="c" showCount="1"/></Node>)"))
      << describe(scene.log());
  bool told = false;
  for (const Message& m : scene.log().messages())
    told |= m.level == MessageLevel::info && m.field == "showCount" &&
            m.text.find("SOFA option 'showCount' accepted without effect") != std::string::npos;
  EXPECT_TRUE(told) << describe(scene.log());
  EXPECT_FALSE(load(R"(<Node name="root"><TestCounter name="c" showCounts="1"/></Node>)"));
}

TEST_F(SceneLoaderTest, SofaComponentThatStromaLacksIsSaidToBeOne) {
  EXPECT_FALSE(load(R"(<Node name="root">
  <MechanicalObject name="dofs" position="0 0 0"/>
  <BeamFEMForceField name="loop"/>
</Node>
)"));
  ASSERT_EQ(scene.log().errorCount(), 1u) << describe(scene.log());
  const Message m =
      error({"'BeamFEMForceField' is a SOFA component", "Stroma does not provide"});
  expectPlace(m, file, 3, "/root/loop", "BeamFEMForceField", "");
}

TEST_F(SceneLoaderTest, UnknownAttributeSuggestsTheClosestField) {
  EXPECT_FALSE(load(R"(<Node name="root">
  <TestCounter name="counter"
               incremnet="2"/>
</Node>
)"));
  const Message m = error({"unknown attribute 'incremnet'", "did you mean 'increment'?"});
  // The element's line: tinyxml2 gives no line per attribute.
  expectPlace(m, file, 2, "/root/counter", "TestCounter", "incremnet");
}

TEST_F(SceneLoaderTest, UnknownNodeAttributeIsReported) {
  EXPECT_FALSE(load(R"(<Node name="root" gravty="0 0 0"/>)"));
  const Message m = error({"unknown attribute 'gravty'", "'gravity'"});
  expectPlace(m, file, 1, "/root", "Node", "gravty");
}

TEST_F(SceneLoaderTest, ValueOfTheWrongTypeSaysWhatWasExpected) {
  EXPECT_FALSE(load(R"(<Node name="root">
  <TestCounter name="counter" increment="fast"/>
</Node>
)"));
  const Message m = error({"expected a number, got 'fast'", "(real)"});
  expectPlace(m, file, 2, "/root/counter", "TestCounter", "increment");
}

TEST_F(SceneLoaderTest, ValueWithTheWrongCountSaysHowManyNumbers) {
  EXPECT_FALSE(load(R"(<Node name="root" gravity="0 -9.81">
  <MechanicalObject name="dofs" position="0 0 0  1 0"/>
</Node>
)"));
  expectPlace(error({"expected 3 numbers (Vec3d), got 2"}), file, 1, "/root", "Node", "gravity");
  expectPlace(error({"expected a multiple of 3 numbers", "got 5"}), file, 2, "/root/dofs",
              "MechanicalObject", "position");
}

TEST_F(SceneLoaderTest, NanIsRefusedWhereTheDataForbidsIt) {
  EXPECT_FALSE(load(R"(<Node name="root">
  <TestEngine name="engine" input="1 nan 3"/>
</Node>
)"));
  const Message m = error({"expected a finite number, got NaN"});
  expectPlace(m, file, 2, "/root/engine", "TestEngine", "input");
}

TEST_F(SceneLoaderTest, ValueOutsideTheRangeGivesTheBound) {
  EXPECT_FALSE(load(R"(<Node name="root">
  <TestCounter name="counter" increment="11"/>
  <TestCounter name="other" failAtStep="-1"/>
</Node>
)"));
  expectPlace(error({"expected a value <= 10, got 11"}), file, 2, "/root/counter", "TestCounter",
              "increment");
  expectPlace(error({"-1 is outside the allowed range [0, +inf)"}), file, 3, "/root/other",
              "TestCounter", "failAtStep");
}

TEST_F(SceneLoaderTest, BadValueFoundByInitFailsTheLoad) {
  EXPECT_FALSE(load(R"(<Node name="root">
  <Node name="Spring">
    <TestInitCheck name="check" stiffness="-2"/>
  </Node>
</Node>
)"));
  const Message m = error({"expected a positive stiffness, got -2"});
  expectPlace(m, file, 3, "/root/Spring/check", "TestInitCheck", "stiffness");
}

TEST_F(SceneLoaderTest, BrokenObjectLinkSuggestsTheClosestName) {
  EXPECT_FALSE(load(R"(<Node name="root">
  <Node name="Body">
    <MechanicalObject name="dofs" position="0 0 0"/>
    <TestCounter name="counter" mstate="@dofz"/>
  </Node>
</Node>
)"));
  const Message m =
      error({"broken link '@dofz'", "no object or node named 'dofz'", "did you mean 'dofs'?"});
  expectPlace(m, file, 4, "/root/Body/counter", "TestCounter", "mstate");
}

TEST_F(SceneLoaderTest, ObjectLinkToTheWrongKindOfObjectSaysWhatIsExpected) {
  EXPECT_FALSE(load(R"(<Node name="root">
  <TestEngine name="engine"/>
  <TestCounter name="counter" mstate="@engine"/>
</Node>
)"));
  const Message m = error({"broken link '@engine'", "is a TestEngine, not a BaseState"});
  expectPlace(m, file, 3, "/root/counter", "TestCounter", "mstate");
}

TEST_F(SceneLoaderTest, ObjectLinkThroughAMissingNodeSuggestsTheClosestNode) {
  EXPECT_FALSE(load(R"(<Node name="root">
  <Node name="Liver"><MechanicalObject name="dofs" position="0 0 0"/></Node>
  <TestCounter name="counter" mstate="@Livr/dofs"/>
</Node>
)"));
  const Message m = error({"no child node named 'Livr'", "did you mean 'Liver'?"});
  expectPlace(m, file, 3, "/root/counter", "TestCounter", "mstate");
}

TEST_F(SceneLoaderTest, BrokenDataLinkSuggestsTheClosestField) {
  EXPECT_FALSE(load(R"(<Node name="root">
  <TestEngine name="a" input="1 2"/>
  <TestEngine name="b" input="@a.outptu"/>
  <TestEngine name="c" input="@ghost.output"/>
</Node>
)"));
  expectPlace(error({"broken link '@a.outptu'", "has no field 'outptu'", "did you mean 'output'?"}),
              file, 3, "/root/b", "TestEngine", "input");
  expectPlace(error({"broken link '@ghost.output'", "no object or node named 'ghost'"}), file, 4,
              "/root/c", "TestEngine", "input");
}

TEST_F(SceneLoaderTest, DataLinkBetweenTypesThatDoNotConvertIsBroken) {
  EXPECT_FALSE(load(R"(<Node name="root">
  <TestEngine name="a" input="1 2"/>
  <TestCounter name="counter" increment="@a.output"/>
</Node>
)"));
  const Message m = error({"broken link '@a.output'", "cannot take the value of 'output'"});
  expectPlace(m, file, 3, "/root/counter", "TestCounter", "increment");
}

TEST_F(SceneLoaderTest, ComponentOfAPluginWhoseLibraryIsMissing) {
  TempDir plugins;
  plugins.write("Ghost.stroma-plugin", R"(# a plugin whose library was deleted
plugin GhostPlugin
library libGhostPlugin.so
version 1.0
description Gone
component GhostForceField
)");
  useTestPlugins(runtime, {plugins.path()});
  EXPECT_FALSE(load(R"(<Node name="root">
  <GhostForceField name="ghost"/>
</Node>
)"));
  const Message m = error({"component 'GhostForceField' is in plugin GhostPlugin", "failed to load",
                           (plugins.path() / "libGhostPlugin.so").string()});
  expectPlace(m, file, 2, "/root/ghost", "GhostForceField", "");
  EXPECT_FALSE(runtime.plugins().isLoaded("GhostPlugin"));
}

TEST_F(SceneLoaderTest, MissingFileListsTheFoldersSearched) {
  const fs::path data = folder.path() / "data";
  fs::create_directories(data);
  runtime.addDataDirectory(data);
  EXPECT_FALSE(load(R"(<Node name="root">
  <TestLoader name="loader" filename="nope.obj"/>
</Node>
)"));
  const Message m = error({"file 'nope.obj' not found", "searched:", folder.path().string(),
                           data.string(), "--data-path"});
  expectPlace(m, file, 2, "/root/loader", "TestLoader", "filename");
}

TEST_F(SceneLoaderTest, MissingViewerOnlyFileIsAWarning) {
  EXPECT_TRUE(load(R"(<Node name="root">
  <OglModel name="visual" filename="nope.obj" texturename="nope.png"/>
</Node>
)")) << describe(scene.log());
  EXPECT_EQ(scene.log().count(MessageLevel::warning), 2u) << describe(scene.log());
}

TEST_F(SceneLoaderTest, MissingIncludeNamesTheHref) {
  EXPECT_FALSE(load(R"(<Node name="root">
  <TestCounter/>
  <include href="fragments/absent.xml"/>
</Node>
)"));
  const Message m = error({"included file 'fragments/absent.xml' not found"});
  EXPECT_EQ(m.where.file, file.string());
  EXPECT_EQ(m.where.line, 3);
}

TEST_F(SceneLoaderTest, RootMustBeANode) {
  EXPECT_FALSE(load(R"(<TestCounter name="alone"/>)"));
  const Message m = error({"the root element must be a <Node>", "<TestCounter>"});
  EXPECT_EQ(m.where.line, 1);
}

TEST_F(SceneLoaderTest, ComponentWithChildElementsIsReported) {
  EXPECT_FALSE(load(R"(<Node name="root">
  <TestCounter name="counter">
    <TestEngine name="inner"/>
  </TestCounter>
</Node>
)"));
  const Message m = error({"has no child elements", "<TestEngine> belongs in a <Node>"});
  expectPlace(m, file, 3, "/root/counter", "TestCounter", "");
}

TEST_F(SceneLoaderTest, ErrorInAFragmentNamesTheFragmentFileAndLine) {
  const fs::path fragment = folder.write("fragments/counter.xml", R"(<Node name="Group">
  <TestCounter name="counter"
               incremnt="1"/>
</Node>
)");
  EXPECT_FALSE(load(R"(<Node name="root">
  <include href="fragments/counter.xml"/>
</Node>
)"));
  const Message m = error({"unknown attribute 'incremnt'", "'increment'"});
  expectPlace(m, fragment, 2, "/root/counter", "TestCounter", "incremnt");
}

TEST_F(SceneLoaderTest, EveryErrorOfTheSceneIsReported) {
  EXPECT_FALSE(load(R"(<Node name="root">
  <MechanicalObjekt name="a"/>
  <TestCounter name="b" incremnet="1"/>
  <TestCounter name="c" increment="much"/>
  <TestCounter name="d" mstate="@nothing"/>
  <TestLoader name="e" filename="missing.obj"/>
  <BeamFEMForceField name="f"/>
  <TestEngine name="g" input="@b.outptu"/>
  <TestInitCheck name="h" stiffness="-1"/>
</Node>
)"));
  EXPECT_EQ(scene.log().errorCount(), 7u) << describe(scene.log());
  EXPECT_EQ(error({"unknown component"}).where.line, 2);
  EXPECT_EQ(error({"unknown attribute"}).where.line, 3);
  EXPECT_EQ(error({"expected a number"}).where.line, 4);
  EXPECT_EQ(error({"broken link '@nothing'"}).where.line, 5);
  EXPECT_EQ(error({"not found"}).where.line, 6);
  EXPECT_EQ(error({"SOFA component"}).where.line, 7);
  EXPECT_EQ(error({"broken link '@b.outptu'"}).where.line, 8);
  // init() does not run on a graph with bad input, so the last line's check stays silent.
  EXPECT_TRUE(findError(scene.log(), "positive stiffness").text.empty());
}

TEST_F(SceneLoaderTest, LoadingAgainAfterAFailureWorks) {
  EXPECT_FALSE(load(R"(<Node><Nope/></Node>)"));
  EXPECT_TRUE(load(R"(<Node><TestCounter name="counter"/></Node>)")) << describe(scene.log());
  EXPECT_TRUE(scene.isLoaded());
  EXPECT_TRUE(scene.step());
  EXPECT_EQ(value("@counter", "count"), "1");
}

// --- Accepted forms ---------------------------------------------------------------------------

TEST_F(SceneLoaderTest, IncludeExpandsTheFragmentWithOverrides) {
  const fs::path fragment = folder.write("fragments/doubler.xml", R"(<!-- a reusable group -->
<Node name="Group">
  <TestEngine name="copy" src="@"/>
  <TestCounter name="counter" increment="1"/>
</Node>
)");
  const std::string xml = R"(<Node name="root">
  <TestEngine name="loader" input="1 2 3"/>
  <Node name="Child">
    <include href="../fragments/doubler.xml" src="@loader" counter.increment="2.5"/>
  </Node>
</Node>
)";
  ASSERT_TRUE(load(xml, "scenes/scene.scn")) << describe(scene.log());
  // The fragment's elements are inserted in the including node, which keeps its name.
  EXPECT_EQ(value("@/Child/copy", "input"), "1 2 3");  // src="@" became src="@loader"
  EXPECT_EQ(value("@/Child/copy", "output"), "2 4 6");
  EXPECT_EQ(value("@/Child/counter", "increment"), "2.5");
  EXPECT_EQ(scene.root().findChild("Child")->objects().size(), 2u);
  EXPECT_EQ(object("@/Child/copy")->sourceLocation().file, fragment.string());
  EXPECT_EQ(object("@/Child/copy")->sourceLocation().line, 3);
}

TEST_F(SceneLoaderTest, IncludeOfASingleComponentAndNestedIncludes) {
  folder.write("parts/counter.xml", R"(<TestCounter name="single" increment="3"/>)");
  folder.write("parts/group.xml", R"(<Node name="Group">
  <include href="counter.xml"/>
  <TestEngine name="engine" input="4"/>
</Node>
)");
  ASSERT_TRUE(load(R"(<Node name="root">
  <include href="parts/group.xml" single.increment="0.5"/>
</Node>
)")) << describe(scene.log());
  EXPECT_EQ(value("@single", "increment"), "0.5");
  EXPECT_EQ(value("@engine", "output"), "8");
}

TEST_F(SceneLoaderTest, IncludeFoundInTheDataPath) {
  TempDir data;
  data.write("shared/fragment.xml", R"(<TestCounter name="shared"/>)");
  runtime.addDataDirectory(data.path());
  ASSERT_TRUE(load(R"(<Node name="root"><include href="shared/fragment.xml"/></Node>)"))
      << describe(scene.log());
  EXPECT_NE(scene.root().findObject("shared"), nullptr);
}

TEST_F(SceneLoaderTest, SofaObjectAndAttributeElementsAreAccepted) {
  ASSERT_TRUE(load(R"(<?xml version="1.0"?>
<Node name="root">
  <Object type="TestCounter" name="counter">
    <Attribute type="increment"><Data value="3"/></Attribute>
  </Object>
  <Object type="TestEngine" name="engine" input="1"/>
</Node>
)")) << describe(scene.log());
  EXPECT_EQ(object("@counter")->className(), "TestCounter");
  EXPECT_EQ(object("@counter")->sourceLocation().line, 3);
  EXPECT_EQ(value("@counter", "increment"), "3");
  EXPECT_EQ(value("@engine", "output"), "2");
}

TEST_F(SceneLoaderTest, CommentsAreIgnored) {
  ASSERT_TRUE(load(R"(<?xml version="1.0"?>
<!-- <Nope/> before the root -->
<Node name="root">
  <!-- <MechanicalObjekt/> -->
  <TestCounter name="counter" /> <!-- trailing -->
  <!--
    <Node name="Disabled"><Broken attr="x"/></Node>
  -->
</Node>
)")) << describe(scene.log());
  EXPECT_EQ(scene.root().objects().size(), 1u);
  EXPECT_TRUE(scene.root().children().empty());
}

TEST_F(SceneLoaderTest, RelativeFileNamesResolveInTheSceneFolderThenTheDataPath) {
  TempDir data;
  folder.write("scenes/meshes/a.obj", "");
  data.write("meshes/a.obj", "");
  data.write("meshes/b.obj", "");
  const fs::path absolute = data.write("absolute.obj", "");
  runtime.addDataDirectory(data.path());
  const std::string xml = R"(<Node name="root">
  <TestLoader name="a" filename="meshes/a.obj"/>
  <TestLoader name="b" filename="meshes/b.obj"/>
  <TestLoader name="c" filename=")" +
                          absolute.string() + R"("/>
</Node>
)";
  ASSERT_TRUE(load(xml, "scenes/scene.scn")) << describe(scene.log());
  auto resolved = [&](const std::string& name) {
    auto* data = dynamic_cast<const Data<FileName>*>(object("@" + name)->findData("filename"));
    EXPECT_NE(data, nullptr);
    return data ? data->value().resolved : std::string();
  };
  EXPECT_EQ(resolved("a"), (folder.path() / "scenes/meshes/a.obj").string());
  EXPECT_EQ(resolved("b"), (data.path() / "meshes/b.obj").string());
  EXPECT_EQ(resolved("c"), absolute.string());
  EXPECT_EQ(value("@a", "filename"), "meshes/a.obj");  // the scene's text is kept
}

TEST_F(SceneLoaderTest, AliasCreatesTheRegisteredClass) {
  ASSERT_TRUE(load(R"(<Node name="root"><LegacyTestCounter name="old" increment="2"/></Node>)"))
      << describe(scene.log());
  EXPECT_EQ(object("@old")->className(), "TestCounter");
  ASSERT_TRUE(scene.step());
  EXPECT_EQ(value("@old", "count"), "1");
  EXPECT_EQ(value("@old", "total"), "2");
}

TEST_F(SceneLoaderTest, TemplateIsDeducedFromTheContextState) {
  ASSERT_TRUE(load(R"(<Node name="root">
  <Node name="Frames">
    <MechanicalObject name="dofs" template="Rigid3d" position="0 0 0  0 0 0 1"/>
    <TestTemplated name="deduced" values="1 2 3  0 0 0 1"/>
    <Node name="Child"><TestTemplated name="inherited"/></Node>
  </Node>
  <Node name="Points">
    <MechanicalObject name="dofs" position="0 0 0"/>
    <TestTemplated name="deduced"/>
  </Node>
  <TestTemplated name="byDefault"/>
  <TestTemplated name="given" template="Rigid"/>
</Node>
)")) << describe(scene.log());
  EXPECT_EQ(object("@/Frames/dofs")->templateName(), "Rigid3d");
  EXPECT_EQ(object("@/Frames/deduced")->templateName(), "Rigid3d");
  EXPECT_EQ(object("@/Frames/Child/inherited")->templateName(), "Rigid3d");
  EXPECT_EQ(object("@/Points/deduced")->templateName(), "Vec3d");
  EXPECT_EQ(object("@/byDefault")->templateName(), "Vec3d");
  EXPECT_EQ(object("@/given")->templateName(), "Rigid3d");
  EXPECT_EQ(value("@/Frames/deduced", "values"), "1 2 3 0 0 0 1");
}

TEST_F(SceneLoaderTest, UnknownTemplateListsTheAvailableOnes) {
  EXPECT_FALSE(load(R"(<Node name="root">
  <TestTemplated name="t" template="Vec2d"/>
</Node>
)"));
  const Message m = error({"has no template 'Vec2d'", "'Vec3d' or 'Rigid3d'"});
  expectPlace(m, file, 2, "/root/t", "TestTemplated", "template");
}

TEST_F(SceneLoaderTest, DataLinksPullLazilyAfterTheSourceChanges) {
  ASSERT_TRUE(load(R"(<Node name="root">
  <TestEngine name="a" input="1 2 3"/>
  <Node name="Child">
    <TestEngine name="b" input="@../a.output"/>
    <TestEngine name="c" input="@/root/Child/b.output"/>
  </Node>
</Node>
)")) << describe(scene.log());
  EXPECT_EQ(value("@/Child/c", "output"), "8 16 24");
  EXPECT_EQ(value("@/Child/b", "output"), "4 8 12");
  const std::string aUpdates = value("@a", "updates");
  const std::string bUpdates = value("@/Child/b", "updates");

  set("@a", "input", "5");
  // Nothing is recomputed until an output is read.
  EXPECT_EQ(value("@a", "updates"), aUpdates);
  EXPECT_EQ(value("@/Child/b", "updates"), bUpdates);
  EXPECT_EQ(value("@/Child/c", "output"), "40");
  EXPECT_EQ(value("@a", "updates"), std::to_string(std::stoi(aUpdates) + 1));
  EXPECT_EQ(value("@/Child/b", "updates"), std::to_string(std::stoi(bUpdates) + 1));
  EXPECT_EQ(value("@/Child/b", "output"), "20");
  // Reading again computes nothing.
  EXPECT_EQ(value("@/Child/c", "output"), "40");
  EXPECT_EQ(value("@a", "updates"), std::to_string(std::stoi(aUpdates) + 1));
}

TEST_F(SceneLoaderTest, SrcCopiesTheSameNamedFieldsOfALoader) {
  ASSERT_TRUE(load(R"(<Node name="root">
  <TestLoader name="loader" count="3" spacing="0.5"/>
  <MechanicalObject name="dofs" src="@loader"/>
  <MechanicalObject name="own" src="@loader" position="9 9 9"/>
</Node>
)")) << describe(scene.log());
  EXPECT_EQ(value("@dofs", "position"), "0 0 0 0.5 0 0 1 0 0");
  EXPECT_EQ(value("@own", "position"), "9 9 9");  // what the scene sets wins
  auto* state = dynamic_cast<BaseState*>(object("@dofs"));
  ASSERT_NE(state, nullptr);
  EXPECT_EQ(state->size(), 3u);
  // The loader's own fields are not copied over the target's (name, outputs).
  EXPECT_EQ(object("@dofs")->name(), "dofs");
}

TEST_F(SceneLoaderTest, BrokenSrcLinkIsReported) {
  EXPECT_FALSE(load(R"(<Node name="root">
  <TestLoader name="loader"/>
  <MechanicalObject name="dofs" src="@loadr"/>
</Node>
)"));
  const Message m = error({"broken link '@loadr'", "did you mean 'loader'?"});
  expectPlace(m, file, 3, "/root/dofs", "MechanicalObject", "src");
}

TEST_F(SceneLoaderTest, UnnamedComponentsGetUniqueNames) {
  ASSERT_TRUE(load(R"(<Node name="root">
  <TestCounter/>
  <TestCounter/>
  <Node><TestCounter/></Node>
</Node>
)")) << describe(scene.log());
  ASSERT_EQ(scene.root().objects().size(), 2u);
  EXPECT_EQ(scene.root().objects()[0]->name(), "testCounter");
  EXPECT_EQ(scene.root().objects()[1]->name(), "testCounter1");
  ASSERT_EQ(scene.root().children().size(), 1u);
  EXPECT_EQ(scene.root().children()[0]->name(), "node");
}

TEST_F(SceneLoaderTest, TwoObjectsWithOneNameAreReportedAndTheSecondRenamed) {
  // As SOFA does: a warning, and the second object renamed so that names stay unique.
  ASSERT_TRUE(load(R"(<Node name="root">
  <Node name="Body">
    <MechanicalObject name="dofs" position="0 0 0"/>
    <MechanicalObject name="dofs" position="1 1 1"/>
  </Node>
</Node>
)")) << describe(scene.log());
  const Node& body = *scene.root().children().front();
  ASSERT_EQ(body.objects().size(), 2u);
  EXPECT_EQ(body.objects()[0]->name(), "dofs");
  EXPECT_EQ(body.objects()[1]->name(), "dofs1");
  std::vector<Message> warnings;
  for (const Message& m : scene.log().messages())
    if (m.level == MessageLevel::warning) warnings.push_back(m);
  ASSERT_EQ(warnings.size(), 1u) << describe(scene.log());
  const Message& w = warnings.front();
  EXPECT_NE(w.text.find("two objects were named 'dofs' (MechanicalObject at line 3, "
                        "MechanicalObject at line 4); the second is now 'dofs1'"),
            std::string::npos)
      << w.text;
  expectPlace(w, file, 4, "/root/Body/dofs1", "MechanicalObject", "name");
}

TEST_F(SceneLoaderTest, ALinkToADuplicatedNameIsAnErrorNotEitherObject) {
  EXPECT_FALSE(load(R"(<Node name="root">
  <Node name="Body">
    <MechanicalObject name="dofs" position="0 0 0"/>
    <MechanicalObject name="dofs" position="1 1 1"/>
    <TestCounter name="counter" mstate="@dofs"/>
    <MechanicalObject name="copy" position="@dofs.position"/>
  </Node>
  <Node name="Other">
    <TestCounter name="far" mstate="@/Body/dofs"/>
  </Node>
</Node>
)"));
  const Message m = error({"broken link '@dofs'", "'dofs' is ambiguous in /root/Body",
                           "two objects were named 'dofs'", "give them different names"});
  expectPlace(m, file, 5, "/root/Body/counter", "TestCounter", "mstate");
  error({"'dofs' is ambiguous in /root/Body"});  // the Data link of 'copy'
  const Message far = error({"broken link '@/Body/dofs'", "'dofs' is ambiguous"});
  expectPlace(far, file, 9, "/root/Other/far", "TestCounter", "mstate");
  // The renamed object is still reachable by its new name.
  std::string why;
  EXPECT_NE(resolveObjectPath(scene.root(), "/Body/dofs1", why), nullptr) << why;
}

TEST_F(SceneLoaderTest, TwoChildNodesWithOneNameAreReportedAndLinksThroughThemRefused) {
  EXPECT_FALSE(load(R"(<Node name="root">
  <Node name="Organ"><MechanicalObject name="dofs" position="0 0 0"/></Node>
  <Node name="Organ"><MechanicalObject name="dofs" position="1 0 0"/></Node>
  <TestCounter name="counter" mstate="@Organ/dofs"/>
</Node>
)"));
  ASSERT_EQ(scene.root().children().size(), 2u);
  EXPECT_EQ(scene.root().children()[1]->name(), "Organ1");
  const Message m = error({"'Organ' is ambiguous in /root",
                           "two child nodes were named 'Organ' "
                           "(Node at line 2, Node at line 3)"});
  expectPlace(m, file, 4, "/root/counter", "TestCounter", "mstate");
}

}  // namespace
}  // namespace stroma::test
