// SPDX-License-Identifier: MIT
// `stroma render` as a user runs it: bundled scenes against reference pictures, the frames it
// writes, the video pipe, and every kind of bad input refused with its message and exit code.
//
// Reference pictures: tests/plugins/Rendering/reference/*.png, compared with the tolerance of
// RenderingTestSupport.h. After a deliberate change of the drawing, regenerate them with
// tests/plugins/Rendering/update-references.sh (STROMA_UPDATE_RENDER_REFERENCES=1) and look
// at them before committing.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "RenderingTestSupport.h"
#include "core/PluginManager.h"
#include "core/Runtime.h"
#include "support/CliRun.h"

namespace stroma::test {
namespace {

namespace fs = std::filesystem;
const std::string kStroma = STROMA_CLI;
const fs::path kSource = STROMA_SOURCE_DIR;

std::string quoted(const fs::path& p) { return "\"" + p.string() + "\""; }

CliRun render(const std::string& arguments) { return runCli(kStroma, "render " + arguments); }

struct ReferenceCase {
  const char* name;       ///< reference/<name>.png
  const char* scene;      ///< under scenes/
  const char* arguments;  ///< besides the size and the output folder
  const char* frame;      ///< the frame compared
};

const ReferenceCase kReferences[] = {
    // The organ has no visual model: its FEM mesh is drawn (the fallback).
    {"organ-rest", "organ/Organ.scn", "-n 0", "frame_00000.png"},
    // Stretched under gravity, colored by displacement, with the legend.
    {"organ-displacement", "organ/Organ.scn",
     "-n 20 --color-map displacement --camera \"0 -0.1 0.6  0 -0.1 0\"", "frame_00001.png"},
    // OglModel surfaces mapped on sparse grids.
    {"sparsegrid-organ-visual", "sparsegrid/SparseGridOrgan.scn", "-n 5", "frame_00001.png"},
    // Points, fixed points and the hexahedra's edges, from a given eye.
    {"hexabeam-behavior-wireframe", "beam/HexaBeam.scn",
     "-n 10 --show \"showBehavior showWireframe\" --camera \"0.2 0.08 0.5  0.2 -0.02 0\"",
     "frame_00001.png"},
    // Collision spheres and triangles (the bowl) with the contacts of a pipeline, from above.
    {"spheres-in-bowl-collision", "collision/SpheresInBowl.scn",
     "-n 40 --show showCollisionModels --camera \"0 0.25 0.2  0 0 0\"", "frame_00001.png"},
};

TEST(RenderCommand, BundledScenesMatchTheirReferencePictures) {
  const bool update = std::getenv("STROMA_UPDATE_RENDER_REFERENCES") != nullptr;
  Runtime probe;
  const PluginIndexEntry* collision = probe.plugins().providerOf("CollisionPipeline");
  const bool hasCollision = collision && collision->unavailable.empty();
  for (const ReferenceCase& c : kReferences) {
    SCOPED_TRACE(c.name);
    if (std::string(c.scene).starts_with("collision/") && !hasCollision) {
      std::cout << "skipping " << c.name << ": this build has no Collision plugin (Bullet)\n";
      continue;
    }
    TempDir out;
    const CliRun run = render(quoted(kSource / "scenes" / c.scene) + " --size 160x120 --out " +
                              quoted(out.path()) + " " + c.arguments);
    ASSERT_EQ(run.exitCode, 0) << run.output;
    rendering::Image picture, reference;
    std::string error;
    ASSERT_TRUE(rendering::readPng(out.path() / c.frame, picture, error)) << error << run.output;
    const fs::path file =
        kSource / "tests/plugins/Rendering/reference" / (std::string(c.name) + ".png");
    if (update) {
      fs::copy_file(out.path() / c.frame, file, fs::copy_options::overwrite_existing);
      continue;
    }
    ASSERT_TRUE(rendering::readPng(file, reference, error))
        << file << ": " << error << " (update-references.sh makes it)";
    EXPECT_GE(matchingFraction(picture, reference), kMatchingFraction)
        << "more than 0.5 % of the pixels differ by more than " << kChannelTolerance
        << " levels from " << file;
  }
}

TEST(RenderCommand, WritesTheFirstFrameEveryKStepsAndTheLast) {
  TempDir out;
  const CliRun run = render(quoted(kSource / "scenes/organ/Organ.scn") +
                            " -n 5 --every 2 --size 64x48 --out " + quoted(out.path()));
  ASSERT_EQ(run.exitCode, 0) << run.output;
  // Steps 0, 2, 4 and 5.
  for (const char* name :
       {"frame_00000.png", "frame_00001.png", "frame_00002.png", "frame_00003.png"}) {
    rendering::Image image;
    std::string error;
    ASSERT_TRUE(rendering::readPng(out.path() / name, image, error)) << name << ": " << error;
    EXPECT_EQ(image.width, 64);
    EXPECT_EQ(image.height, 48);
  }
  EXPECT_FALSE(fs::exists(out.path() / "frame_00004.png"));
  EXPECT_NE(run.output.find("frame 00003: step 5"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("Rendered 4 frames of 64x48"), std::string::npos) << run.output;
}

TEST(RenderCommand, EveryBundledSceneDrawsSomething) {
  // One step of each scene of scenes/ in a small picture: never a crash, never an empty
  // picture (scenes without visual models get their FEM meshes or points).
  std::size_t rendered = 0;
  for (const auto& entry : fs::recursive_directory_iterator(kSource / "scenes")) {
    if (entry.path().extension() != ".scn") continue;
    SCOPED_TRACE(entry.path().string());
    if (runCli(kStroma, "check " + quoted(entry.path())).exitCode != 0) {
      std::cout << "skipping " << entry.path() << ": it does not load in this build\n";
      continue;
    }
    TempDir out;
    const CliRun run =
        render(quoted(entry.path()) + " -n 1 --size 32x24 --out " + quoted(out.path()));
    EXPECT_EQ(run.exitCode, 0) << run.output;
    EXPECT_EQ(run.output.find("nothing was drawn"), std::string::npos) << run.output;
    EXPECT_TRUE(fs::exists(out.path() / "frame_00001.png")) << run.output;
    ++rendered;
  }
  EXPECT_GE(rendered, 30u) << "the bundled scenes are found and load";
}

TEST(RenderCommand, AFailedStepEndsWithExitCodeOneAndThePictureOfTheFailedState) {
  // TestCounter (tests/plugins/TestPlugin) fails the step it is told to.
  TempDir dir;
  const auto scene = dir.write("fails.scn", R"(<Node name="root" dt="0.1">
      <VisualStyle displayFlags="showBehaviorModels"/>
      <TestCounter name="counter" failAtStep="3"/>
      <MechanicalObject name="dofs" position="0 0 0  1 2 3"/></Node>)");
  const std::string command = "STROMA_PLUGIN_PATH=" + quoted(testPluginDirectory()) + " " +
                              quoted(fs::path(kStroma)) + " render " + quoted(scene) +
                              " -n 10 --every 2 --size 32x24 --out " + quoted(dir.path() / "f") +
                              " > " + quoted(dir.path() / "log") + " 2>&1";
  const int status = std::system(command.c_str());
  std::ifstream in(dir.path() / "log");
  const std::string log((std::istreambuf_iterator<char>(in)), {});
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 1) << log;
  EXPECT_NE(log.find("the simulation failed at step 3"), std::string::npos) << log;
  // Frames of steps 0 and 2, then the failed step 3.
  EXPECT_NE(log.find("frame 00002: step 3"), std::string::npos) << log;
  EXPECT_TRUE(fs::exists(dir.path() / "f" / "frame_00002.png"));
  EXPECT_FALSE(fs::exists(dir.path() / "f" / "frame_00003.png"));
}

TEST(RenderCommand, AFrameThatCannotBeWrittenEndsTheRunWithExitCodeOne) {
  // A folder where the second frame's file should go (files are written on another thread
  // while the scene steps on: the failure is found at the next frame or at the end).
  TempDir out;
  fs::create_directories(out.path() / "frame_00001.png");
  const CliRun run = render(quoted(kSource / "scenes/organ/Organ.scn") +
                            " -n 3 --every 1 --size 32x24 --out " + quoted(out.path()));
  EXPECT_EQ(run.exitCode, 1) << run.output;
  EXPECT_NE(run.output.find("cannot write " + (out.path() / "frame_00001.png").string()),
            std::string::npos)
      << run.output;
  EXPECT_TRUE(fs::exists(out.path() / "frame_00000.png"));
}

TEST(RenderCommand, VonMisesColorsOfTheOrgan) {
  // TetrahedronFEMForceField is a StressField (plugins/SolidMechanics/src/CorotationalStress.h).
  TempDir out;
  const CliRun run = render(quoted(kSource / "scenes/organ/Organ.scn") +
                            " -n 5 --size 64x48 --color-map vonmises --out " + quoted(out.path()));
  ASSERT_EQ(run.exitCode, 0) << run.output;
  // "frame 00001: step 5, time 0.05 s -> ..., von Mises stress MIN to MAX Pa"
  const std::size_t at = run.output.find("frame 00001: step 5");
  ASSERT_NE(at, std::string::npos) << run.output;
  const std::size_t field = run.output.find("von Mises stress ", at);
  ASSERT_NE(field, std::string::npos) << run.output;
  std::istringstream in(run.output.substr(field + std::string("von Mises stress ").size()));
  double min = -1, max = -1;
  std::string to, unit;
  in >> min >> to >> max >> unit;
  EXPECT_EQ(to, "to");
  EXPECT_EQ(unit, "Pa");
  EXPECT_GE(min, 0.0);
  EXPECT_GT(max, min) << "the hanging organ is stressed unevenly";
}

TEST(RenderCommand, HelpExitsZero) {
  const CliRun run = render("--help");
  EXPECT_EQ(run.exitCode, 0);
  EXPECT_NE(run.output.find("stroma render SCENE"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("--color-map"), std::string::npos) << run.output;
}

TEST(RenderCommand, TheStromaProgramLinksNoOpenGL) {
  const CliRun run = runCli("/usr/bin/ldd", quoted(fs::path(kStroma)));
  ASSERT_EQ(run.exitCode, 0) << run.output;
  EXPECT_EQ(run.output.find("OSMesa"), std::string::npos) << run.output;
  EXPECT_EQ(run.output.find("libGL"), std::string::npos) << run.output;
  EXPECT_EQ(run.output.find("libpng"), std::string::npos) << run.output;
}

struct BadInput {
  const char* arguments;  ///< after the scene
  const char* message;    ///< part of what stroma says
};

TEST(RenderCommand, BadInputIsRefusedBeforeTheFirstStep) {
  TempDir dir;
  const auto aFile = dir.write("a-file", "x");
  const std::string organ = quoted(kSource / "scenes/organ/Organ.scn");
  const std::string outFlag = " --out " + quoted(dir.path() / "frames");
  const std::vector<BadInput> cases = {
      {"--size 0x0", "each side must be 1 to 16384"},
      {"--size 100000x100000", "each side must be 1 to 16384"},
      {"--size big", "WIDTHxHEIGHT"},
      {"--color-map temperature",
       "unknown color map 'temperature' (known: displacement, vonmises)"},
      {"--camera \"0 0 1\"", "expected 6 numbers"},
      {"--every 0", "--every expects an integer >= 1"},
      {"-n -3", "-n expects an integer >= 0"},
      {"--colour-map displacement", "unknown option --colour-map"},
  };
  for (const BadInput& c : cases) {
    const CliRun run = render(organ + outFlag + " " + c.arguments);
    EXPECT_EQ(run.exitCode, 2) << c.arguments << "\n" << run.output;
    EXPECT_NE(run.output.find(c.message), std::string::npos) << c.arguments << "\n" << run.output;
    EXPECT_EQ(run.output.find("frame 0"), std::string::npos) << "nothing rendered: " << run.output;
  }
  // Output folders that cannot be made or written.
  for (const fs::path& out : {aFile, aFile / "frames"}) {
    const CliRun run = render(organ + " --out " + quoted(out));
    EXPECT_EQ(run.exitCode, 2) << run.output;
    EXPECT_NE(run.output.find("--out " + out.string()), std::string::npos) << run.output;
  }
  // No scene, a missing one.
  EXPECT_EQ(render("").exitCode, 2);
  const CliRun missing = render(quoted(dir.path() / "none.scn") + outFlag);
  EXPECT_EQ(missing.exitCode, 2) << missing.output;
  EXPECT_NE(missing.output.find("none.scn"), std::string::npos) << missing.output;
}

TEST(RenderCommand, ColorMapWithNothingToColorIsRefused) {
  TempDir dir;
  const auto scene = dir.write("points.scn", R"(<Node name="root">
      <Node name="A"><MechanicalObject template="Rigid3d" position="0 0 0 0 0 0 1"/></Node></Node>)");
  for (const char* map : {"displacement", "vonmises"}) {
    const CliRun run =
        render(quoted(scene) + " -n 1 --out " + quoted(dir.path() / "f") + " --color-map " + map);
    EXPECT_EQ(run.exitCode, 2) << run.output;
    EXPECT_NE(run.output.find("--color-map"), std::string::npos) << run.output;
  }
}

TEST(RenderCommand, ASceneShowingNothingIsWarnedAboutAndStillWritten) {
  TempDir dir;
  const auto scene = dir.write("invisible.scn", R"(<Node name="root">
      <VisualStyle displayFlags="showVisual"/><MechanicalObject position="0 0 0  1 1 1"/></Node>)");
  const CliRun run = render(quoted(scene) + " -n 2 --size 32x32 --out " + quoted(dir.path() / "f"));
  EXPECT_EQ(run.exitCode, 0) << run.output;
  EXPECT_NE(run.output.find("warning: nothing was drawn in frame 0"), std::string::npos)
      << run.output;
  EXPECT_TRUE(fs::exists(dir.path() / "f" / "frame_00000.png"));
  EXPECT_TRUE(fs::exists(dir.path() / "f" / "frame_00001.png"));
}

TEST(RenderCommand, VideoWithoutFfmpegIsRefusedWithWhatToInstall) {
  TempDir dir;
  // A PATH with the shell's tools but no ffmpeg.
  const std::string command =
      "PATH=/nonexistent \"" + kStroma + "\" render " + quoted(kSource / "scenes/organ/Organ.scn") +
      " --video " + quoted(dir.path() / "a.mp4") + " > " + quoted(dir.path() / "log") + " 2>&1";
  const int status = std::system(command.c_str());
  std::ifstream in(dir.path() / "log");
  std::stringstream log;
  log << in.rdbuf();
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 2) << log.str();
  EXPECT_NE(log.str().find("ffmpeg not found: install Debian's ffmpeg"), std::string::npos)
      << log.str();
  EXPECT_FALSE(fs::exists(dir.path() / "a.mp4"));
}

TEST(RenderCommand, VideoFramesArePipedToFfmpeg) {
  // A stand-in ffmpeg that records its arguments and counts the bytes it is sent.
  TempDir dir;
  const auto fake =
      dir.write("bin/ffmpeg", "#!/bin/sh\necho \"$@\" > \"" + (dir.path() / "args").string() +
                                  "\"\nwc -c > \"" + (dir.path() / "bytes").string() + "\"\n");
  fs::permissions(fake, fs::perms::owner_all);
  const std::string command =
      "PATH=\"" + (dir.path() / "bin").string() + ":$PATH\" \"" + kStroma + "\" render " +
      quoted(kSource / "scenes/organ/Organ.scn") + " -n 4 --every 2 --size 32x24 --video " +
      quoted(dir.path() / "a.mp4") + " > " + quoted(dir.path() / "log") + " 2>&1";
  const int status = std::system(command.c_str());
  std::ifstream logIn(dir.path() / "log");
  std::stringstream log;
  log << logIn.rdbuf();
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0) << log.str();
  std::ifstream bytesIn(dir.path() / "bytes");
  long long bytes = 0;
  bytesIn >> bytes;
  EXPECT_EQ(bytes, 3LL * 32 * 24 * 3) << "frames at steps 0, 2 and 4, RGB";
  std::ifstream argsIn(dir.path() / "args");
  std::string args((std::istreambuf_iterator<char>(argsIn)), {});
  EXPECT_NE(args.find("-s 32x24"), std::string::npos) << args;
  EXPECT_NE(args.find("a.mp4"), std::string::npos) << args;
  EXPECT_FALSE(fs::exists(fs::current_path() / "frames" / "frame_00000.png"))
      << "with --video and no --out, no PNG files";
}

}  // namespace
}  // namespace stroma::test
