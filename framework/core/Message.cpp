// SPDX-License-Identifier: MIT
#include "core/Message.h"

#include <cstdio>
#include <ostream>
#include <sstream>

namespace stroma {

const char* levelName(MessageLevel level) {
  switch (level) {
    case MessageLevel::info: return "info";
    case MessageLevel::warning: return "warning";
    case MessageLevel::error: return "error";
  }
  return "unknown";
}

std::string formatNumber(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

std::string formatForConsole(const Message& m) {
  std::ostringstream out;
  if (!m.where.file.empty()) {
    out << m.where.file;
    if (m.where.line > 0) out << ':' << m.where.line;
    out << ": ";
  }
  out << levelName(m.level) << ": ";
  if (!m.componentPath.empty() || !m.componentClass.empty()) {
    out << (m.componentPath.empty() ? "?" : m.componentPath);
    if (!m.componentClass.empty()) out << " (" << m.componentClass << ')';
    out << (m.field.empty() ? ": " : ", ");
  }
  if (!m.field.empty()) out << "field '" << m.field << "': ";
  out << m.text;
  return out.str();
}

namespace {

void appendJsonString(std::ostream& out, const std::string& text) {
  out << '"';
  for (unsigned char c : text) {
    switch (c) {
      case '"': out << "\\\""; break;
      case '\\': out << "\\\\"; break;
      case '\n': out << "\\n"; break;
      case '\r': out << "\\r"; break;
      case '\t': out << "\\t"; break;
      default:
        if (c < 0x20) {
          static const char* hex = "0123456789abcdef";
          out << "\\u00" << hex[c >> 4] << hex[c & 15];
        } else {
          out << static_cast<char>(c);
        }
    }
  }
  out << '"';
}

}  // namespace

std::string formatAsJson(const Message& m) {
  std::ostringstream out;
  out << "{\"level\":";
  appendJsonString(out, levelName(m.level));
  out << ",\"text\":";
  appendJsonString(out, m.text);
  out << ",\"component\":";
  appendJsonString(out, m.componentPath);
  out << ",\"class\":";
  appendJsonString(out, m.componentClass);
  out << ",\"field\":";
  appendJsonString(out, m.field);
  out << ",\"file\":";
  appendJsonString(out, m.where.file);
  out << ",\"line\":" << m.where.line;
  if (m.failsRun) out << ",\"failsRun\":true";
  out << '}';
  return out.str();
}

StreamSink::StreamSink(std::ostream& out, MessageLevel minimum) : m_out(out), m_minimum(minimum) {}

void StreamSink::receive(const Message& message) {
  if (static_cast<int>(message.level) < static_cast<int>(m_minimum)) return;
  m_out << formatForConsole(message) << '\n';
}

JsonLinesSink::JsonLinesSink(std::ostream& out) : m_out(out) {}

void JsonLinesSink::receive(const Message& message) {
  m_out << formatAsJson(message) << '\n';
  m_out.flush();
}

void MessageLog::add(Message message) {
  std::lock_guard lock(m_mutex);
  for (auto& sink : m_sinks) sink->receive(message);
  m_messages.push_back(std::move(message));
}

void MessageLog::addSink(std::shared_ptr<MessageSink> sink) {
  std::lock_guard lock(m_mutex);
  m_sinks.push_back(std::move(sink));
}

std::size_t MessageLog::count(MessageLevel level) const {
  std::lock_guard lock(m_mutex);
  std::size_t n = 0;
  for (const auto& m : m_messages) n += (m.level == level);
  return n;
}

std::size_t MessageLog::runFailureCount() const {
  std::lock_guard lock(m_mutex);
  std::size_t n = 0;
  for (const auto& m : m_messages) n += (m.level == MessageLevel::error || m.failsRun);
  return n;
}

std::vector<Message> MessageLog::messages() const {
  std::lock_guard lock(m_mutex);
  return m_messages;
}

void MessageLog::clear() {
  std::lock_guard lock(m_mutex);
  m_messages.clear();
}

}  // namespace stroma
