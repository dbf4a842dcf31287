// SPDX-License-Identifier: MIT
#pragma once

#include <string>
#include <string_view>

#include "core/Base.h"

namespace stroma {

/// A named pointer from a component to another object, set in a scene by path:
/// `@../dofs`, `@/A/B`, `@name` (see PathResolver.h). Resolved after the whole graph exists.
class BaseLink {
 public:
  BaseLink(Base* owner, std::string name, std::string help);
  virtual ~BaseLink() = default;
  BaseLink(const BaseLink&) = delete;
  BaseLink& operator=(const BaseLink&) = delete;

  const std::string& name() const { return m_name; }
  const std::string& help() const { return m_help; }
  Base* owner() const { return m_owner; }

  /// The path written in the scene ("@../dofs"), empty when the link was not given.
  const std::string& path() const { return m_path; }
  void setPath(std::string path) { m_path = std::move(path); }

  /// What the target must be, for messages and `stroma doc` ("a mechanical state").
  virtual std::string targetTypeName() const = 0;
  virtual Base* targetBase() const = 0;
  /// Points the link at `target` when it has the right type; otherwise says what it is.
  virtual bool setTarget(Base* target, std::string& error) = 0;

 private:
  Base* m_owner;
  std::string m_name;
  std::string m_help;
  std::string m_path;
};

namespace internal {
std::string demangledName(const char* mangled);
}

template <class T>
class Link final : public BaseLink {
 public:
  Link(Base* owner, std::string name, std::string help)
      : BaseLink(owner, std::move(name), std::move(help)) {}

  T* get() const { return m_target; }
  T* operator->() const { return m_target; }
  explicit operator bool() const { return m_target != nullptr; }
  void set(T* target) { m_target = target; }

  std::string targetTypeName() const override {
    return internal::demangledName(typeid(T).name());
  }
  Base* targetBase() const override { return dynamic_cast<Base*>(m_target); }
  bool setTarget(Base* target, std::string& error) override {
    if (!target) {
      m_target = nullptr;
      return true;
    }
    T* typed = dynamic_cast<T*>(target);
    if (!typed) {
      error = target->path() + " is a " + target->className() + ", not a " + targetTypeName();
      return false;
    }
    m_target = typed;
    return true;
  }

 private:
  T* m_target = nullptr;
};

}  // namespace stroma
