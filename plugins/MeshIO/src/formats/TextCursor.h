// SPDX-License-Identifier: MIT
// Reading the text of a mesh file token by token, knowing the line of each token, so that an
// error can say "line 12: expected 3 coordinates, got 'x'".
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace stroma::meshio {

class TextCursor {
 public:
  explicit TextCursor(std::string_view text) : m_text(text) {}

  /// The next whitespace-separated token; empty at the end of the text.
  std::string_view next();
  /// The next token, not consumed.
  std::string_view peek();
  /// True when only whitespace is left.
  bool atEnd();
  /// The rest of the current line after the last token (without the line break), and moves to
  /// the start of the next line.
  std::string_view restOfLine();
  /// 1-based line of the last token returned (of the current position before any).
  int line() const { return m_tokenLine; }
  /// Byte offset of the current position (after the last token or line read).
  std::size_t offset() const { return m_pos; }
  /// Moves forward to `offset` (binary data in between is skipped; lines are still counted).
  void seek(std::size_t offset);
  std::string_view text() const { return m_text; }

  // Typed reads. On failure each sets `error` to "line N: expected <what>, got '<token>'".
  bool readDouble(double& value, std::string_view what, std::string& error);
  bool readInteger(long long& value, std::string_view what, std::string& error);
  /// A count in [0, max]; larger counts are refused before anything is allocated for them.
  bool readCount(std::size_t& value, std::string_view what, std::size_t max, std::string& error);
  /// Reads the next token and checks it is `keyword`.
  bool expect(std::string_view keyword, std::string& error);

  /// "line N: expected <what>, got '<token>'" (or "got the end of the file").
  std::string expected(std::string_view what, std::string_view got) const;
  /// "line N: <text>".
  std::string at(std::string_view text) const;

 private:
  void skipSpace();

  std::string_view m_text;
  std::size_t m_pos = 0;
  int m_line = 1;       // line at m_pos
  int m_tokenLine = 1;  // line of the last token
};

/// Parses a whole token as a number (locale independent; a leading '+' is accepted).
bool parseNumber(std::string_view token, double& value);
bool parseNumber(std::string_view token, long long& value);

/// A token shortened for messages.
std::string quoted(std::string_view token);

}  // namespace stroma::meshio
