// SPDX-License-Identifier: MIT
#include "core/Base.h"

#include <cxxabi.h>

#include <cstdlib>

#include "core/Link.h"
#include "core/Node.h"

namespace stroma {

namespace internal {

void registerData(Base* owner, BaseData* data) { owner->m_data.push_back(data); }

std::string demangledName(const char* mangled) {
  int status = 0;
  char* text = abi::__cxa_demangle(mangled, nullptr, nullptr, &status);
  std::string result = status == 0 && text ? text : mangled;
  std::free(text);
  if (result.rfind("stroma::", 0) == 0) result.erase(0, 8);
  return result;
}

}  // namespace internal

Base::Base() = default;
Base::~Base() = default;

void Base::setClassName(std::string className, std::string templateName) {
  m_className = std::move(className);
  m_templateName = std::move(templateName);
}

std::string Base::path() const {
  std::string prefix = m_node ? m_node->path() : std::string();
  if (prefix == "/") prefix.clear();
  return prefix + "/" + name();
}

BaseData* Base::findData(std::string_view name) const {
  for (BaseData* d : m_data)
    if (d->name() == name) return d;
  for (BaseData* d : m_data)
    if (d->options().alias && name == d->options().alias) return d;
  return nullptr;
}

BaseLink* Base::findLink(std::string_view name) const {
  for (BaseLink* l : m_links)
    if (l->name() == name) return l;
  return nullptr;
}

MessageLog& Base::messageLog() const {
  if (m_node) {
    if (MessageLog* log = m_node->sceneLog()) return *log;
  } else if (auto* self = dynamic_cast<const Node*>(this)) {
    if (MessageLog* log = self->sceneLog()) return *log;
  }
  if (!m_ownLog) m_ownLog = std::make_unique<MessageLog>();
  return *m_ownLog;
}

void Base::send(MessageLevel level, std::string text, std::string field, bool failsRun) const {
  Message m;
  m.level = level;
  m.failsRun = failsRun;
  m.text = std::move(text);
  m.componentPath = path();
  m.componentClass = m_className;
  m.field = std::move(field);
  m.where = m_source;
  messageLog().add(std::move(m));
}

void Base::msgInfo(std::string text, std::string field) const {
  send(MessageLevel::info, std::move(text), std::move(field));
}

void Base::msgWarning(std::string text, std::string field) const {
  send(MessageLevel::warning, std::move(text), std::move(field));
}

void Base::msgRunFailure(std::string text, std::string field) const {
  send(MessageLevel::warning, std::move(text), std::move(field), true);
}

void Base::msgError(std::string text, std::string field) {
  m_valid = false;
  send(MessageLevel::error, std::move(text), std::move(field));
}

BaseLink::BaseLink(Base* owner, std::string name, std::string help)
    : m_owner(owner), m_name(std::move(name)), m_help(std::move(help)) {
  if (owner) owner->m_links.push_back(this);
}

}  // namespace stroma
