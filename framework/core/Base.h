// SPDX-License-Identifier: MIT
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "core/Data.h"
#include "core/Message.h"

namespace stroma {

class Node;
class BaseLink;

/// The root of every scene object (components and nodes): a name, Data fields and links that
/// the scene fills, a place in the graph, a lifecycle and a message log.
///
/// Lifecycle, driven by the scene loader: construction, Data and links set from the scene,
/// init() top-down in scene order, bwdInit() bottom-up, then steps; reinit() after a Data
/// changed at run time; cleanup() before destruction.
class Base {
  // Declared first: the Data members below register into them as they are constructed.
  std::vector<BaseData*> m_data;
  std::vector<BaseLink*> m_links;

 public:
  Base();
  virtual ~Base();
  Base(const Base&) = delete;
  Base& operator=(const Base&) = delete;

  Data<std::string> d_name{this, "name", "", "Name, unique among siblings; links use it (@name)."};
  Data<bool> d_printLog{this, "printLog", false, "Also print this object's info messages."};
  Data<std::vector<std::string>> d_tags{this, "tags", {}, "Tags (words) for tag-filtered visitors."};
  Data<bool> d_listening{this, "listening", false,
                         "SOFA option, accepted: Stroma components receive the events they need."};

  const std::string& name() const { return d_name.value(); }
  void setName(std::string name) { d_name.setValue(std::move(name)); }

  /// Class name as registered in the factory ("TetrahedronFEMForceField"), and the template
  /// it was created with ("Vec3d"; empty for untemplated classes).
  const std::string& className() const { return m_className; }
  const std::string& templateName() const { return m_templateName; }
  void setClassName(std::string className, std::string templateName = {});

  /// The node holding this object (for a Node: its parent; nullptr at the root).
  Node* node() const { return m_node; }
  /// Absolute path in the graph: "/root/Liver/FEM".
  virtual std::string path() const;

  const std::vector<BaseData*>& dataFields() const { return m_data; }
  BaseData* findData(std::string_view name) const;
  const std::vector<BaseLink*>& links() const { return m_links; }
  BaseLink* findLink(std::string_view name) const;

  /// Where the scene declared this object (file and line), for messages.
  const SourceLocation& sourceLocation() const { return m_source; }
  void setSourceLocation(SourceLocation where) { m_source = std::move(where); }

  virtual void init() {}
  virtual void bwdInit() {}
  virtual void reinit() {}
  virtual void cleanup() {}

  /// False after the component reported that it cannot work (bad input found in init()).
  bool isValid() const { return m_valid; }

  void msgInfo(std::string text, std::string field = {}) const;
  void msgWarning(std::string text, std::string field = {}) const;
  /// A warning that lets the run go on but makes it end as a failure (Message::failsRun): a
  /// state that diverged while the scene asked to continue.
  void msgRunFailure(std::string text, std::string field = {}) const;
  /// Reports an error. Use from init() for bad input, after which the component is invalid.
  void msgError(std::string text, std::string field = {});
  /// The log messages go to: the scene's, or one of the object's own when it is not in a scene.
  MessageLog& messageLog() const;

 protected:
  void setInvalid() { m_valid = false; }

 private:
  friend class Node;
  friend class BaseLink;
  friend void internal::registerData(Base*, BaseData*);
  void send(MessageLevel level, std::string text, std::string field, bool failsRun = false) const;

  std::string m_className;
  std::string m_templateName;
  Node* m_node = nullptr;
  SourceLocation m_source;
  bool m_valid = true;
  mutable std::unique_ptr<MessageLog> m_ownLog;
};

}  // namespace stroma
