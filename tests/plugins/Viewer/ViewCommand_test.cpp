// SPDX-License-Identifier: MIT
// `stroma view` run as a user runs it (applications/stroma/ViewCommand.cpp and the viewer
// module it opens).
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "support/CliRun.h"

namespace stroma::test {
namespace {

const std::string kScene = STROMA_SOURCE_DIR "/scenes/beam/HexaBeam.scn";

TEST(ViewCommand, HelpListsTheKeysAndTheMouse) {
  const CliRun run = runCli(STROMA_CLI, "view --help");
  EXPECT_EQ(run.exitCode, 0) << run.output;
  for (const char* control : {"left drag", "right or middle drag", "wheel", "shift + left",
                              "space", "n or right arrow", "r ", "q or escape", "--size"})
    EXPECT_NE(run.output.find(control), std::string::npos) << control << "\n" << run.output;
}

TEST(ViewCommand, WithoutADisplayItSaysSoAndFails) {
  const CliRun run =
      runCli("env", "-u DISPLAY -u WAYLAND_DISPLAY \"" STROMA_CLI "\" view \"" + kScene + "\"");
  EXPECT_EQ(run.exitCode, 2) << run.output;
  EXPECT_NE(run.output.find("no display"), std::string::npos) << run.output;
  // A display that cannot be opened: GLFW's reason.
  const CliRun closed =
      runCli("env", "DISPLAY=:7777 \"" STROMA_CLI "\" view \"" + kScene + "\"");
  EXPECT_EQ(closed.exitCode, 2) << closed.output;
  EXPECT_NE(closed.output.find("cannot start GLFW"), std::string::npos) << closed.output;
}

TEST(ViewCommand, BadArgumentsAreUsageErrors) {
  for (const std::string& args : std::vector<std::string>{
           "view", "view /no/such/scene.scn", "view \"" + kScene + "\" --size 0x100",
        "view \"" + kScene + "\" --size 100000x100", "view \"" + kScene + "\" --size wide",
        "view \"" + kScene + "\" --spring-stiffness -3"}) {
    const CliRun run = runCli(STROMA_CLI, args);
    EXPECT_EQ(run.exitCode, 2) << args << "\n" << run.output;
    EXPECT_NE(run.output.find("stroma"), std::string::npos) << run.output;
  }
}

// The stroma program opens the viewer module only for `stroma view`: it links neither GLFW nor
// OpenGL (DESIGN.md section 8: a batch run never loads them).
TEST(ViewCommand, TheStromaProgramLinksNoWindowOrOpenGLLibrary) {
  const CliRun ldd = runCli("ldd", "\"" STROMA_CLI "\"");
  if (ldd.exitCode != 0) GTEST_SKIP() << "ldd is not available: " << ldd.output;
  EXPECT_EQ(ldd.output.find("libglfw"), std::string::npos) << ldd.output;
  EXPECT_EQ(ldd.output.find("libGL"), std::string::npos) << ldd.output;
  EXPECT_EQ(ldd.output.find("libOSMesa"), std::string::npos) << ldd.output;
}

// The whole path (module found, opened, scene loaded, frames drawn while running, quit),
// when this test runs with a display (ctest gives it one through xvfb-run).
TEST(ViewCommand, RunsASceneForSomeFramesAndQuits) {
  const char* display = std::getenv("DISPLAY");
  if (!display || !*display) GTEST_SKIP() << "no DISPLAY (ctest runs this under xvfb-run)";
  const CliRun run =
      runCli(STROMA_CLI, "view \"" + kScene + "\" --size 200x150 --animate --frames 20");
  EXPECT_EQ(run.exitCode, 0) << run.output;
}

// A scene that does not load: its errors, exit code 2, and no window left behind.
TEST(ViewCommand, ASceneWithErrorsIsRefused) {
  const char* display = std::getenv("DISPLAY");
  if (!display || !*display) GTEST_SKIP() << "no DISPLAY (ctest runs this under xvfb-run)";
  TempDir dir;
  const auto scene = dir.write("bad.scn", R"(<Node name="root">
    <MechanicalObjekt name="dofs" position="0 0 0"/>
  </Node>)");
  const CliRun run = runCli(STROMA_CLI, "view \"" + scene.string() + "\" --frames 1");
  EXPECT_EQ(run.exitCode, 2) << run.output;
  EXPECT_NE(run.output.find("MechanicalObjekt"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("the scene was not shown"), std::string::npos) << run.output;
}

}  // namespace
}  // namespace stroma::test
