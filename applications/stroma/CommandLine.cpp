// SPDX-License-Identifier: MIT
#include "CommandLine.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <iostream>

#include "core/NameSuggestions.h"

namespace stroma::cli {

bool Arguments::has(const std::string& flag) const {
  return std::find(flags.begin(), flags.end(), flag) != flags.end();
}

const std::string* Arguments::value(const std::string& option) const {
  auto it = options.find(option);
  return it == options.end() || it->second.empty() ? nullptr : &it->second.back();
}

std::vector<std::string> Arguments::values(const std::string& option) const {
  auto it = options.find(option);
  return it == options.end() ? std::vector<std::string>() : it->second;
}

bool parseArguments(const std::vector<std::string>& args,
                    const std::vector<std::string>& valueOptions,
                    const std::vector<std::string>& flagOptions, Arguments& out,
                    std::string& error) {
  auto contains = [](const std::vector<std::string>& v, const std::string& s) {
    return std::find(v.begin(), v.end(), s) != v.end();
  };
  for (std::size_t i = 0; i < args.size(); ++i) {
    std::string arg = args[i];
    std::string inlineValue;
    bool hasInline = false;
    if (arg.rfind("--", 0) == 0) {
      if (auto eq = arg.find('='); eq != std::string::npos) {
        inlineValue = arg.substr(eq + 1);
        arg = arg.substr(0, eq);
        hasInline = true;
      }
    }
    if (arg.size() > 1 && arg[0] == '-' && !(std::isdigit(static_cast<unsigned char>(arg[1])))) {
      if (contains(valueOptions, arg)) {
        if (!hasInline && i + 1 >= args.size()) {
          error = "option " + arg + " needs a value";
          return false;
        }
        out.options[arg].push_back(hasInline ? inlineValue : args[++i]);
      } else if (contains(flagOptions, arg) && !hasInline) {
        out.flags.push_back(arg);
      } else {
        std::vector<std::string> known = valueOptions;
        known.insert(known.end(), flagOptions.begin(), flagOptions.end());
        error = "unknown option " + arg;
        const auto near = nearestNames(arg, known);
        if (!near.empty()) error += "; did you mean " + quotedList(near) + "?";
        return false;
      }
    } else {
      out.positional.push_back(arg);
    }
  }
  return true;
}

bool readInteger(const Arguments& a, const std::string& option, long long min, long long& value,
                 std::string& error) {
  const std::string* text = a.value(option);
  if (!text) return true;
  auto [ptr, ec] = std::from_chars(text->data(), text->data() + text->size(), value);
  if (ec != std::errc() || ptr != text->data() + text->size() || value < min) {
    error = "option " + option + " expects an integer >= " + std::to_string(min) + ", got '" +
            *text + "'";
    return false;
  }
  return true;
}

bool readReal(const Arguments& a, const std::string& option, double& value, std::string& error) {
  const std::string* text = a.value(option);
  if (!text) return true;
  auto [ptr, ec] = std::from_chars(text->data(), text->data() + text->size(), value);
  if (ec != std::errc() || ptr != text->data() + text->size() || !std::isfinite(value) ||
      value <= 0) {
    error = "option " + option + " expects a positive number, got '" + *text + "'";
    return false;
  }
  return true;
}

int usageError(const std::string& text) {
  std::cerr << "stroma: " << text << "\n(see stroma --help)\n";
  return kBadInput;
}

}  // namespace stroma::cli
