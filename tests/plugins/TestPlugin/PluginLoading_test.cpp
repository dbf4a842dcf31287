// SPDX-License-Identifier: MIT
// Plugin loading: on demand from the index, refusal of foreign libraries, search path.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <optional>

#include "core/Base.h"
#include "core/Plugin.h"
#include "core/Runtime.h"
#include "plugins/TestPlugin/TestSupport.h"
#include "simulation/Scene.h"

namespace stroma::test {
namespace {

bool contains(const std::vector<std::string>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

TEST(PluginLoading, SceneLoadsOnlyThePluginsOfItsComponents) {
  Runtime runtime;
  useTestPlugins(runtime);
  Scene scene(runtime);
  ASSERT_TRUE(scene.loadString(R"(<Node name="root"><TestCounter name="counter"/></Node>)"))
      << describe(scene.log());
  EXPECT_EQ(runtime.plugins().loadedPlugins(), std::vector<std::string>{"StromaTestPlugin"});
  EXPECT_FALSE(runtime.plugins().isLoaded("Visual"));
  EXPECT_FALSE(runtime.plugins().isLoaded("StateContainer"));
  EXPECT_FALSE(runtime.plugins().isLoaded("SceneBasics"));
}

TEST(PluginLoading, SecondSceneLoadsTheMissingPluginOnly) {
  Runtime runtime;
  useTestPlugins(runtime);
  Scene first(runtime);
  ASSERT_TRUE(first.loadString(R"(<Node><TestCounter/></Node>)")) << describe(first.log());
  Scene second(runtime);
  ASSERT_TRUE(
      second.loadString(R"(<Node><TestCounter/><MechanicalObject position="0 0 0"/></Node>)"))
      << describe(second.log());
  EXPECT_EQ(runtime.plugins().loadedPlugins(),
            (std::vector<std::string>{"StromaTestPlugin", "StateContainer"}));
}

TEST(PluginLoading, IndexListsClassesAndAliases) {
  Runtime runtime;
  useTestPlugins(runtime);
  const PluginIndexEntry* entry = runtime.plugins().providerOf("TestCounter");
  ASSERT_NE(entry, nullptr);
  EXPECT_EQ(entry->name, "StromaTestPlugin");
  EXPECT_EQ(entry->version, "0.1.0");
  EXPECT_TRUE(entry->library.is_absolute()) << entry->library;
  for (const char* name : {"TestCounter", "LegacyTestCounter", "TestEngine", "TestLoader",
                           "TestTemplated", "TestInitCheck"})
    EXPECT_TRUE(contains(entry->components, name)) << name;
  EXPECT_EQ(runtime.plugins().providerOf("LegacyTestCounter"), entry);
  EXPECT_EQ(runtime.plugins().providerOf("NoSuchComponent"), nullptr);
  // Reading the index loads nothing.
  EXPECT_TRUE(runtime.plugins().loadedPlugins().empty());
}

TEST(PluginLoading, RequiredPluginIsAcceptedButLoadsNothing) {
  Runtime runtime;
  useTestPlugins(runtime);
  Scene scene(runtime);
  ASSERT_TRUE(scene.loadString(R"(<Node name="root">
    <RequiredPlugin name="Sofa.Component.StateContainer"/>
    <RequiredPlugin pluginName="Visual StateContainer"/>
    <RequiredPlugin name="declared" pluginName="NoSuchPluginAnywhere"/>
    <TestCounter/>
  </Node>)"))
      << describe(scene.log());
  EXPECT_EQ(scene.log().count(MessageLevel::warning), 0u) << describe(scene.log());
  // RequiredPlugin itself comes from SceneBasics; the plugins it names are not loaded.
  const std::vector<std::string> loaded = runtime.plugins().loadedPlugins();
  EXPECT_TRUE(contains(loaded, "SceneBasics"));
  EXPECT_TRUE(contains(loaded, "StromaTestPlugin"));
  EXPECT_FALSE(contains(loaded, "StateContainer"));
  EXPECT_FALSE(contains(loaded, "Visual"));
  bool toldNotNeeded = false;
  for (const Message& m : scene.log().messages())
    toldNotNeeded |= m.componentClass == "RequiredPlugin" &&
                     m.text.find("not needed") != std::string::npos &&
                     m.text.find("Sofa.Component.StateContainer") != std::string::npos;
  EXPECT_TRUE(toldNotNeeded) << describe(scene.log());
}

TEST(PluginLoading, RefusesALibraryBuiltForAnotherAbi) {
  Runtime runtime;
  useTestPlugins(runtime);
  std::string error;
  EXPECT_FALSE(runtime.plugins().load(STROMA_TEST_WRONG_ABI_LIBRARY, error));
  EXPECT_NE(error.find(STROMA_TEST_WRONG_ABI_LIBRARY), std::string::npos) << error;
  EXPECT_NE(error.find("plugin ABI"), std::string::npos) << error;
  EXPECT_NE(error.find("plugin ABI " + std::to_string(kPluginAbiVersion + 100)), std::string::npos)
      << error;
  EXPECT_NE(error.find("this Stroma " + std::to_string(kPluginAbiVersion)), std::string::npos)
      << error;
  EXPECT_TRUE(runtime.plugins().loadedPlugins().empty());
  EXPECT_TRUE(runtime.factory().classes().empty());

  PluginIndexEntry entry;
  error.clear();
  EXPECT_FALSE(PluginManager::inspectLibrary(STROMA_TEST_WRONG_ABI_LIBRARY, entry, error));
  EXPECT_NE(error.find("plugin ABI"), std::string::npos) << error;
}

TEST(PluginLoading, RefusesALibraryWithoutEntryPoint) {
  Runtime runtime;
  useTestPlugins(runtime);
  std::string error;
  EXPECT_FALSE(runtime.plugins().load(STROMA_TEST_NO_ENTRY_LIBRARY, error));
  EXPECT_NE(error.find(STROMA_TEST_NO_ENTRY_LIBRARY), std::string::npos) << error;
  EXPECT_NE(error.find("not a Stroma plugin"), std::string::npos) << error;
  EXPECT_NE(error.find("stroma_plugin_entry"), std::string::npos) << error;
  EXPECT_TRUE(runtime.plugins().loadedPlugins().empty());
}

TEST(PluginLoading, ReportsALibraryThatDoesNotExist) {
  Runtime runtime;
  std::string error;
  EXPECT_FALSE(runtime.plugins().load("/nonexistent/libNothing.so", error));
  EXPECT_NE(error.find("/nonexistent/libNothing.so"), std::string::npos) << error;
  EXPECT_NE(error.find("does not exist"), std::string::npos) << error;
}

TEST(PluginLoading, UnknownPluginNameShowsTheSearchPath) {
  Runtime runtime;
  useTestPlugins(runtime);
  std::string error;
  EXPECT_FALSE(runtime.plugins().load("NoSuchPlugin", error));
  EXPECT_NE(error.find("no plugin named 'NoSuchPlugin'"), std::string::npos) << error;
  EXPECT_NE(error.find(testPluginDirectory().string()), std::string::npos) << error;
  EXPECT_NE(error.find("STROMA_PLUGIN_PATH"), std::string::npos) << error;
}

TEST(PluginLoading, LoadingTwiceByNameOrPathIsANoOp) {
  Runtime runtime;
  useTestPlugins(runtime);
  std::string error;
  ASSERT_TRUE(runtime.plugins().load("StromaTestPlugin", error)) << error;
  ASSERT_TRUE(runtime.plugins().load("StromaTestPlugin", error)) << error;
  const PluginIndexEntry* entry = runtime.plugins().providerOf("TestCounter");
  ASSERT_NE(entry, nullptr);
  ASSERT_TRUE(runtime.plugins().load(entry->library.string(), error)) << error;
  EXPECT_EQ(runtime.plugins().loadedPlugins(), std::vector<std::string>{"StromaTestPlugin"});
  const ComponentClass* counter = runtime.factory().find("TestCounter");
  ASSERT_NE(counter, nullptr);
  EXPECT_EQ(counter->plugin, "StromaTestPlugin");
  EXPECT_EQ(runtime.factory().find("LegacyTestCounter"), counter);
}

/// Sets an environment variable for the lifetime of the object, then restores it.
class ScopedEnvironment {
 public:
  ScopedEnvironment(const char* name, const std::string& value) : m_name(name) {
    if (const char* old = std::getenv(name)) m_old = old;
    ::setenv(name, value.c_str(), 1);
  }
  ~ScopedEnvironment() {
    if (m_old)
      ::setenv(m_name, m_old->c_str(), 1);
    else
      ::unsetenv(m_name);
  }

 private:
  const char* m_name;
  std::optional<std::string> m_old;
};

TEST(PluginLoading, HonoursStromaPluginPath) {
  {
    ScopedEnvironment path("STROMA_PLUGIN_PATH",
                           "/nonexistent/stroma-plugins:" + testPluginDirectory().string());
    Runtime runtime;  // reads the variable when constructed
    const auto& dirs = runtime.plugins().searchPath();
    ASSERT_GE(dirs.size(), 2u);
    EXPECT_EQ(dirs[0], "/nonexistent/stroma-plugins");
    EXPECT_EQ(dirs[1], testPluginDirectory());
    Scene scene(runtime);
    EXPECT_TRUE(scene.loadString(R"(<Node><TestCounter/></Node>)")) << describe(scene.log());
    EXPECT_TRUE(runtime.plugins().isLoaded("StromaTestPlugin"));
  }
  ::unsetenv("STROMA_PLUGIN_PATH");
  Runtime runtime;  // without the variable the test plugin is not found
  Scene scene(runtime);
  EXPECT_FALSE(scene.loadString(R"(<Node><TestCounter/></Node>)"));
  EXPECT_NE(findError(scene.log(), "unknown component 'TestCounter'").text, "")
      << describe(scene.log());
}

TEST(PluginLoading, RuntimesCanBeMadeAndDestroyedRepeatedly) {
  // Creating and destroying runtimes (each dlopens and dlcloses the plugin) is repeatable.
  for (int i = 0; i < 5; ++i) {
    Runtime runtime;
    useTestPlugins(runtime);
    Scene scene(runtime);
    ASSERT_TRUE(scene.loadString(R"(<Node><TestCounter/><TestEngine input="1 2"/></Node>)"))
        << describe(scene.log());
    ASSERT_TRUE(scene.step());
  }
}

}  // namespace
}  // namespace stroma::test
