// SPDX-License-Identifier: MIT
#include "core/Node.h"

#include <algorithm>

namespace stroma {

Node::Node(std::string name) {
  setName(std::move(name));
  setClassName("Node");
}

Node::~Node() {
  // Objects may hold pointers into siblings and children: destroy components last-first.
  while (!m_objects.empty()) m_objects.pop_back();
  while (!m_children.empty()) m_children.pop_back();
}

std::string Node::path() const {
  if (!parent()) return "/" + name();
  return parent()->path() + "/" + name();
}

Node& Node::root() {
  Node* n = this;
  while (n->parent()) n = n->parent();
  return *n;
}

const Node& Node::root() const {
  const Node* n = this;
  while (n->parent()) n = n->parent();
  return *n;
}

Node& Node::addChild(std::unique_ptr<Node> child) {
  child->m_node = this;
  m_children.push_back(std::move(child));
  return *m_children.back();
}

Node& Node::createChild(std::string name) { return addChild(std::make_unique<Node>(std::move(name))); }

Base& Node::addObject(std::unique_ptr<Base> object) {
  object->m_node = this;
  m_objects.push_back(std::move(object));
  return *m_objects.back();
}

std::unique_ptr<Base> Node::removeObject(const Base* object) {
  auto it = std::find_if(m_objects.begin(), m_objects.end(),
                         [&](const auto& o) { return o.get() == object; });
  if (it == m_objects.end()) return nullptr;
  std::unique_ptr<Base> removed = std::move(*it);
  m_objects.erase(it);
  removed->m_node = nullptr;
  return removed;
}

std::unique_ptr<Node> Node::removeChild(const Node* child) {
  auto it = std::find_if(m_children.begin(), m_children.end(),
                         [&](const auto& c) { return c.get() == child; });
  if (it == m_children.end()) return nullptr;
  std::unique_ptr<Node> removed = std::move(*it);
  m_children.erase(it);
  removed->m_node = nullptr;
  return removed;
}

Node* Node::findChild(std::string_view name) const {
  for (const auto& c : m_children)
    if (c->name() == name) return c.get();
  return nullptr;
}

Base* Node::findObject(std::string_view name) const {
  for (const auto& o : m_objects)
    if (o->name() == name) return o.get();
  return nullptr;
}

void Node::addAmbiguousName(std::string name, std::string why) {
  for (auto& [known, reason] : m_ambiguousNames)
    if (known == name) {
      reason += "; " + why;
      return;
    }
  m_ambiguousNames.emplace_back(std::move(name), std::move(why));
}

const std::string* Node::ambiguity(std::string_view name) const {
  for (const auto& [known, why] : m_ambiguousNames)
    if (known == name) return &why;
  return nullptr;
}

double Node::dt() const {
  for (const Node* n = this; n; n = n->parent())
    if (n->d_dt.isSet() || !n->parent()) return n->d_dt.value();
  return d_dt.value();
}

Vec3d Node::gravity() const {
  for (const Node* n = this; n; n = n->parent())
    if (n->d_gravity.isSet() || !n->parent()) return n->d_gravity.value();
  return d_gravity.value();
}

const ThreadPool& Node::threadPool() const {
  static const ThreadPool serial(1);  // immutable: safe to share between scenes
  const Node& r = root();
  return r.m_pool ? *r.m_pool : serial;
}

double Node::time() const { return root().d_time.value(); }

void Node::setTime(double t) { root().d_time.setValue(t); }

}  // namespace stroma
