// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <iosfwd>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace stroma {

/// Where a piece of a scene was written: file and 1-based line (0 when unknown).
struct SourceLocation {
  std::string file;
  int line = 0;
};

enum class MessageLevel { info, warning, error };

/// One report about the scene or the run. Every field but `text` may be empty: a message names
/// as much as it knows (file and line, component path and class, field).
struct Message {
  MessageLevel level = MessageLevel::info;
  std::string text;
  std::string componentPath;   ///< "/root/Liver/FEM"
  std::string componentClass;  ///< "TetrahedronFEMForceField"
  std::string field;           ///< "youngModulus"
  SourceLocation where;
  /// A warning after which the run may go on but cannot end as a success: its state diverged
  /// and the scene asked to continue (onDivergence="warn"). `stroma run` then exits with 1.
  bool failsRun = false;
};

const char* levelName(MessageLevel level);

/// "scene.scn:12: error: /root/Liver/FEM (TetrahedronFEMForceField), field 'youngModulus': ..."
std::string formatForConsole(const Message& message);
/// One JSON object on one line, with the keys level, text, component, class, field, file, line.
std::string formatAsJson(const Message& message);

/// A number as messages quote it: printf's "%g" (6 significant digits), so that "got 1e+40"
/// or "got -5" reads as the user wrote it.
std::string formatNumber(double value);

/// Receives messages as they are logged (console, JSON-lines file, test collector).
class MessageSink {
 public:
  virtual ~MessageSink() = default;
  virtual void receive(const Message& message) = 0;
};

/// Writes human-readable lines to a stream (stderr for the CLI). `minimum` filters out
/// lower levels.
class StreamSink final : public MessageSink {
 public:
  StreamSink(std::ostream& out, MessageLevel minimum);
  void receive(const Message& message) override;

 private:
  std::ostream& m_out;
  MessageLevel m_minimum;
};

/// Writes one JSON object per line, for tools (`stroma --log-json FILE`).
class JsonLinesSink final : public MessageSink {
 public:
  explicit JsonLinesSink(std::ostream& out);
  void receive(const Message& message) override;

 private:
  std::ostream& m_out;
};

/// The messages of one scene or one command. It keeps every message and forwards each to its
/// sinks. Owned by whoever runs the scene: there is no process-wide log. Thread-safe, so element
/// loops running in parallel may report.
class MessageLog {
 public:
  void add(Message message);
  void addSink(std::shared_ptr<MessageSink> sink);

  std::size_t count(MessageLevel level) const;
  std::size_t errorCount() const { return count(MessageLevel::error); }
  /// Messages that make the run a failure: errors, and warnings marked `failsRun`.
  std::size_t runFailureCount() const;
  std::vector<Message> messages() const;
  void clear();

 private:
  mutable std::mutex m_mutex;
  std::vector<Message> m_messages;
  std::vector<std::shared_ptr<MessageSink>> m_sinks;
};

}  // namespace stroma
