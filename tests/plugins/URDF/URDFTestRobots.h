// SPDX-License-Identifier: MIT
// What the URDF tests share: the 2-link planar arm as URDF text (two links of length L swinging
// about y, gravity along -z, masses as point-like rods), a temporary folder to write it in, and
// the scene that loads it.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <string>

#include "core/Runtime.h"
#include "plugins/Mapping/MappingChecks.h"
#include "simulation/Scene.h"

namespace stroma::test {

/// A fresh folder, removed at the end.
class RobotFolder {
 public:
  RobotFolder() {
    static std::atomic<int> counter{0};
    m_path = std::filesystem::temp_directory_path() /
             ("stroma-urdf-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
    std::filesystem::create_directories(m_path);
  }
  ~RobotFolder() {
    std::error_code ignored;
    std::filesystem::remove_all(m_path, ignored);
  }
  std::filesystem::path write(const std::string& name, const std::string& text) const {
    std::ofstream(m_path / name, std::ios::binary) << text;
    return m_path / name;
  }
  const std::filesystem::path& path() const { return m_path; }

 private:
  std::filesystem::path m_path;
};

struct ArmOptions {
  double length = 0.5;         // of each link, m
  double mass = 1.0;           // of each link, kg, at the link's middle
  double inertia = 0.0;        // about the link's y axis through its center, kg m^2
  std::string joint1Extra;     // more elements in joint 1 (limit, dynamics)
  std::string joint1Type = "continuous";
  bool secondLink = true;
  double baseMass = 0;         // of base_link, at its origin, with an inertia of 0.01 kg m^2
};

/// The arm: base_link fixed at the origin; joint1 (about y) at the origin moves link1; joint2
/// (about y) at link1's end moves link2. At q = 0 both links point along +x. A rotation by q
/// about y turns +x toward -z, so link1's end is L (cos q1, 0, -sin q1).
inline std::string twoLinkArm(const ArmOptions& o = {}) {
  const std::string L = std::to_string(o.length);
  const std::string half = std::to_string(o.length / 2);
  auto link = [&](const std::string& name) {
    const std::string I = std::to_string(o.inertia);
    return "  <link name=\"" + name + "\"><inertial><origin xyz=\"" + half +
           " 0 0\"/><mass value=\"" + std::to_string(o.mass) + "\"/><inertia ixx=\"" +
           (o.inertia > 0 ? I : "1e-9") + "\" ixy=\"0\" ixz=\"0\" iyy=\"" +
           (o.inertia > 0 ? I : "1e-9") + "\" iyz=\"0\" izz=\"" +
           (o.inertia > 0 ? I : "1e-9") + "\"/></inertial></link>\n";
  };
  std::string base = "  <link name=\"base_link\"/>\n";
  if (o.baseMass > 0)
    base = "  <link name=\"base_link\"><inertial><mass value=\"" + std::to_string(o.baseMass) +
           "\"/><inertia ixx=\"0.01\" ixy=\"0\" ixz=\"0\" iyy=\"0.01\" iyz=\"0\" "
           "izz=\"0.01\"/></inertial></link>\n";
  std::string text = "<?xml version=\"1.0\"?>\n<robot name=\"arm\">\n" + base + link("link1");
  text += "  <joint name=\"joint1\" type=\"" + o.joint1Type +
          "\"><parent link=\"base_link\"/><child link=\"link1\"/><origin xyz=\"0 0 0\"/>"
          "<axis xyz=\"0 1 0\"/>" +
          o.joint1Extra + "</joint>\n";
  if (o.secondLink) {
    text += link("link2");
    text += "  <joint name=\"joint2\" type=\"continuous\"><parent link=\"link1\"/><child "
            "link=\"link2\"/><origin xyz=\"" +
            L + " 0 0\"/><axis xyz=\"0 1 0\"/></joint>\n";
  }
  return text + "</robot>\n";
}

/// A scene with gravity along -z, the given solver lines and a URDFLoader of `urdf` (written in
/// `folder` as robot.urdf, with `loaderAttributes`), plus `extra` in the loader's node.
inline std::string armScene(const RobotFolder& folder, const std::string& urdf,
                            const std::string& solvers, const std::string& extra = "",
                            const std::string& gravity = "0 0 -9.81",
                            const std::string& loaderAttributes = "") {
  folder.write("robot.urdf", urdf);
  return "<Node name=\"root\" gravity=\"" + gravity + "\" dt=\"0.001\">\n" + solvers +
         "\n<URDFLoader name=\"loader\" filename=\"robot.urdf\" " + loaderAttributes +
         "/>\n" + extra + "</Node>\n";
}

inline bool loadArm(Scene& scene, const RobotFolder& folder, const std::string& xml) {
  return scene.loadString(xml, folder.path() / "scene.scn");
}

}  // namespace stroma::test
