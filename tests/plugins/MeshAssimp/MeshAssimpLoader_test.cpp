// SPDX-License-Identifier: MIT
// MeshAssimpLoader in scenes: merged and per-mesh outputs, the loader transform, what
// src="@loader" gives a topology and a visual model, and the errors a user sees (with
// `stroma run`'s exit code).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

#include "plugins/MeshIO/SceneFixture.h"
#include "support/CliRun.h"

namespace stroma::test {
namespace {

using MeshAssimpLoaderTest = SceneFixture;

std::string shared(const std::string& name) {
  return (std::filesystem::path(STROMA_SOURCE_DIR) / "share/mesh" / name).string();
}

std::string loader(const std::string& name, const std::string& file,
                   const std::string& extra = "") {
  return "<MeshAssimpLoader name=\"" + name + "\" filename=\"" + shared(file) + "\" " + extra +
         "/>\n";
}

std::string wrap(const std::string& body) { return "<Node name=\"root\">\n" + body + "</Node>\n"; }

std::vector<double> numbers(const std::string& text) {
  std::istringstream in(text);
  std::vector<double> result;
  for (double x; in >> x;) result.push_back(x);
  return result;
}

TEST_F(MeshAssimpLoaderTest, MergedByDefaultOrOneMeshPicked) {
  ASSERT_TRUE(load(wrap(loader("all", "two_parts.gltf") +
                        loader("wedge", "two_parts.gltf", "meshName=\"wedge\"") +
                        loader("box", "two_parts.gltf", "meshName=\"box\""))))
      << messages();
  EXPECT_EQ(scene.log().count(MessageLevel::warning), 0u) << messages();
  // The box (8 points, 12 triangles) then the wedge (3, 1), its indices shifted by 8.
  EXPECT_EQ(numbers(value("/all", "position")).size(), 3u * 11);
  EXPECT_EQ(numbers(value("/box", "position")).size(), 3u * 8);
  EXPECT_EQ(numbers(value("/wedge", "position")).size(), 3u * 3);
  EXPECT_EQ(value("/all", "position"),
            value("/box", "position") + " " + value("/wedge", "position"));
  EXPECT_EQ(value("/wedge", "triangles"), "0 1 2");
  const std::string all = value("/all", "triangles");
  EXPECT_EQ(all, value("/box", "triangles") + " 8 9 10");
  // meshIndex picks the same mesh as its name does (meshNames lists them by index).
  std::istringstream names(value("/all", "meshNames"));
  std::vector<std::string> list{std::istream_iterator<std::string>(names), {}};
  ASSERT_EQ(list.size(), 2u);
  const auto wedgeIndex = std::find(list.begin(), list.end(), "wedge") - list.begin();
  ASSERT_TRUE(load(
      wrap(loader("byIndex", "two_parts.gltf", "meshIndex=\"" + std::to_string(wedgeIndex) + "\"") +
           loader("byName", "two_parts.gltf", "meshName=\"wedge\""))))
      << messages();
  EXPECT_EQ(value("/byIndex", "position"), value("/byName", "position"));
  // The wedge's own material.
  EXPECT_EQ(value("/byIndex", "color"), "0.1 0.7 0.2 1");
}

// The organ surface through the components: MeshAssimpLoader on the PLY and glTF files gives
// what MeshSTLLoader gives on the STL they were written from (the same points in the same
// order, the same triangles), and what MeshOBJLoader gives on the OBJ (its points are the
// decimal text, equal to the float32 values once rounded to float).
TEST_F(MeshAssimpLoaderTest, SameAsMeshStlAndObjLoaders) {
  ASSERT_TRUE(load(wrap(loader("ply", "organ_surface.ply") + loader("gltf", "organ_surface.gltf") +
                        "<MeshSTLLoader name=\"stl\" filename=\"" + shared("organ_surface.stl") +
                        "\"/>\n"
                        "<MeshOBJLoader name=\"obj\" filename=\"" +
                        shared("organ_surface.obj") + "\"/>\n")))
      << messages();
  EXPECT_EQ(numbers(value("/stl", "position")).size(), 3u * 643);
  for (const char* l : {"/ply", "/gltf"}) {
    EXPECT_EQ(value(l, "position"), value("/stl", "position")) << l;
    EXPECT_EQ(value(l, "triangles"), value("/stl", "triangles")) << l;
    EXPECT_EQ(value(l, "triangles"), value("/obj", "triangles")) << l;
  }
  const std::vector<double> obj = numbers(value("/obj", "position"));
  const std::vector<double> gltf = numbers(value("/gltf", "position"));
  ASSERT_EQ(obj.size(), gltf.size());
  for (std::size_t i = 0; i < obj.size(); ++i)
    EXPECT_EQ(static_cast<float>(obj[i]), static_cast<float>(gltf[i])) << i;
}

// SOFA's scenes name it AssimpLoader (SofaAssimp's examples: src into a MechanicalObject).
TEST_F(MeshAssimpLoaderTest, SofaNameAssimpLoader) {
  ASSERT_TRUE(load(wrap("<AssimpLoader name=\"sofa\" filename=\"" + shared("organ_surface.ply") +
                        "\"/>\n<MechanicalObject name=\"dofs\" src=\"@sofa\"/>\n")))
      << messages();
  EXPECT_EQ(numbers(value("/dofs", "position")).size(), 3u * 643);
}

TEST_F(MeshAssimpLoaderTest, LoaderTransformAfterTheNodeTransforms) {
  ASSERT_TRUE(load(wrap(
      loader("plain", "two_parts.gltf", "meshName=\"wedge\"") +
      loader("moved", "two_parts.gltf", "meshName=\"wedge\" scale=\"2\" translation=\"10 0 0\""))))
      << messages();
  const std::vector<double> plain = numbers(value("/plain", "position"));
  const std::vector<double> moved = numbers(value("/moved", "position"));
  ASSERT_EQ(plain.size(), moved.size());
  for (std::size_t i = 0; i < plain.size(); ++i)
    EXPECT_NEAR(moved[i], 2 * plain[i] + (i % 3 == 0 ? 10 : 0), 1e-9) << i;
}

// src="@loader": a topology takes the elements; an OglModel also the texture coordinates and
// the material's color, material text and texture file.
TEST_F(MeshAssimpLoaderTest, SrcGivesTopologyAndVisualModel) {
  ASSERT_TRUE(load(wrap(loader("box", "two_parts.gltf", "meshName=\"box\"") +
                        "<MeshTopology name=\"topology\" src=\"@box\"/>\n"
                        "<OglModel name=\"visual\" src=\"@box\"/>\n")))
      << messages();
  EXPECT_EQ(topology("/topology")->triangles().size(), 12u);
  EXPECT_EQ(value("/visual", "position"), value("/box", "position"));
  EXPECT_EQ(value("/visual", "texcoords"), value("/box", "texcoords"));
  EXPECT_EQ(numbers(value("/visual", "texcoords")).size(), 2u * 8);
  EXPECT_EQ(value("/visual", "color"), "0.8 0.1 0.1 1");
  EXPECT_EQ(value("/visual", "material").rfind("red Diffuse 1 0.8 0.1 0.1 1", 0), 0u)
      << value("/visual", "material");
  EXPECT_EQ(value("/visual", "texturename"), shared("box_texture.png"));
  EXPECT_EQ(value("/visual", "translation"), "0 0 0");  // the loader's settings stay its own
}

// A file without material (STL; PLY, where assimp makes an unnamed white one) leaves the
// visual model's default color alone.
TEST_F(MeshAssimpLoaderTest, NoMaterialNoColor) {
  ASSERT_TRUE(load(wrap(loader("stl", "organ_surface.stl") + loader("ply", "organ_surface.ply"))))
      << messages();
  for (const char* l : {"/stl", "/ply"}) {
    EXPECT_EQ(value(l, "color"), "") << l;
    EXPECT_EQ(value(l, "material"), "") << l;
  }
}

// `stroma run`: every bad input is an error naming the component, the field and the file,
// with assimp's reason where assimp gave one, and exit code 2.
TEST(MeshAssimpLoaderCli, BadInputExitsWith2) {
  TempDir dir;
  const std::string noise = dir.write("noise.xyz", "hello world\n").string();
  const std::string broken = dir.write("broken.ply",
                                       "ply\nformat ascii 1.0\nelement vertex 3\n"
                                       "property float x\nend_header\n1 2\n")
                                 .string();
  const std::string missing = (dir.path() / "missing.gltf").string();
  struct Case {
    std::string attributes;
    std::string expected;
  };
  const Case cases[] = {
      {"filename=\"" + noise + "\"", "No suitable reader found"},
      {"filename=\"" + broken + "\"", "with assimp: "},
      {"filename=\"" + missing + "\"", "missing.gltf"},
      {"filename=\"" + shared("empty_scene.gltf") + "\"", "no mesh"},
      {"filename=\"" + shared("two_parts.gltf") + "\" meshName=\"handle\"",
       "no mesh named 'handle'"},
      {"filename=\"" + shared("two_parts.gltf") + "\" meshIndex=\"5\"", "no mesh 5"},
      {"filename=\"" + shared("two_parts.gltf") + "\" meshIndex=\"-2\"", "got -2"},
      {"filename=\"" + shared("two_parts.gltf") + "\" meshIndex=\"0\" meshName=\"box\"",
       "give one of them"},
      {"filename=\"" + shared("two_parts.gltf") + "\" scale=\"1 2\"", "field 'scale'"},
  };
  for (const Case& c : cases) {
    const CliRun run = runScene(
        STROMA_CLI,
        "<Node name=\"root\"><MeshAssimpLoader name=\"mesh\" " + c.attributes + "/></Node>", 1);
    EXPECT_EQ(run.exitCode, 2) << c.attributes << "\n" << run.output;
    EXPECT_NE(run.output.find("/root/mesh (MeshAssimpLoader)"), std::string::npos) << run.output;
    EXPECT_NE(run.output.find(c.expected), std::string::npos) << run.output;
  }
  // The file is named with assimp's reason.
  const CliRun noiseRun = runScene(
      STROMA_CLI, "<Node name=\"root\"><MeshAssimpLoader filename=\"" + noise + "\"/></Node>", 1);
  EXPECT_NE(noiseRun.output.find("cannot read '" + noise + "' with assimp: No suitable reader"),
            std::string::npos)
      << noiseRun.output;
}

// The list a build without assimp writes in its index names what this build registers.
TEST(MeshAssimpLoaderCli, ComponentsFileListsTheRegisteredComponents) {
  const CliRun run = runCli(
      STROMA_CLI, "plugin-index \"" + std::string(STROMA_PLUGIN_FILE) + "\" --output /dev/stdout");
  ASSERT_EQ(run.exitCode, 0) << run.output;
  std::ifstream list(std::string(STROMA_SOURCE_DIR) + "/plugins/MeshAssimp/components.txt");
  ASSERT_TRUE(list);
  std::size_t listed = 0;
  for (std::string line; std::getline(list, line);) {
    if (line.empty() || line[0] == '#') continue;
    ++listed;
    EXPECT_NE(run.output.find("component " + line), std::string::npos) << line << run.output;
  }
  std::size_t registered = 0;
  for (std::size_t at = 0; (at = run.output.find("\ncomponent ", at)) != std::string::npos; ++at)
    ++registered;
  EXPECT_EQ(listed, registered) << run.output;
}

// The index plugins/MeshAssimp/CMakeLists.txt writes where assimp is missing
// (stroma_add_unavailable_plugin): a scene using the loader is told what to install.
TEST(MeshAssimpLoaderCli, WithoutAssimpASceneIsToldToInstallIt) {
  TempDir dir;
  dir.write("MeshAssimp.stroma-plugin",
            "plugin MeshAssimp\nunavailable it needs assimp (the Debian package libassimp-dev): "
            "install it (scripts/install-deps.sh does) and build Stroma again\n"
            "component MeshAssimpLoader\ncomponent AssimpLoader\n");
  Runtime runtime;
  runtime.plugins().setSearchPath({dir.path()});
  Scene scene(runtime);
  EXPECT_FALSE(
      scene.loadString("<Node name=\"root\"><MeshAssimpLoader name=\"mesh\" "
                       "filename=\"" +
                       shared("organ_surface.ply") + "\"/></Node>"));
  const Message m = findError(scene.log(), "MeshAssimpLoader");
  EXPECT_NE(m.text.find("is in plugin MeshAssimp, which this build left out: it needs assimp "
                        "(the Debian package libassimp-dev)"),
            std::string::npos)
      << describe(scene.log());
}

}  // namespace
}  // namespace stroma::test
