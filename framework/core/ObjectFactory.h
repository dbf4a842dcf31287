// SPDX-License-Identifier: MIT
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "core/Base.h"

namespace stroma {

/// Makes one object of a registered class.
using Creator = std::function<std::unique_ptr<Base>()>;

/// A component class known to the factory: its name, aliases (SOFA's old names), what it does,
/// the plugin that provides it, and one creator per template ("Vec3d", "Rigid3d"). A class with
/// one creator registered without a template is untemplated.
struct ComponentClass {
  struct Variant {
    std::string templateName;  ///< normalized ("Vec3d"); empty for untemplated
    Creator create;
  };
  std::string name;
  std::string description;
  std::string plugin;
  std::vector<std::string> aliases;
  std::vector<Variant> variants;  ///< the first one is the default
  /// Attributes of SOFA's component that Stroma's has no use for (threading, drawing, GUI
  /// options): a scene may give them; they are accepted without effect (an info message) and
  /// listed by `stroma doc`, without crowding the component's own Data.
  std::vector<std::string> sofaOptions;

  bool isTemplated() const { return !variants.empty() && !variants.front().templateName.empty(); }
  std::vector<std::string> templateNames() const;
};

/// The canonical spelling of a template name: "Vec3" and "Vec3f" are "Vec3d", "Rigid" and
/// "Rigid3" are "Rigid3d". Stroma computes in double precision; single-precision template names
/// of SOFA scenes map to the double ones. A mapping's "In,Out" pair is normalized part by part
/// ("Rigid3,Vec3" is "Rigid3d,Vec3d").
std::string normalizeTemplateName(std::string_view name);

class ObjectFactory;

/// Builder returned by ObjectFactory::add, for one class:
///   factory.add("MechanicalObject", "Positions and velocities of a set of points")
///       .with<MechanicalObject<Vec3Types>>("Vec3d")
///       .with<MechanicalObject<Rigid3Types>>("Rigid3d");
class ComponentRegistration {
 public:
  ComponentRegistration(ObjectFactory& factory, std::string name)
      : m_factory(factory), m_name(std::move(name)) {}

  template <class T>
  ComponentRegistration& with(std::string templateName = {}) {
    static_assert(std::is_base_of_v<Base, T>, "A component class must derive from stroma::Base.");
    return addCreator(std::move(templateName), [] { return std::make_unique<T>(); });
  }
  ComponentRegistration& addCreator(std::string templateName, Creator create);
  ComponentRegistration& alias(std::string name);
  /// SOFA's attributes accepted without effect (ComponentClass::sofaOptions).
  ComponentRegistration& sofaOptions(std::vector<std::string> names);

 private:
  ObjectFactory& m_factory;
  std::string m_name;
};

/// Class name (+ template) to creator. One factory per Runtime: no process-wide registry.
/// Lookups are const and safe from several threads once registration is done.
class ObjectFactory {
 public:
  ComponentRegistration add(std::string name, std::string description, std::string plugin = {});

  /// The class registered under this name or alias, or nullptr.
  const ComponentClass* find(std::string_view nameOrAlias) const;
  /// Every class, sorted by name.
  std::vector<const ComponentClass*> classes() const;
  /// Every name and alias, for suggestions.
  std::vector<std::string> allNames() const;
  /// Forgets every class (the plugin manager does it before unloading the libraries whose
  /// code the creators are).
  void clear() {
    m_classes.clear();
    m_aliases.clear();
  }

  /// Creates an object. `templateName` is the one the scene wrote (may be empty);
  /// `contextTemplate` the template of the mechanical state in the node, used when the scene
  /// wrote none and the class has a variant for it (as SOFA deduces templates from context).
  /// On failure returns nullptr and `error` says what is available.
  std::unique_ptr<Base> create(std::string_view nameOrAlias, std::string_view templateName,
                               std::string_view contextTemplate, std::string& error) const;

 private:
  friend class ComponentRegistration;
  ComponentClass* findMutable(std::string_view name);
  std::map<std::string, ComponentClass, std::less<>> m_classes;
  std::map<std::string, std::string, std::less<>> m_aliases;  // alias -> class name
};

}  // namespace stroma
