// SPDX-License-Identifier: MIT
// The `stroma` command: run, check and document scenes (usage texts: Usage.cpp).
#include <iostream>
#include <string>
#include <vector>

#include "CommandLine.h"
#include "Usage.h"
#include "core/NameSuggestions.h"
#include "core/Runtime.h"

int main(int argc, char** argv) {
  using namespace stroma::cli;
  std::vector<std::string> args(argv + 1, argv + argc);
  if (args.empty()) {
    std::cerr << generalUsage();
    return kBadInput;
  }
  const std::string command = args.front();
  const std::vector<std::string> rest(args.begin() + 1, args.end());
  try {
    if (command == "help" && rest.size() == 1 && !commandUsage(rest.front()).empty()) {
      std::cout << commandUsage(rest.front());
      return kSuccess;
    }
    if (command == "--help" || command == "-h" || command == "help") {
      std::cout << generalUsage();
      return kSuccess;
    }
    // `stroma COMMAND --help`: the command's own usage, before its options are parsed.
    if (const std::string usage = commandUsage(command); !usage.empty() && asksForHelp(rest)) {
      std::cout << usage;
      return kSuccess;
    }
    if (command == "--version") {
      std::cout << "stroma " << stroma::stromaVersion() << '\n';
      return kSuccess;
    }
    if (command == "run") return runCommand(rest);
    if (command == "check") return checkCommand(rest);
    if (command == "bench") return benchCommand(rest);
    if (command == "view")
      return moduleCommand("view", "StromaViewer", "stroma_viewer_main", rest);
    if (command == "render")
      return moduleCommand("render", "StromaRenderCommand", "stroma_render_main", rest);
    if (command == "list") return listCommand(rest);
    if (command == "doc") return docCommand(rest);
    if (command == "plugin-index") return pluginIndexCommand(rest);
  } catch (const std::exception& e) {
    // A bug, not bad input: say so plainly rather than abort.
    std::cerr << "stroma: internal error: " << e.what() << '\n';
    return kSimulationFailure;
  }
  std::string text = "unknown command '" + command + "'";
  std::vector<std::string> known(commandNames().begin(), commandNames().end());
  known.insert(known.end(), {"--help", "--version"});
  const auto near = stroma::nearestNames(command, known);
  if (!near.empty()) text += "; did you mean " + stroma::quotedList(near) + "?";
  return usageError(text);
}
