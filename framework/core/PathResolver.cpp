// SPDX-License-Identifier: MIT
#include "core/PathResolver.h"

#include <charconv>
#include <vector>

#include "core/NameSuggestions.h"
#include "core/Node.h"

namespace stroma {

namespace {

std::vector<std::string_view> splitSegments(std::string_view path) {
  std::vector<std::string_view> segments;
  std::size_t start = 0;
  while (start <= path.size()) {
    const std::size_t slash = path.find('/', start);
    const std::size_t end = slash == std::string_view::npos ? path.size() : slash;
    if (end > start) segments.push_back(path.substr(start, end - start));
    if (slash == std::string_view::npos) break;
    start = slash + 1;
  }
  return segments;
}

std::vector<std::string> namesIn(const Node& node) {
  std::vector<std::string> names;
  for (const auto& o : node.objects()) names.push_back(o->name());
  for (const auto& c : node.children()) names.push_back(c->name());
  return names;
}

// With `andAncestors`, the search went up from `where`: suggest the ancestors' names too.
std::string notFound(std::string_view what, const Node& where, bool andAncestors = false) {
  std::string error = "no object or node named '" + std::string(what) + "' in " + where.path();
  if (andAncestors) error += " nor in its ancestors";
  std::vector<std::string> names;
  for (const Node* n = &where; n; n = andAncestors ? n->parent() : nullptr) {
    auto here = namesIn(*n);
    names.insert(names.end(), here.begin(), here.end());
  }
  const auto near = nearestNames(std::string(what), names);
  if (!near.empty()) error += "; did you mean " + quotedList(near) + "?";
  return error;
}

// A name two siblings had in the scene: refused rather than resolved to either (Node.h).
bool isAmbiguous(const Node& node, std::string_view name, std::string& error) {
  const std::string* why = node.ambiguity(name);
  if (!why) return false;
  error = "'" + std::string(name) + "' is ambiguous in " + node.path() + ": " + *why +
          "; give them different names and link to the one meant";
  return true;
}

Base* findHere(const Node& node, std::string_view name) {
  if (Base* object = node.findObject(name)) return object;
  if (Node* child = node.findChild(name)) return child;
  return nullptr;
}

}  // namespace

bool isLinkText(std::string_view text) {
  std::size_t i = 0;
  while (i < text.size() && (text[i] == ' ' || text[i] == '\t')) ++i;
  return i + 1 < text.size() && text[i] == '@';
}

namespace {

// "@[-k]": the k-th object before `owner` in its node.
Base* resolveRelativeIndex(const Node& from, std::string_view path, const Base* owner,
                           std::string& error) {
  long long offset = 0;
  const std::string_view digits = path.substr(1, path.size() - 2);
  auto [ptr, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), offset);
  if (ec != std::errc() || ptr != digits.data() + digits.size() || offset >= 0) {
    error = "expected '@[-k]' (the k-th object before this one), got '@" + std::string(path) +
            "'";
    return nullptr;
  }
  const auto& objects = from.objects();
  long long index = -1;
  for (std::size_t i = 0; i < objects.size(); ++i)
    if (objects[i].get() == owner) index = static_cast<long long>(i);
  if (index < 0) {
    error = "'@" + std::string(path) + "' is only meaningful for a component of " + from.path();
    return nullptr;
  }
  if (index + offset < 0) {
    error = "'@" + std::string(path) + "' goes before the first object of " + from.path();
    return nullptr;
  }
  return objects[static_cast<std::size_t>(index + offset)].get();
}

}  // namespace

Base* resolveObjectPath(const Node& from, std::string_view path, std::string& error,
                        const Base* owner) {
  while (!path.empty() && (path.front() == ' ' || path.front() == '\t')) path.remove_prefix(1);
  while (!path.empty() && (path.back() == ' ' || path.back() == '\t')) path.remove_suffix(1);
  if (!path.empty() && path.front() == '@') path.remove_prefix(1);
  if (path.empty()) {
    error = "empty link path";
    return nullptr;
  }
  if (path.front() == '[' && path.back() == ']')
    return resolveRelativeIndex(from, path, owner, error);
  const bool absolute = path.front() == '/';
  auto segments = splitSegments(path);
  const Node* current = absolute ? &from.root() : &from;

  // A bare name: this node, then the ancestors (SOFA's search upwards).
  if (!absolute && segments.size() == 1 && segments[0] != "." && segments[0] != "..") {
    for (const Node* n = &from; n; n = n->parent()) {
      if (isAmbiguous(*n, segments[0], error)) return nullptr;
      if (Base* found = findHere(*n, segments[0])) return found;
    }
    error = notFound(segments[0], from, true);
    return nullptr;
  }
  if (absolute && !segments.empty() && segments[0] == current->name() &&
      !findHere(*current, segments[0]))
    segments.erase(segments.begin());
  if (segments.empty()) return const_cast<Node*>(current);

  for (std::size_t i = 0; i < segments.size(); ++i) {
    const std::string_view segment = segments[i];
    const bool last = i + 1 == segments.size();
    if (segment == ".") continue;
    if (segment == "..") {
      if (!current->parent()) {
        error = "'..' goes above the root node in '" + std::string(path) + "'";
        return nullptr;
      }
      current = current->parent();
      continue;
    }
    if (isAmbiguous(*current, segment, error)) return nullptr;
    if (last) {
      if (Base* found = findHere(*current, segment)) return found;
      error = notFound(segment, *current);
      return nullptr;
    }
    const Node* child = current->findChild(segment);
    if (!child) {
      error = "no child node named '" + std::string(segment) + "' in " + current->path();
      std::vector<std::string> names;
      for (const auto& c : current->children()) names.push_back(c->name());
      const auto near = nearestNames(std::string(segment), names);
      if (!near.empty()) error += "; did you mean " + quotedList(near) + "?";
      return nullptr;
    }
    current = child;
  }
  return const_cast<Node*>(current);
}

BaseData* resolveDataPath(const Node& from, std::string_view path, std::string& error,
                          const Base* owner) {
  std::string_view text = path;
  while (!text.empty() && (text.back() == ' ' || text.back() == '\t')) text.remove_suffix(1);
  const std::size_t slash = text.rfind('/');
  const std::size_t dot = text.rfind('.');
  if (dot == std::string_view::npos || (slash != std::string_view::npos && dot < slash) ||
      dot + 1 == text.size() || (dot > 0 && text[dot - 1] == '.')) {
    error = "a Data link names an object and a field, as '@object.field'; got '" +
            std::string(path) + "'";
    return nullptr;
  }
  std::string_view objectPath = text.substr(0, dot);
  const std::string field(text.substr(dot + 1));
  Base* object = nullptr;
  if (objectPath == "@" || objectPath.empty()) {
    error = "a Data link names an object before the field, as '@object.field'; got '" +
            std::string(path) + "'";
    return nullptr;
  }
  object = resolveObjectPath(from, objectPath, error, owner);
  if (!object) return nullptr;
  if (BaseData* data = object->findData(field)) return data;
  std::vector<std::string> names;
  for (const BaseData* d : object->dataFields()) names.push_back(d->name());
  error = object->path() + " (" + object->className() + ") has no field '" + field + "'";
  const auto near = nearestNames(field, names);
  if (!near.empty()) error += "; did you mean " + quotedList(near) + "?";
  return nullptr;
}

}  // namespace stroma
