// SPDX-License-Identifier: MIT
// Commands whose code lives in a module of the plugin folder (`stroma render`: OSMesa), loaded
// only when the command runs, so that the stroma program and batch runs never load their
// libraries.
#include <dlfcn.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "CommandLine.h"
#include "core/PluginManager.h"

namespace stroma::cli {

namespace fs = std::filesystem;

int moduleCommand(const std::string& command, const std::string& module, const std::string& entry,
                  const std::vector<std::string>& args) {
  const std::string library = "lib" + module + ".so";
  fs::path found;
  std::string unavailable;
  for (const fs::path& dir : PluginManager::defaultSearchPath()) {
    std::error_code ec;
    if (fs::exists(dir / library, ec)) {
      found = dir / library;
      break;
    }
    // A build without the module's libraries leaves a note saying what to install.
    if (std::ifstream note(dir / (module + ".unavailable")); note && unavailable.empty()) {
      std::stringstream text;
      text << note.rdbuf();
      unavailable = text.str();
      while (!unavailable.empty() && (unavailable.back() == '\n' || unavailable.back() == ' '))
        unavailable.pop_back();
    }
  }
  if (found.empty()) {
    const std::string why =
        !unavailable.empty()
            ? unavailable
            : library + " was not found in the plugin folders (build it: ninja " + module + ")";
    std::cerr << "stroma: `stroma " << command << "` is not available in this build: " << why
              << "\n";
    return kBadInput;
  }
  void* handle = dlopen(found.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) {
    std::cerr << "stroma: cannot load " << found.string() << ": " << dlerror() << "\n";
    return kSimulationFailure;
  }
  using Entry = int (*)(int, const char* const*);
  auto main = reinterpret_cast<Entry>(dlsym(handle, entry.c_str()));
  if (!main) {
    std::cerr << "stroma: " << found.string() << " has no entry point " << entry << "\n";
    return kSimulationFailure;
  }
  std::vector<const char*> argv;
  for (const std::string& a : args) argv.push_back(a.c_str());
  argv.push_back(nullptr);
  // The module stays loaded until the process ends: its static objects may outlive the call.
  return main(static_cast<int>(args.size()), argv.data());
}

}  // namespace stroma::cli
