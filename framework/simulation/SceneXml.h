// SPDX-License-Identifier: MIT
// The first stage of scene loading: XML text to a tree of elements, with every <include>
// expanded and every element knowing its file and line. Nothing is instantiated here.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "core/Message.h"

namespace stroma {

struct SceneAttribute {
  std::string name;
  std::string value;
};

struct SceneElement {
  std::string tag;  ///< "Node" or a component class name
  std::vector<SceneAttribute> attributes;
  std::vector<SceneElement> children;
  SourceLocation where;

  const std::string* attribute(std::string_view name) const;
};

/// Finds the file an <include href> names, relative to the including file's folder first.
using IncludeResolver =
    std::function<std::filesystem::path(const std::string& href, const std::filesystem::path& from)>;

/// Parses a scene document. `file` names it in messages and anchors relative includes.
/// Includes, as SOFA reads them: `<include href="fragment.xml" attr="v" obj.attr="v"/>` is
/// replaced by the fragment's root element (a Node or a component), except that a root Node
/// named "Group" (or "_Group_") is replaced by its children and one named "_Merge_" merges
/// into the including node (children of the same class and name merge). `name="n"` renames
/// the fragment's root; `obj.attr="v"` (SOFA: `obj__attr`) sets attribute attr of the
/// fragment's elements named obj, and a plain `attr="v"` replaces attr in every fragment
/// element that declares it (so a fragment's placeholder `src="@"` becomes the includer's
/// `src="@loader"`).
/// SOFA's older forms are accepted too: `<Object type="Class" .../>` and attributes given as
/// `<Attribute type="name"><Data value="..."/></Attribute>` children.
/// Returns false after adding an error to `log` (malformed XML, missing include, cycle).
bool parseSceneXml(std::string_view text, const std::filesystem::path& file,
                   const IncludeResolver& resolveInclude, MessageLog& log, SceneElement& root);

}  // namespace stroma
