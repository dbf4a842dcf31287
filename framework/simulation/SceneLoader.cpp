// SPDX-License-Identifier: MIT
#include "simulation/SceneLoader.h"

#include <algorithm>
#include <cctype>

#include "core/BaseState.h"
#include "core/Link.h"
#include "core/NameSuggestions.h"
#include "core/PathResolver.h"
#include "core/Runtime.h"
#include "simulation/SceneGenerator.h"
#include "simulation/Visitor.h"

namespace stroma {

namespace fs = std::filesystem;

namespace {

std::string defaultObjectName(const std::string& className) {
  std::string name = className;
  if (!name.empty()) name[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(name[0])));
  return name;
}

std::string childPath(const Node& node, const std::string& name) {
  const std::string base = node.path();
  return (base == "/" ? "" : base) + "/" + name;
}

class GraphBuilder {
 public:
  GraphBuilder(Runtime& runtime, const fs::path& sceneFile, MessageLog& log)
      : m_runtime(runtime), m_sceneDir(sceneFile.parent_path()), m_log(log) {}

  std::unique_ptr<Node> build(const SceneElement& root) {
    if (root.tag != "Node" && root.tag != "node") {
      error(root.where, {}, {}, {},
            "the root element must be a <Node>, got <" + root.tag + ">");
      return nullptr;
    }
    auto node = std::make_unique<Node>();
    node->setMessageLog(&m_log);  // before filling: components may report while being set
    fillNode(*node, root);
    resolveLinks(*node);
    return node;
  }

 private:
  struct PendingSource {
    Base* object;
    std::string path;
  };

  void error(const SourceLocation& where, std::string path, std::string className,
             std::string field, std::string text) {
    Message m;
    m.level = MessageLevel::error;
    m.text = std::move(text);
    m.componentPath = std::move(path);
    m.componentClass = std::move(className);
    m.field = std::move(field);
    m.where = where;
    m_log.add(std::move(m));
  }

  void fillNode(Node& node, const SceneElement& e) {
    node.setSourceLocation(e.where);
    if (!e.attribute("name")) node.setName(node.parent() ? "node" : "root");
    setAttributes(node, e);
    for (const SceneElement& child : e.children) {
      if (child.tag == "Node" || child.tag == "node") {
        Node& sub = node.createChild("node");
        fillNode(sub, child);
        if (child.attribute("name")) renameDuplicate(node, sub, sub.name(), "child nodes");
      } else {
        addComponent(node, child);
      }
    }
  }

  void addComponent(Node& node, const SceneElement& e) {
    const std::string* givenName = e.attribute("name");
    const std::string* templ = e.attribute("template");
    const std::string displayName = givenName ? *givenName : defaultObjectName(e.tag);
    const BaseState* state = node.getUp<BaseState>();
    const std::string contextTemplate = state ? state->templateName() : std::string();

    std::string why;
    std::unique_ptr<Base> object =
        m_runtime.create(e.tag, templ ? *templ : std::string(), contextTemplate, why);
    // A state takes the scene's template or its class's default, never its parent's (as in
    // SOFA: a MechanicalObject without template in a child of a Rigid3d node, the output of a
    // RigidMapping, holds Vec3d points).
    if (object && !templ && !contextTemplate.empty() && dynamic_cast<BaseState*>(object.get()))
      object = m_runtime.create(e.tag, std::string(), std::string(), why);
    if (!object) {
      m_failedNames.push_back(displayName);
      error(e.where, childPath(node, displayName), e.tag, templ && why.find("template") !=
                                                                     std::string::npos
                                                             ? "template"
                                                             : "",
            why);
      return;
    }
    if (!e.children.empty())
      error(e.children.front().where, childPath(node, displayName), object->className(), {},
            "a component element has no child elements; <" + e.children.front().tag +
                "> belongs in a <Node>");
    Base& added = node.addObject(std::move(object));
    added.setSourceLocation(e.where);
    added.setName(givenName ? *givenName : uniqueName(node, displayName, &added));
    setAttributes(added, e);
    if (givenName) renameDuplicate(node, added, *givenName, "objects");
    if (auto* generator = dynamic_cast<SceneGenerator*>(&added)) addGenerated(node, *generator, e);
  }

  // The elements a SceneGenerator writes, built in its node after it; messages about them point
  // to the generator's element.
  void addGenerated(Node& node, SceneGenerator& generator, const SceneElement& e) {
    SceneElement generated;
    generated.tag = "Node";
    if (!generator.generateScene(generated)) return;
    setLocation(generated, e.where);
    for (const SceneElement& child : generated.children) {
      if (child.tag == "Node" || child.tag == "node") {
        Node& sub = node.createChild("node");
        fillNode(sub, child);
        if (child.attribute("name")) renameDuplicate(node, sub, sub.name(), "child nodes");
      } else {
        addComponent(node, child);
      }
    }
  }

  static void setLocation(SceneElement& element, const SourceLocation& where) {
    if (element.where.file.empty()) element.where = where;
    for (SceneElement& child : element.children) setLocation(child, where);
  }

  // A name already given to a sibling of the same kind (SOFA warns and renames): `later` gets
  // a unique name, and the name becomes ambiguous in `node`, so that no link silently picks
  // one of the two.
  static void renameDuplicate(Node& node, Base& later, std::string name, const char* kind) {
    const Base* first = nullptr;
    if (dynamic_cast<Node*>(&later))
      first = node.findChild(name);
    else
      first = node.findObject(name);
    if (!first || first == &later) return;
    const std::string renamed = uniqueName(node, name, &later);
    later.setName(renamed);
    auto where = [](const Base& b) {
      const int line = b.sourceLocation().line;
      return b.className() + (line > 0 ? " at line " + std::to_string(line) : std::string());
    };
    const std::string why = std::string("two ") + kind + " were named '" + name + "' (" +
                            where(*first) + ", " + where(later) + "); the second is now '" +
                            renamed + "'";
    later.msgWarning(why + ", and a link to '" + name + "' is an error", "name");
    node.addAmbiguousName(name, why);
  }

  // `base`, or `base` followed by the first number that no sibling of `self` of its kind
  // (objects, or child nodes) has.
  static std::string uniqueName(const Node& node, const std::string& base, const Base* self) {
    auto taken = [&](const std::string& n) {
      if (dynamic_cast<const Node*>(self)) {
        for (const auto& c : node.children())
          if (c.get() != self && c->name() == n) return true;
        return false;
      }
      for (const auto& o : node.objects())
        if (o.get() != self && o->name() == n) return true;
      return false;
    };
    if (!taken(base)) return base;
    for (int i = 1;; ++i)
      if (!taken(base + std::to_string(i))) return base + std::to_string(i);
  }

  void setAttributes(Base& object, const SceneElement& e) {
    const bool isNode = dynamic_cast<Node*>(&object) != nullptr;
    for (const SceneAttribute& a : e.attributes) {
      if (!isNode && a.name == "template") continue;
      if (!isNode && a.name == "src") {
        if (isLinkText(a.value)) m_sources.push_back({&object, a.value});
        else if (a.value != "@" && !a.value.empty())
          error(e.where, object.path(), object.className(), "src",
                "expected a link to the object to take Data from, as src=\"@loader\"; got '" +
                    a.value + "'");
        continue;
      }
      if (BaseData* data = object.findData(a.name)) {
        setData(object, *data, a.value, e.where);
      } else if (BaseLink* link = object.findLink(a.name)) {
        if (isLinkText(a.value)) link->setPath(a.value);
        else if (!a.value.empty() && a.value != "@")
          error(e.where, object.path(), object.className(), a.name,
                "expected a link to " + link->targetTypeName() + ", as \"@path\"; got '" +
                    a.value + "'");
      } else if (isSofaOption(object, a.name)) {
        object.msgInfo("SOFA option '" + a.name + "' accepted without effect", a.name);
      } else {
        std::vector<std::string> names;
        for (const BaseData* d : object.dataFields()) names.push_back(d->name());
        for (const BaseLink* l : object.links()) names.push_back(l->name());
        std::string text = "unknown attribute '" + a.name + "'";
        const auto near = nearestNames(a.name, names);
        if (!near.empty()) text += "; did you mean " + quotedList(near) + "?";
        else text += " (`stroma doc " + object.className() + "` lists its fields)";
        error(e.where, object.path(), object.className(), a.name, text);
      }
    }
  }

  // An attribute of SOFA's component that the class accepts without effect.
  bool isSofaOption(const Base& object, const std::string& name) const {
    const ComponentClass* c = m_runtime.factory().find(object.className());
    return c && std::find(c->sofaOptions.begin(), c->sofaOptions.end(), name) != c->sofaOptions.end();
  }

  void setData(Base& object, BaseData& data, const std::string& value,
               const SourceLocation& where) {
    if (isLinkText(value)) {
      data.setLinkText(value);
      return;
    }
    std::string why;
    if (!data.read(value, why)) {
      error(where, object.path(), object.className(), data.name(),
            why + " (" + data.typeName() + ")");
      return;
    }
    if (auto* file = dynamic_cast<Data<FileName>*>(&data)) resolveFile(object, *file, where);
  }

  void resolveFile(Base& object, Data<FileName>& data, const SourceLocation& where) {
    const std::string& name = data.value().original;
    if (name.empty()) return;
    std::vector<fs::path> dirs{fs::path(where.file).parent_path()};
    if (m_sceneDir != dirs.front()) dirs.push_back(m_sceneDir);
    const fs::path found = m_runtime.findFile(name, dirs);
    if (!found.empty()) {
      data.edit().resolved = found.string();
      return;
    }
    if (data.options().output) return;  // a file the component will write
    std::string searched;
    for (const auto& d : dirs) {
      if (!searched.empty()) searched += ", ";
      searched += d.string();
    }
    for (const auto& d : m_runtime.dataPath()) searched += ", " + d.string();
    const std::string text = "file '" + name + "' not found (searched: " + searched +
                             "; add folders with --data-path or STROMA_DATA_PATH)";
    if (!data.options().mustExist) {  // only a viewer would read it
      object.msgWarning(text + "; not needed by a batch run", data.name());
      return;
    }
    error(where, object.path(), object.className(), data.name(), text);
  }

  void resolveLinks(Node& node) {
    resolveLinksOf(node, node);
    for (const auto& o : node.objects()) resolveLinksOf(*o, node);
    for (const auto& c : node.children()) resolveLinks(*c);
    if (node.parent() == nullptr) resolveSources();
  }

  void resolveLinksOf(Base& object, const Node& from) {
    // A node's links start from the node itself; a component's from the node holding it.
    const Node* asNode = dynamic_cast<const Node*>(&object);
    const Node& context = asNode ? *asNode : from;
    for (BaseData* data : object.dataFields()) {
      if (data->linkText().empty()) continue;
      std::string why;
      BaseData* parent = resolveDataPath(context, data->linkText(), why, &object);
      if (parent) {
        if (!data->setParent(parent, why)) parent = nullptr;
      }
      if (!parent)
        error(object.sourceLocation(), object.path(), object.className(), data->name(),
              brokenLinkText(data->linkText(), why));
    }
    for (BaseLink* link : object.links()) {
      if (link->path().empty()) continue;
      std::string why;
      Base* target = resolveObjectPath(context, link->path(), why, &object);
      if (!target || !link->setTarget(target, why))
        error(object.sourceLocation(), object.path(), object.className(), link->name(),
              brokenLinkText(link->path(), why));
    }
  }

  // src="@loader": every field of the source that this object also has, and that the scene
  // did not set here, follows the source's.
  void resolveSources() {
    for (const PendingSource& s : m_sources) {
      std::string why;
      const Base* source = resolveObjectPath(*s.object->node(), s.path, why, s.object);
      if (!source) {
        error(s.object->sourceLocation(), s.object->path(), s.object->className(), "src",
              brokenLinkText(s.path, why));
        continue;
      }
      for (BaseData* field : source->dataFields()) {
        if (field->name() == "name" || field->name() == "printLog" || field->name() == "tags" ||
            !field->options().autoLink)
          continue;
        BaseData* mine = s.object->findData(field->name());
        if (!mine || mine->isSet() || !mine->linkText().empty() || mine->options().output)
          continue;
        std::string ignored;
        mine->setParent(field, ignored);  // types that do not convert are skipped, as in SOFA
      }
    }
  }

  // A link to an object that could not be created is a consequence, not a second problem.
  std::string brokenLinkText(const std::string& path, const std::string& why) const {
    std::string target = path;
    if (const auto dot = target.rfind('.'); dot != std::string::npos &&
                                            target.find('/', dot) == std::string::npos &&
                                            dot > 0 && target[dot - 1] != '.')
      target.erase(dot);
    const auto slash = target.find_last_of("/@");
    const std::string last = slash == std::string::npos ? target : target.substr(slash + 1);
    if (path.find("@[") != std::string::npos && !m_failedNames.empty())
      return "link '" + path + "' counts objects back from this one, and an earlier component "
             "could not be created (see its error)";
    for (const auto& failed : m_failedNames)
      if (failed == last)
        return "link '" + path + "' names '" + last +
               "', a component that could not be created (see its error)";
    return "broken link '" + path + "': " + why;
  }

  Runtime& m_runtime;
  std::vector<std::string> m_failedNames;
  fs::path m_sceneDir;
  MessageLog& m_log;
  std::vector<PendingSource> m_sources;
};

// init() top-down in scene order, then bwdInit() bottom-up.
class InitVisitor final : public Visitor {
 public:
  InitVisitor() = default;
  Result processNodeTopDown(Node& node) override {
    for (const auto& o : node.objects()) guarded(*o, [&] { o->init(); });
    return Result::carryOn;
  }
  void processNodeBottomUp(Node& node) override {
    for (const auto& o : node.objects()) guarded(*o, [&] { o->bwdInit(); });
  }
  std::string_view name() const override { return "init"; }

 private:
  template <class F>
  void guarded(Base& object, F&& f) {
    try {
      f();
    } catch (const std::exception& e) {
      object.msgError(std::string("initialization failed: ") + e.what());
    }
  }
};

}  // namespace

bool buildSceneGraph(Runtime& runtime, const SceneElement& root, const fs::path& sceneFile,
                     MessageLog& log, std::unique_ptr<Node>& graph, const ThreadPool* threads) {
  const std::size_t errorsBefore = log.errorCount();
  GraphBuilder builder(runtime, sceneFile, log);
  graph = builder.build(root);
  if (!graph) return false;
  graph->setThreadPool(threads);
  if (log.errorCount() != errorsBefore) return false;  // do not init a graph with bad input
  InitVisitor init;
  traverse(*graph, init);
  return log.errorCount() == errorsBefore;
}

}  // namespace stroma
