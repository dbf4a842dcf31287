// SPDX-License-Identifier: MIT
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace stroma::cli {

/// Exit codes of every command.
enum ExitCode { kSuccess = 0, kSimulationFailure = 1, kBadInput = 2 };

/// Arguments of one command: options with values ("--dt 0.01", "-n 10"), repeatable
/// options ("--data-path A --data-path B"), flags ("--verbose") and positional arguments.
struct Arguments {
  std::vector<std::string> positional;
  std::map<std::string, std::vector<std::string>> options;
  std::vector<std::string> flags;

  bool has(const std::string& flag) const;
  const std::string* value(const std::string& option) const;  ///< the last one given
  std::vector<std::string> values(const std::string& option) const;
};

/// Parses `args` for a command that takes `valueOptions` (each followed by a value) and
/// `flagOptions`. Returns false with `error` on an unknown option or a missing value.
bool parseArguments(const std::vector<std::string>& args,
                    const std::vector<std::string>& valueOptions,
                    const std::vector<std::string>& flagOptions, Arguments& out,
                    std::string& error);

/// Reads a number option; `error` names the option on failure.
bool readInteger(const Arguments& a, const std::string& option, long long min, long long& value,
                 std::string& error);
bool readReal(const Arguments& a, const std::string& option, double& value, std::string& error);

int runCommand(const std::vector<std::string>& args);
int checkCommand(const std::vector<std::string>& args);
int stabilityCommand(const std::vector<std::string>& args);  ///< StabilityCommand.cpp
int listCommand(const std::vector<std::string>& args);
int docCommand(const std::vector<std::string>& args);
int pluginIndexCommand(const std::vector<std::string>& args);
int benchCommand(const std::vector<std::string>& args);  ///< BenchCommand.cpp
/// Runs `command` from the module lib<module>.so of the plugin folders (ModuleCommand.cpp):
/// dlopen, then `entry`(argc, argv) with the arguments after the command.
int moduleCommand(const std::string& command, const std::string& module, const std::string& entry,
                  const std::vector<std::string>& args);

/// Prints "stroma: <text>" to stderr and returns kBadInput.
int usageError(const std::string& text);

}  // namespace stroma::cli
