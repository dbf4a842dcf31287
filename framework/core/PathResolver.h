// SPDX-License-Identifier: MIT
// Paths of links in scenes, SOFA's syntax:
//   @name          an object (or child node) named so in this node, else in the nearest
//                  ancestor that has one
//   @../dofs       relative: '..' is the parent node, '.' this node, other segments child nodes,
//                  the last segment an object or a node
//   @/A/B          absolute, from the root (the root's own name may be given or omitted)
//   @path.field    a Data of the object at `path` (Data links)
//   @[-1]          the object declared just before the link's owner in its node (SOFA's
//                  relative index form; [-k] goes k objects back)
#pragma once

#include <string>
#include <string_view>

namespace stroma {

class Base;
class BaseData;
class Node;

/// The object at `path` seen from `from`, or nullptr with `error` naming the segment that
/// failed and the nearest existing names.
/// `owner` is the object holding the link, needed only by the @[-k] form.
Base* resolveObjectPath(const Node& from, std::string_view path, std::string& error,
                        const Base* owner = nullptr);

/// The Data at `path` ("@obj.field"), or nullptr with `error` set.
BaseData* resolveDataPath(const Node& from, std::string_view path, std::string& error,
                          const Base* owner = nullptr);

/// True for an attribute value that is a link ("@..." and not just "@").
bool isLinkText(std::string_view text);

}  // namespace stroma
