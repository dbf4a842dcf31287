// SPDX-License-Identifier: MIT
#pragma once

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "core/Base.h"
#include "core/ThreadPool.h"

namespace stroma {

/// A node of the scene graph: child nodes, components, and a context (time step, gravity,
/// time) that children inherit unless they set their own.
class Node final : public Base {
 public:
  explicit Node(std::string name = "root");
  ~Node() override;

  Data<double> d_dt{this, "dt", 0.01,
                    "Time step; inherited by child nodes that do not set their own.",
                    {.unit = "s", .min = 0.0}};
  Data<Vec3d> d_gravity{this, "gravity", Vec3d(0, -9.81, 0),
                        "Gravity acceleration; inherited by child nodes that do not set it.",
                        {.unit = "m/s^2"}};
  Data<double> d_time{this, "time", 0.0, "Simulation time at the start (root node only).",
                      {.unit = "s"}};
  Data<bool> d_animate{this, "animate", false,
                       "Start animating at once (viewers; a batch run always animates)."};
  Data<bool> d_activated{this, "activated", true,
                         "When false, visitors skip this node and its subtree."};
  Data<bool> d_showBoundingTree{this, "showBoundingTree", false,
                                "Draw collision bounding trees (viewers only)."};
  Data<std::vector<double>> d_bbox{this, "bbox", {},
                                   "Scene bounding box 'xmin ymin zmin xmax ymax zmax' "
                                   "(viewers only)."};
  Data<bool> d_multiThreadSimulation{this, "multiThreadSimulation", false,
                                     "SOFA option, accepted and ignored: Stroma chooses its "
                                     "threads with `stroma run --threads`."};
  Data<std::string> d_depend{this, "depend", "",
                             "SOFA option, accepted and ignored: initialization order is the "
                             "scene order."};

  std::string path() const override;

  Node* parent() const { return node(); }
  Node& root();
  const Node& root() const;

  const std::vector<std::unique_ptr<Node>>& children() const { return m_children; }
  const std::vector<std::unique_ptr<Base>>& objects() const { return m_objects; }

  Node& addChild(std::unique_ptr<Node> child);
  Node& createChild(std::string name);
  Base& addObject(std::unique_ptr<Base> object);
  /// Detaches and returns the object (nullptr when it is not here).
  std::unique_ptr<Base> removeObject(const Base* object);
  std::unique_ptr<Node> removeChild(const Node* child);

  Node* findChild(std::string_view name) const;
  Base* findObject(std::string_view name) const;

  /// A name that two siblings were given in the scene (two objects, or two child nodes): the
  /// later one was renamed, and a link naming it is refused rather than resolved to either.
  /// `why` says which objects had it (paths and lines) and what they are now called.
  void addAmbiguousName(std::string name, std::string why);
  /// The explanation of `name`'s ambiguity in this node, or nullptr when it is not ambiguous.
  const std::string* ambiguity(std::string_view name) const;

  /// First object of type T in this node.
  template <class T>
  T* get() const {
    for (const auto& o : m_objects)
      if (auto* t = dynamic_cast<T*>(o.get())) return t;
    return nullptr;
  }
  /// Every object of type T in this node, in scene order.
  template <class T>
  std::vector<T*> getAll() const {
    std::vector<T*> result;
    for (const auto& o : m_objects)
      if (auto* t = dynamic_cast<T*>(o.get())) result.push_back(t);
    return result;
  }
  /// First object of type T in this node or the nearest ancestor that has one.
  template <class T>
  T* getUp() const {
    for (const Node* n = this; n; n = n->parent())
      if (T* t = n->get<T>()) return t;
    return nullptr;
  }

  /// Context, inherited downwards.
  double dt() const;
  Vec3d gravity() const;
  /// Current simulation time, kept by the root.
  double time() const;
  void setTime(double t);

  /// The log of the scene this node belongs to (set on the root by whoever owns the scene).
  void setMessageLog(MessageLog* log) { m_log = log; }
  MessageLog* sceneLog() const { return root().m_log; }

  /// The threads of the scene this node belongs to (set on the root by the scene); a
  /// single-threaded pool when the node is not in a scene.
  void setThreadPool(const ThreadPool* pool) { m_pool = pool; }
  const ThreadPool& threadPool() const;

 private:
  std::vector<std::unique_ptr<Node>> m_children;
  std::vector<std::unique_ptr<Base>> m_objects;
  std::vector<std::pair<std::string, std::string>> m_ambiguousNames;  // name, why
  MessageLog* m_log = nullptr;
  const ThreadPool* m_pool = nullptr;
};

}  // namespace stroma
