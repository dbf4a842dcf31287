// SPDX-License-Identifier: MIT
#include "simulation/ModelSceneWrapper.h"

#include <cctype>

namespace stroma {

namespace {

std::string escapedAttribute(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '&') out += "&amp;";
    else if (c == '<') out += "&lt;";
    else if (c == '>') out += "&gt;";
    else if (c == '"') out += "&quot;";
    else out += c;
  }
  return out;
}

}  // namespace

std::string wrapModelInScene(const std::filesystem::path& file) {
  std::string ext = file.extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (ext != ".urdf") return {};
  // The robot's file by its name alone: the scene loader looks for it in the scene's folder,
  // which is the URDF's own.
  return "<?xml version=\"1.0\"?>\n"
         "<!-- the default scene of a URDF robot (simulation/ModelSceneWrapper.cpp) -->\n"
         "<Node name=\"root\" gravity=\"0 0 -9.81\" dt=\"0.001\">\n"
         "  <EulerImplicitSolver rayleighStiffness=\"0\" rayleighMass=\"0\" />\n"
         "  <SparseLDLSolver />\n"
         "  <URDFLoader name=\"robot\" filename=\"" +
         escapedAttribute(file.filename().string()) +
         "\" />\n"
         "</Node>\n";
}

}  // namespace stroma
