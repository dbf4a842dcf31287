// SPDX-License-Identifier: MIT
// `stroma list`, `stroma doc` and `stroma plugin-index`: what the plugins provide.
#include <algorithm>
#include <fstream>
#include <iostream>
#include <map>

#include "CommandLine.h"
#include "core/Link.h"
#include "core/NameSuggestions.h"
#include "core/Node.h"
#include "core/Runtime.h"

namespace stroma::cli {

int listCommand(const std::vector<std::string>& args) {
  Arguments a;
  std::string error;
  if (!parseArguments(args, {"--plugin"}, {}, a, error)) return usageError(error);
  if (!a.positional.empty()) return usageError("list takes no argument besides --plugin NAME");
  Runtime runtime;
  std::string loadErrors;
  const bool allLoaded = runtime.plugins().loadAll(loadErrors);
  std::map<std::string, std::vector<const ComponentClass*>> byPlugin;
  for (const ComponentClass* c : runtime.factory().classes()) byPlugin[c->plugin].push_back(c);
  const std::string* only = a.value("--plugin");
  const auto& index = runtime.plugins().available();
  const bool leftOut = only && std::any_of(index.begin(), index.end(), [&](const auto& e) {
                         return e.name == *only && !e.unavailable.empty();
                       });
  if (only && !byPlugin.count(*only) && !leftOut) {
    std::vector<std::string> names;
    for (const auto& [plugin, classes] : byPlugin) names.push_back(plugin);
    std::string text = "no plugin named '" + *only + "'";
    const auto near = nearestNames(*only, names);
    if (!near.empty()) text += "; did you mean " + quotedList(near) + "?";
    return usageError(text);
  }
  for (const auto& [plugin, classes] : byPlugin) {
    if (only && plugin != *only) continue;
    std::cout << plugin << '\n';
    for (const ComponentClass* c : classes) {
      std::cout << "  " << c->name;
      if (c->isTemplated()) std::cout << '<' << [&] {
        std::string t;
        for (const auto& n : c->templateNames()) {
          if (!t.empty()) t += ',';
          t += n;
        }
        return t;
      }() << '>';
      if (!c->aliases.empty()) {
        std::cout << " (also";
        for (const auto& alias : c->aliases) std::cout << ' ' << alias;
        std::cout << ')';
      }
      std::cout << ": " << c->description << '\n';
    }
  }
  // Plugins this build left out (a library they need was missing): their components by name.
  for (const PluginIndexEntry& entry : runtime.plugins().available()) {
    if (entry.unavailable.empty() || (only && entry.name != *only)) continue;
    std::cout << entry.name << " (left out of this build: " << entry.unavailable << ")\n";
    for (const std::string& component : entry.components) std::cout << "  " << component << '\n';
  }
  if (!allLoaded) {
    std::cerr << "stroma: some plugins failed to load:\n" << loadErrors << '\n';
    return kBadInput;
  }
  return kSuccess;
}

int docCommand(const std::vector<std::string>& args) {
  Arguments a;
  std::string error;
  if (!parseArguments(args, {"--template"}, {}, a, error)) return usageError(error);
  if (a.positional.size() != 1) return usageError("doc expects one component name");
  Runtime runtime;
  const std::string& name = a.positional.front();
  const std::string* templ = a.value("--template");
  std::unique_ptr<Base> object;
  const ComponentClass* c = nullptr;
  if (name == "Node") {
    object = std::make_unique<Node>("node");
  } else {
    object = runtime.create(name, templ ? *templ : "", "", error);
    if (!object) return usageError(error);
    c = runtime.factory().find(name);
  }
  if (!c) {
    std::cout << "Node\n  A node of the scene graph: child nodes, components and a context "
                 "inherited downwards.\n";
  } else {
    std::cout << c->name;
  if (!object->templateName().empty()) std::cout << " <" << object->templateName() << '>';
  std::cout << "\n  " << c->description << "\n  plugin: " << c->plugin << '\n';
  if (c->isTemplated()) {
    std::cout << "  templates:";
    for (const auto& t : c->templateNames()) std::cout << ' ' << t;
    std::cout << " (first is the default; `--template T` documents another)\n";
  }
  if (!c->aliases.empty()) {
    std::cout << "  also accepted as:";
    for (const auto& alias : c->aliases) std::cout << ' ' << alias;
    std::cout << '\n';
  }
  }
  std::cout << "\nFields:\n";
  for (const BaseData* d : object->dataFields()) {
    std::cout << "  " << d->name() << "  (" << d->typeName();
    const DataOptions& o = d->options();
    if (!o.unit.empty()) std::cout << ", unit " << o.unit;
    if (o.min || o.max) {
      std::string lo = "-inf", hi = "+inf";
      if (o.min) lo.clear(), internal::printDouble(lo, *o.min);
      if (o.max) hi.clear(), internal::printDouble(hi, *o.max);
      std::cout << ", range [" << lo << ", " << hi << "]";
    }
    if (o.output) std::cout << ", output";
    if (o.alias) std::cout << ", also '" << o.alias << "'";
    std::cout << ")\n      " << d->help() << "\n      default: ";
    const std::string def = d->defaultText();
    std::cout << (def.empty() ? "(empty)" : def) << '\n';
  }
  if (!object->links().empty()) {
    std::cout << "\nLinks:\n";
    for (const BaseLink* l : object->links())
      std::cout << "  " << l->name() << "  (link to " << l->targetTypeName() << ")\n      "
                << l->help() << '\n';
  }
  if (c && !c->sofaOptions.empty()) {
    std::cout << "\nSOFA options accepted without effect:";
    for (const auto& option : c->sofaOptions) std::cout << ' ' << option;
    std::cout << '\n';
  }
  if (c)
    std::cout << "\nAlso: template=\"...\" picks a template; src=\"@object\" takes every field of "
                 "the same name from another object (a loader).\n";
  return kSuccess;
}

int pluginIndexCommand(const std::vector<std::string>& args) {
  Arguments a;
  std::string error;
  if (!parseArguments(args, {"--output", "-o"}, {}, a, error)) return usageError(error);
  const std::string* output = a.value("--output") ? a.value("--output") : a.value("-o");
  if (a.positional.size() != 1 || !output)
    return usageError("usage: stroma plugin-index LIBRARY --output FILE");
  PluginIndexEntry entry;
  const std::filesystem::path library = std::filesystem::absolute(a.positional.front());
  if (!PluginManager::inspectLibrary(library, entry, error)) return usageError(error);
  std::ofstream out(*output);
  out << "# Stroma plugin index, written at build time by `stroma plugin-index`.\n"
      << "plugin " << entry.name << "\nlibrary " << library.filename().string() << "\nversion "
      << entry.version << "\ndescription " << entry.description << '\n';
  for (const auto& c : entry.components) out << "component " << c << '\n';
  if (!out.flush()) return usageError("cannot write " + *output);
  return kSuccess;
}

}  // namespace stroma::cli
