// SPDX-License-Identifier: MIT
#include "TextCursor.h"

#include <charconv>
#include <cmath>

namespace stroma::meshio {

namespace {
bool isSpace(char c) {
  return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v';
}
}  // namespace

void TextCursor::skipSpace() {
  while (m_pos < m_text.size() && isSpace(m_text[m_pos])) {
    if (m_text[m_pos] == '\n') ++m_line;
    ++m_pos;
  }
}

std::string_view TextCursor::next() {
  skipSpace();
  m_tokenLine = m_line;
  const std::size_t start = m_pos;
  while (m_pos < m_text.size() && !isSpace(m_text[m_pos])) ++m_pos;
  return m_text.substr(start, m_pos - start);
}

std::string_view TextCursor::peek() {
  const std::size_t pos = m_pos;
  const int line = m_line, tokenLine = m_tokenLine;
  const std::string_view token = next();
  m_pos = pos;
  m_line = line;
  m_tokenLine = tokenLine;
  return token;
}

bool TextCursor::atEnd() {
  skipSpace();
  return m_pos >= m_text.size();
}

std::string_view TextCursor::restOfLine() {
  const std::size_t start = m_pos;
  while (m_pos < m_text.size() && m_text[m_pos] != '\n') ++m_pos;
  std::string_view rest = m_text.substr(start, m_pos - start);
  if (!rest.empty() && rest.back() == '\r') rest.remove_suffix(1);
  if (m_pos < m_text.size()) {
    ++m_pos;
    ++m_line;
  }
  return rest;
}

void TextCursor::seek(std::size_t offset) {
  if (offset > m_text.size()) offset = m_text.size();
  for (; m_pos < offset; ++m_pos)
    if (m_text[m_pos] == '\n') ++m_line;
  m_tokenLine = m_line;
}

bool parseNumber(std::string_view token, double& value) {
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  if (token.empty()) return false;
  const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
  return ec == std::errc() && end == token.data() + token.size() && std::isfinite(value);
}

bool parseNumber(std::string_view token, long long& value) {
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  if (token.empty()) return false;
  const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
  return ec == std::errc() && end == token.data() + token.size();
}

std::string quoted(std::string_view token) {
  std::string text;
  for (char c : token.substr(0, 40))
    text += (static_cast<unsigned char>(c) < 32 || c == 127) ? '?' : c;
  if (token.size() > 40) text += "...";
  return "'" + text + "'";
}

std::string TextCursor::expected(std::string_view what, std::string_view got) const {
  std::string text = "line " + std::to_string(m_tokenLine) + ": expected " + std::string(what);
  text += got.empty() ? ", got the end of the file" : ", got " + quoted(got);
  return text;
}

std::string TextCursor::at(std::string_view text) const {
  return "line " + std::to_string(m_tokenLine) + ": " + std::string(text);
}

bool TextCursor::readDouble(double& value, std::string_view what, std::string& error) {
  const std::string_view token = next();
  if (parseNumber(token, value)) return true;
  error = expected(what, token);
  return false;
}

bool TextCursor::readInteger(long long& value, std::string_view what, std::string& error) {
  const std::string_view token = next();
  if (parseNumber(token, value)) return true;
  error = expected(what, token);
  return false;
}

bool TextCursor::readCount(std::size_t& value, std::string_view what, std::size_t max,
                           std::string& error) {
  long long v = 0;
  if (!readInteger(v, what, error)) return false;
  if (v < 0 || static_cast<unsigned long long>(v) > max) {
    error = at(std::string(what) + " " + std::to_string(v) + " is out of range [0, " +
               std::to_string(max) + "]");
    return false;
  }
  value = static_cast<std::size_t>(v);
  return true;
}

bool TextCursor::expect(std::string_view keyword, std::string& error) {
  const std::string_view token = next();
  if (token == keyword) return true;
  std::string what(1, '\'');
  what.append(keyword).push_back('\'');
  error = expected(what, token);
  return false;
}

}  // namespace stroma::meshio
