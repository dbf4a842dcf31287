// SPDX-License-Identifier: MIT
#include "simulation/SceneXml.h"

#include <tinyxml2.h>

#include <algorithm>
#include <fstream>
#include <sstream>

namespace stroma {

namespace fs = std::filesystem;

const std::string* SceneElement::attribute(std::string_view name) const {
  for (const auto& a : attributes)
    if (a.name == name) return &a.value;
  return nullptr;
}

namespace {

constexpr int kMaxIncludeDepth = 32;
constexpr std::uintmax_t kMaxIncludeBytes = 64u << 20;  // scene fragments are small

struct Parser {
  const IncludeResolver& resolveInclude;
  MessageLog& log;
  std::vector<fs::path> includeStack;
  bool ok = true;

  void error(const SourceLocation& where, std::string text) {
    Message m;
    m.level = MessageLevel::error;
    m.text = std::move(text);
    m.where = where;
    log.add(std::move(m));
    ok = false;
  }

  bool parseDocument(std::string_view text, const fs::path& file, SceneElement& root) {
    tinyxml2::XMLDocument doc;
    if (doc.Parse(text.data(), text.size()) != tinyxml2::XML_SUCCESS) {
      std::string what = doc.ErrorStr() ? doc.ErrorStr() : "unknown error";
      error({file.string(), doc.ErrorLineNum()}, "malformed XML: " + what);
      return false;
    }
    const tinyxml2::XMLElement* top = doc.RootElement();
    if (!top) {
      error({file.string(), 1}, "the document has no root element");
      return false;
    }
    if (const tinyxml2::XMLElement* extra = top->NextSiblingElement()) {
      error({file.string(), extra->GetLineNum()},
            std::string("a scene has one root element; <") + extra->Name() +
                "> follows the root <" + top->Name() + ">: put it inside the root node");
      return false;
    }
    includeStack.push_back(file);
    const bool converted = convert(*top, file, root);
    includeStack.pop_back();
    return converted;
  }

  bool convert(const tinyxml2::XMLElement& xml, const fs::path& file, SceneElement& out) {
    out.tag = xml.Name();
    out.where = {file.string(), xml.GetLineNum()};
    for (const tinyxml2::XMLAttribute* a = xml.FirstAttribute(); a; a = a->Next())
      out.attributes.push_back({a->Name(), a->Value()});
    if (out.tag == "Object") {  // SOFA's older syntax: <Object type="Class" .../>
      auto type = std::find_if(out.attributes.begin(), out.attributes.end(),
                               [](const auto& a) { return a.name == "type"; });
      if (type == out.attributes.end()) {
        error(out.where, "an <Object> element needs a 'type' attribute naming its class");
        return false;
      }
      out.tag = type->value;
      out.attributes.erase(type);
    }
    for (const tinyxml2::XMLElement* c = xml.FirstChildElement(); c; c = c->NextSiblingElement()) {
      const std::string tag = c->Name();
      if (tag == "include") {
        if (!expandInclude(*c, file, out)) return false;
      } else if (tag == "Attribute") {
        convertAttributeElement(*c, file, out);
      } else {
        SceneElement child;
        if (!convert(*c, file, child)) return false;
        out.children.push_back(std::move(child));
      }
    }
    return true;
  }

  // <Attribute type="name"><Data value="v"/></Attribute>
  void convertAttributeElement(const tinyxml2::XMLElement& xml, const fs::path& file,
                               SceneElement& out) {
    const SourceLocation where{file.string(), xml.GetLineNum()};
    const char* type = xml.Attribute("type");
    const tinyxml2::XMLElement* data = xml.FirstChildElement("Data");
    const char* value = data ? data->Attribute("value") : nullptr;
    if (!type || !value) {
      error(where, "an <Attribute> element needs type=\"field\" and a <Data value=\"...\"/> child");
      return;
    }
    out.attributes.push_back({type, value});
  }

  bool expandInclude(const tinyxml2::XMLElement& xml, const fs::path& file, SceneElement& into) {
    const SourceLocation where{file.string(), xml.GetLineNum()};
    const char* href = xml.Attribute("href");
    if (!href || !*href) {
      error(where, "<include> needs an href attribute naming the fragment file");
      return false;
    }
    const fs::path target = resolveInclude(href, file.parent_path());
    if (target.empty()) {
      error(where, std::string("included file '") + href + "' not found");
      return false;
    }
    if (includeStack.size() >= kMaxIncludeDepth ||
        std::find(includeStack.begin(), includeStack.end(), target) != includeStack.end()) {
      error(where, "include cycle: '" + target.string() + "' includes itself");
      return false;
    }
    std::error_code ec;
    if (!fs::is_regular_file(target, ec)) {
      error(where, "included '" + target.string() + "' is not a regular file");
      return false;
    }
    if (fs::file_size(target, ec) > kMaxIncludeBytes) {
      error(where, "included file '" + target.string() + "' is larger than 64 MiB");
      return false;
    }
    std::ifstream in(target, std::ios::binary);
    std::stringstream buffer;
    buffer << in.rdbuf();
    if (!in) {
      error(where, "cannot read included file '" + target.string() + "'");
      return false;
    }
    SceneElement fragment;
    if (!parseDocument(buffer.str(), target, fragment)) return false;

    // As SOFA does: `name` renames the fragment's root; `obj.attr` (SOFA: `obj__attr`) sets
    // attr on the elements named obj; a plain attr replaces it wherever the fragment has it.
    for (const tinyxml2::XMLAttribute* a = xml.FirstAttribute(); a; a = a->Next()) {
      const std::string name = a->Name();
      if (name == "href") continue;
      if (name == "name") {
        setAttribute(fragment, name, a->Value());
        continue;
      }
      const std::size_t underscores = name.find("__");
      const bool named = underscores != std::string::npos;
      const std::size_t dot = named ? underscores : name.find('.');
      if (dot != std::string::npos) {
        const std::string object = name.substr(0, dot);
        const std::string field = name.substr(dot + (named ? 2 : 1));
        if (!setOnNamed(fragment, object, field, a->Value()))
          error(where, "<include> sets '" + name + "' but the fragment has no element named '" +
                           object + "'");
      } else {
        replaceEverywhere(fragment, name, a->Value());
      }
    }

    // A root Node named Group (or _Group_) stands for its children, one named _Merge_ merges
    // into the including node; any other root element is included as it is.
    const std::string* rootName = fragment.attribute("name");
    const bool isNode = fragment.tag == "Node" || fragment.tag == "node";
    if (isNode && rootName && (*rootName == "Group" || *rootName == "_Group_")) {
      for (auto& e : fragment.children) into.children.push_back(std::move(e));
    } else if (isNode && rootName && *rootName == "_Merge_") {
      merge(into, std::move(fragment));
    } else {
      into.children.push_back(std::move(fragment));
    }
    return true;
  }

  static void setAttribute(SceneElement& e, const std::string& name, const std::string& value) {
    for (auto& a : e.attributes)
      if (a.name == name) {
        a.value = value;
        return;
      }
    e.attributes.push_back({name, value});
  }

  // SOFA's _Merge_: the source's attributes but its name go to `into`; each child merges with
  // the child of the same tag and name, or is appended.
  static void merge(SceneElement& into, SceneElement&& source) {
    for (const auto& a : source.attributes)
      if (a.name != "name") setAttribute(into, a.name, a.value);
    for (auto& child : source.children) {
      const std::string* name = child.attribute("name");
      auto same = std::find_if(into.children.begin(), into.children.end(), [&](const auto& c) {
        const std::string* other = c.attribute("name");
        return name && other && *name == *other && c.tag == child.tag;
      });
      if (same != into.children.end()) merge(*same, std::move(child));
      else into.children.push_back(std::move(child));
    }
  }

  static bool setOnNamed(SceneElement& e, const std::string& object, const std::string& field,
                         const char* value) {
    bool found = false;
    const std::string* name = e.attribute("name");
    if (name && *name == object) {
      auto it = std::find_if(e.attributes.begin(), e.attributes.end(),
                             [&](const auto& a) { return a.name == field; });
      if (it != e.attributes.end()) it->value = value;
      else e.attributes.push_back({field, value});
      found = true;
    }
    for (auto& c : e.children) found |= setOnNamed(c, object, field, value);
    return found;
  }

  static void replaceEverywhere(SceneElement& e, const std::string& field, const char* value) {
    for (auto& a : e.attributes)
      if (a.name == field) a.value = value;
    for (auto& c : e.children) replaceEverywhere(c, field, value);
  }
};

}  // namespace

bool parseSceneXml(std::string_view text, const fs::path& file,
                   const IncludeResolver& resolveInclude, MessageLog& log, SceneElement& root) {
  Parser parser{resolveInclude, log, {}, true};
  const bool parsed = parser.parseDocument(text, file, root);
  return parsed && parser.ok;
}

}  // namespace stroma
