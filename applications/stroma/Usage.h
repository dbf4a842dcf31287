// SPDX-License-Identifier: MIT
// The usage text of every `stroma` command, in one place: `stroma --help` prints them all,
// `stroma COMMAND --help` (or -h) the command's own.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace stroma::cli {

/// The names of the commands, in the order `stroma --help` lists them.
const std::vector<std::string_view>& commandNames();

/// The whole help: every command, the options shared by run and check, exit codes.
std::string generalUsage();

/// One command's usage, with the shared options it takes and the exit codes; empty for an
/// unknown command.
std::string commandUsage(std::string_view command);

/// Whether the arguments after the command ask for its help ("--help" or "-h" anywhere).
bool asksForHelp(const std::vector<std::string>& args);

}  // namespace stroma::cli
