// SPDX-License-Identifier: MIT
// Scenes are independent: several in one process, from several threads, with their own or a
// shared Runtime; and a scene loads and unloads again and again.
#include "simulation/Scene.h"

#include <gtest/gtest.h>

#include <thread>

#include "core/PathResolver.h"
#include "core/Runtime.h"
#include "plugins/TestPlugin/TestSupport.h"

namespace stroma::test {
namespace {

/// A scene with a counter (increment `increment` per step), an engine and a mechanical state.
std::string counterScene(double dt, double increment) {
  return R"(<Node name="root" dt=")" + std::to_string(dt) + R"(">
  <DefaultAnimationLoop/>
  <TestCounter name="counter" increment=")" +
         std::to_string(increment) + R"("/>
  <Node name="Body">
    <MechanicalObject name="dofs" position="0 0 0  1 0 0"/>
    <TestEngine name="engine" input="@../counter.total"/>
  </Node>
</Node>
)";
}

std::string valueOf(const Scene& scene, const std::string& path) {
  std::string why;
  const BaseData* data = resolveDataPath(scene.root(), path, why);
  EXPECT_NE(data, nullptr) << why;
  return data ? data->valueText() : why;
}

int countOf(const Scene& scene) { return std::stoi(valueOf(scene, "@/counter.count")); }
double totalOf(const Scene& scene) { return std::stod(valueOf(scene, "@/counter.total")); }

/// What one scene ended with, to compare runs made in different ways.
struct Outcome {
  bool ok = false;
  int count = 0;
  double total = 0;
  double time = 0;
  long long steps = 0;
  std::string engineOutput;
  std::string log;
};

Outcome loadAndStep(Runtime& runtime, double dt, double increment, int steps) {
  Outcome out;
  Scene scene(runtime);
  if (!scene.loadString(counterScene(dt, increment))) {
    out.log = describe(scene.log());
    return out;
  }
  out.ok = true;
  for (int i = 0; i < steps; ++i) out.ok &= scene.step();
  out.count = countOf(scene);
  out.total = totalOf(scene);
  out.time = scene.root().time();
  out.steps = scene.stepCount();
  out.engineOutput = valueOf(scene, "@/Body/engine.output");
  out.log = describe(scene.log());
  return out;
}

void expectOutcome(const Outcome& o, double dt, double increment, int steps) {
  ASSERT_TRUE(o.ok) << o.log;
  EXPECT_EQ(o.count, steps);
  EXPECT_EQ(o.steps, steps);
  EXPECT_NEAR(o.total, increment * steps, 1e-12);
  EXPECT_NEAR(o.time, dt * steps, 1e-12);
  EXPECT_NEAR(std::stod(o.engineOutput), 2 * increment * steps, 1e-12);
}

TEST(Scene, TwoScenesStepAndUnloadIndependently) {
  Runtime runtime;
  useTestPlugins(runtime);
  Scene a(runtime), b(runtime);
  ASSERT_TRUE(a.loadString(counterScene(0.01, 1))) << describe(a.log());
  ASSERT_TRUE(b.loadString(counterScene(0.5, 2))) << describe(b.log());
  for (int i = 0; i < 3; ++i) ASSERT_TRUE(a.step());
  for (int i = 0; i < 5; ++i) ASSERT_TRUE(b.step());
  EXPECT_EQ(countOf(a), 3);
  EXPECT_EQ(countOf(b), 5);
  EXPECT_NEAR(a.root().time(), 0.03, 1e-12);
  EXPECT_NEAR(b.root().time(), 2.5, 1e-12);
  EXPECT_NEAR(totalOf(b), 10, 1e-12);

  a.unload();
  EXPECT_FALSE(a.isLoaded());
  EXPECT_FALSE(a.step());
  ASSERT_TRUE(b.step());  // the other scene goes on
  EXPECT_EQ(countOf(b), 6);
  EXPECT_NEAR(b.root().time(), 3.0, 1e-12);

  ASSERT_TRUE(a.loadString(counterScene(0.01, 1))) << describe(a.log());
  EXPECT_EQ(countOf(a), 0);
  EXPECT_EQ(a.stepCount(), 0);
  EXPECT_EQ(a.root().time(), 0.0);
}

TEST(Scene, ErrorsOfOneSceneStayInItsLog) {
  Runtime runtime;
  useTestPlugins(runtime);
  Scene good(runtime), bad(runtime);
  ASSERT_TRUE(good.loadString(counterScene(0.01, 1))) << describe(good.log());
  EXPECT_FALSE(bad.loadString(R"(<Node><TestCounter failAtStep="x"/></Node>)"));
  EXPECT_EQ(good.log().errorCount(), 0u);
  EXPECT_EQ(bad.log().errorCount(), 1u);
}

TEST(Scene, StepReportsAnErrorLoggedDuringTheStep) {
  Runtime runtime;
  useTestPlugins(runtime);
  Scene scene(runtime);
  ASSERT_TRUE(
      scene.loadString(R"(<Node name="root"><TestCounter name="c" failAtStep="2"/></Node>)"))
      << describe(scene.log());
  EXPECT_TRUE(scene.step());
  EXPECT_FALSE(scene.step());
  const Message m = findError(scene.log(), "failing at step 2");
  EXPECT_EQ(m.componentPath, "/root/c");
  EXPECT_EQ(m.field, "failAtStep");
  EXPECT_EQ(m.where.line, 1);
  EXPECT_TRUE(scene.step());  // no new error at step 3
}

TEST(Scene, StepUsesTheGivenTimeStepOrTheRootOne) {
  Runtime runtime;
  useTestPlugins(runtime);
  Scene scene(runtime);
  ASSERT_TRUE(scene.loadString(counterScene(0.25, 1))) << describe(scene.log());
  ASSERT_TRUE(scene.step());
  ASSERT_TRUE(scene.step(0.5));
  EXPECT_NEAR(scene.root().time(), 0.75, 1e-12);
  EXPECT_NEAR(std::stod(valueOf(scene, "@/counter.elapsed")), 0.75, 1e-12);
}

TEST(Scene, ThreadsWithTheirOwnRuntimeAreIndependent) {
  Outcome first, second;
  std::thread a([&] {
    Runtime runtime;
    useTestPlugins(runtime);
    first = loadAndStep(runtime, 0.01, 1, 200);
  });
  std::thread b([&] {
    Runtime runtime;
    useTestPlugins(runtime);
    second = loadAndStep(runtime, 0.02, 3, 150);
  });
  a.join();
  b.join();
  expectOutcome(first, 0.01, 1, 200);
  expectOutcome(second, 0.02, 3, 150);
}

TEST(Scene, ThreadsSharingOneRuntimeAreIndependent) {
  // The first scenes load the plugins while the other thread does the same.
  for (int round = 0; round < 3; ++round) {
    Runtime runtime;
    useTestPlugins(runtime);
    Outcome first, second;
    std::thread a([&] { first = loadAndStep(runtime, 0.01, 1, 200); });
    std::thread b([&] { second = loadAndStep(runtime, 0.02, 3, 150); });
    a.join();
    b.join();
    expectOutcome(first, 0.01, 1, 200);
    expectOutcome(second, 0.02, 3, 150);
    EXPECT_TRUE(runtime.plugins().isLoaded("StromaTestPlugin"));
  }
}

TEST(Scene, ManyScenesFromManyThreadsOnOneRuntime) {
  Runtime runtime;
  useTestPlugins(runtime);
  constexpr int kThreads = 4;
  std::vector<Outcome> outcomes(kThreads);
  std::vector<std::thread> threads;
  for (int t = 0; t < kThreads; ++t)
    threads.emplace_back([&, t] {
      for (int repeat = 0; repeat < 5; ++repeat)
        outcomes[t] = loadAndStep(runtime, 0.01 * (t + 1), t + 1, 20 + t);
    });
  for (auto& thread : threads) thread.join();
  for (int t = 0; t < kThreads; ++t) expectOutcome(outcomes[t], 0.01 * (t + 1), t + 1, 20 + t);
}

TEST(Scene, LoadsAndUnloadsAHundredTimes) {
  Runtime runtime;
  useTestPlugins(runtime);
  Scene scene(runtime);
  for (int i = 0; i < 100; ++i) {
    ASSERT_TRUE(scene.loadString(counterScene(0.01, 1))) << "round " << i << '\n'
                                                         << describe(scene.log());
    ASSERT_TRUE(scene.step());
    ASSERT_TRUE(scene.step());
    ASSERT_EQ(countOf(scene), 2) << "round " << i;  // a fresh graph each time
    ASSERT_NEAR(scene.root().time(), 0.02, 1e-12);
    if (i % 2) scene.unload();  // and loading over a loaded scene unloads it first
  }
  scene.unload();
  EXPECT_FALSE(scene.isLoaded());
  EXPECT_EQ(scene.log().errorCount(), 0u);
  EXPECT_EQ(runtime.plugins().loadedPlugins().size(), 3u);  // loaded once, not per scene
}

TEST(Scene, SceneFileThatCannotBeOpenedIsReported) {
  Runtime runtime;
  Scene scene(runtime);
  EXPECT_FALSE(scene.loadFile("/nonexistent/scene.scn"));
  const Message m = findError(scene.log(), "cannot open scene file");
  EXPECT_EQ(m.where.file, "/nonexistent/scene.scn");
}

}  // namespace
}  // namespace stroma::test
