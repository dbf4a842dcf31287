// SPDX-License-Identifier: MIT
#include "core/Data.h"

namespace stroma {

BaseData::BaseData(Base* owner, std::string name, std::string help, DataOptions options)
    : m_owner(owner), m_name(std::move(name)), m_help(std::move(help)),
      m_options(std::move(options)) {
  if (owner) internal::registerData(owner, this);
}

std::string BaseData::valueText() const {
  update();
  std::string text;
  printValue(text);
  return text;
}

bool BaseData::read(std::string_view text, std::string& error) {
  if (!parseValue(text, error)) return false;
  markChanged();
  return true;
}

bool BaseData::setParent(BaseData* parent, std::string& error) {
  if (parent == this) {
    error = "a Data cannot follow itself";
    return false;
  }
  for (const BaseData* p = parent; p; p = p->m_parent) {
    if (p == this) {
      error = "following '" + parent->name() + "' would make a cycle of links";
      return false;
    }
  }
  if (parent) {
    parent->update();
    std::string saved;
    printValue(saved);
    if (!copyFrom(*parent, error)) {
      error = "cannot take the value of '" + parent->name() + "' (" + parent->typeName() +
              "): " + error;
      std::string ignored;
      parseValue(saved, ignored);
      return false;
    }
    m_parentVersionSeen = parent->m_version;
    markChanged();
  }
  m_parent = parent;
  return true;
}

void BaseData::update() const {
  if (m_updating) return;  // an engine reading its own output while computing it
  m_updating = true;
  if (m_engine) m_engine->updateIfDirty();
  if (m_parent) {
    m_parent->update();
    if (m_parent->m_version != m_parentVersionSeen) {
      std::string error;
      // The conversion was checked when the link was made; a later failure keeps the old value.
      if (const_cast<BaseData*>(this)->copyFrom(*m_parent, error)) {
        ++m_version;
      }
      m_parentVersionSeen = m_parent->m_version;
    }
  }
  m_updating = false;
}

void DataEngine::updateIfDirty() {
  if (m_running) return;
  bool dirty = m_forceUpdate;
  for (auto& input : m_inputs) {
    const std::uint64_t v = input.data->version();
    if (v != input.versionSeen) {
      input.versionSeen = v;
      dirty = true;
    }
  }
  if (!dirty) return;
  m_running = true;
  m_forceUpdate = false;
  doUpdate();
  m_running = false;
}

}  // namespace stroma
