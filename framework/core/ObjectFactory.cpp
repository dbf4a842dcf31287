// SPDX-License-Identifier: MIT
#include "core/ObjectFactory.h"

#include <algorithm>
#include <cctype>
#include <stdexcept>

#include "core/NameSuggestions.h"

namespace stroma {

std::vector<std::string> ComponentClass::templateNames() const {
  std::vector<std::string> names;
  for (const auto& v : variants)
    if (!v.templateName.empty()) names.push_back(v.templateName);
  return names;
}

std::string normalizeTemplateName(std::string_view name) {
  // A mapping's template names its input and output kinds: "Rigid3,Vec3" is "Rigid3d,Vec3d".
  if (const auto comma = name.find(','); comma != std::string_view::npos) {
    auto trimmed = [](std::string_view part) {
      while (!part.empty() && part.front() == ' ') part.remove_prefix(1);
      while (!part.empty() && part.back() == ' ') part.remove_suffix(1);
      return part;
    };
    return normalizeTemplateName(trimmed(name.substr(0, comma))) + "," +
           normalizeTemplateName(trimmed(name.substr(comma + 1)));
  }
  std::string n(name);
  if (n.size() >= 4 && n.compare(0, 3, "Vec") == 0) {
    const char last = n.back();
    if (last == 'f') n.back() = 'd';
    else if (std::isdigit(static_cast<unsigned char>(last))) n += 'd';  // "Vec3" -> "Vec3d"
    return n;  // "Vec3d", "Vec3i" unchanged
  }
  if (n == "Rigid" || n == "Rigid3" || n == "Rigid3f" || n == "Rigid3d") return "Rigid3d";
  if (n == "Rigid2" || n == "Rigid2f" || n == "Rigid2d") return "Rigid2d";
  if (n.size() > 1 && n.back() == 'f' && n.rfind("CompressedRowSparseMatrix", 0) == 0)
    n.back() = 'd';
  return n;
}

ComponentRegistration& ComponentRegistration::addCreator(std::string templateName,
                                                         Creator create) {
  ComponentClass* c = m_factory.findMutable(m_name);
  std::string normalized = templateName.empty() ? std::string() : normalizeTemplateName(templateName);
  for (const auto& v : c->variants)
    if (v.templateName == normalized)
      throw std::logic_error("component " + m_name + " registered twice with template '" +
                             normalized + "'");
  c->variants.push_back({std::move(normalized), std::move(create)});
  return *this;
}

ComponentRegistration& ComponentRegistration::alias(std::string name) {
  ComponentClass* c = m_factory.findMutable(m_name);
  c->aliases.push_back(name);
  m_factory.m_aliases[std::move(name)] = m_name;
  return *this;
}

ComponentRegistration& ComponentRegistration::sofaOptions(std::vector<std::string> names) {
  ComponentClass* c = m_factory.findMutable(m_name);
  c->sofaOptions.insert(c->sofaOptions.end(), std::make_move_iterator(names.begin()),
                        std::make_move_iterator(names.end()));
  return *this;
}

ComponentRegistration ObjectFactory::add(std::string name, std::string description,
                                         std::string plugin) {
  ComponentClass& c = m_classes[name];
  if (!c.name.empty() && c.plugin != plugin)
    throw std::logic_error("component " + name + " is provided by two plugins: " + c.plugin +
                           " and " + plugin);
  c.name = name;
  c.description = std::move(description);
  c.plugin = std::move(plugin);
  return ComponentRegistration(*this, std::move(name));
}

ComponentClass* ObjectFactory::findMutable(std::string_view name) {
  auto it = m_classes.find(name);
  return it == m_classes.end() ? nullptr : &it->second;
}

const ComponentClass* ObjectFactory::find(std::string_view nameOrAlias) const {
  if (auto it = m_classes.find(nameOrAlias); it != m_classes.end()) return &it->second;
  if (auto it = m_aliases.find(nameOrAlias); it != m_aliases.end()) {
    auto c = m_classes.find(it->second);
    if (c != m_classes.end()) return &c->second;
  }
  return nullptr;
}

std::vector<const ComponentClass*> ObjectFactory::classes() const {
  std::vector<const ComponentClass*> result;
  for (const auto& [name, c] : m_classes) result.push_back(&c);
  return result;
}

std::vector<std::string> ObjectFactory::allNames() const {
  std::vector<std::string> names;
  for (const auto& [name, c] : m_classes) names.push_back(name);
  for (const auto& [alias, target] : m_aliases) names.push_back(alias);
  return names;
}

std::unique_ptr<Base> ObjectFactory::create(std::string_view nameOrAlias,
                                            std::string_view templateName,
                                            std::string_view contextTemplate,
                                            std::string& error) const {
  const ComponentClass* c = find(nameOrAlias);
  if (!c) {
    error = "unknown component '" + std::string(nameOrAlias) + "'";
    const auto near = nearestNames(std::string(nameOrAlias), allNames());
    if (!near.empty()) error += "; did you mean " + quotedList(near) + "?";
    return nullptr;
  }
  if (c->variants.empty()) {
    error = "component '" + c->name + "' has no creator";
    return nullptr;
  }
  const ComponentClass::Variant* chosen = &c->variants.front();
  if (c->isTemplated()) {
    const std::string wanted = normalizeTemplateName(templateName);
    const std::string context = normalizeTemplateName(contextTemplate);
    const ComponentClass::Variant* byContext = nullptr;
    const ComponentClass::Variant* byScene = nullptr;
    for (const auto& v : c->variants) {
      if (!wanted.empty() && v.templateName == wanted) byScene = &v;
      if (!context.empty() && v.templateName == context) byContext = &v;
    }
    // A mapping ("In,Out") takes the kind of the state it is created beside as its output.
    if (!byContext && !context.empty())
      for (const auto& v : c->variants) {
        const auto comma = v.templateName.rfind(',');
        if (comma != std::string::npos && v.templateName.compare(comma + 1, std::string::npos,
                                                                 context) == 0) {
          byContext = &v;
          break;
        }
      }
    if (!wanted.empty() && !byScene) {
      error = "component '" + c->name + "' has no template '" + std::string(templateName) +
              "'; available: " + quotedList(c->templateNames());
      return nullptr;
    }
    chosen = byScene ? byScene : byContext ? byContext : chosen;
  }
  std::unique_ptr<Base> object = chosen->create();
  object->setClassName(c->name, chosen->templateName);
  return object;
}

}  // namespace stroma
