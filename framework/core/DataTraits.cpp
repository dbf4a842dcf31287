// SPDX-License-Identifier: MIT
#include "core/DataTraits.h"

#include <cctype>
#include <cstring>

#include "core/NameSuggestions.h"

namespace stroma {

namespace {
bool isSpace(char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; }
}  // namespace

bool TokenReader::next(std::string_view& token) {
  while (m_pos < m_text.size() && isSpace(m_text[m_pos])) ++m_pos;
  if (m_pos >= m_text.size()) return false;
  const std::size_t start = m_pos;
  while (m_pos < m_text.size() && !isSpace(m_text[m_pos])) ++m_pos;
  token = m_text.substr(start, m_pos - start);
  return true;
}

bool TokenReader::atEnd() {
  while (m_pos < m_text.size() && isSpace(m_text[m_pos])) ++m_pos;
  return m_pos >= m_text.size();
}

std::size_t TokenReader::remaining() const {
  std::size_t count = 0;
  bool inToken = false;
  for (std::size_t i = m_pos; i < m_text.size(); ++i) {
    const bool space = isSpace(m_text[i]);
    if (!space && !inToken) ++count;
    inToken = !space;
  }
  return count;
}

namespace internal {

bool parseDouble(std::string_view token, double& out, std::string& error) {
  std::string_view t = token;
  if (!t.empty() && t.front() == '+') t.remove_prefix(1);
  // from_chars does not know the spellings "inf"/"nan" with a sign prefix in every case; the
  // explicit check keeps the reading identical across library versions.
  std::string lower(t);
  for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (lower == "nan" || lower == "-nan") {
    out = std::nan("");
    return true;
  }
  if (lower == "inf" || lower == "infinity") {
    out = HUGE_VAL;
    return true;
  }
  if (lower == "-inf" || lower == "-infinity") {
    out = -HUGE_VAL;
    return true;
  }
  const char* begin = t.data();
  const char* end = t.data() + t.size();
  auto [ptr, ec] = std::from_chars(begin, end, out);
  if (t.empty() || ec == std::errc::invalid_argument || ptr != end) {
    error = "expected a number, got '" + std::string(token) + "'";
    return false;
  }
  if (ec == std::errc::result_out_of_range) {
    error = "number '" + std::string(token) + "' is out of the range of double precision";
    return false;
  }
  return true;
}

bool parseInt64(std::string_view token, long long& out, std::string& error) {
  std::string_view t = token;
  if (!t.empty() && t.front() == '+') t.remove_prefix(1);
  auto [ptr, ec] = std::from_chars(t.data(), t.data() + t.size(), out);
  if (t.empty() || ec == std::errc::invalid_argument || ptr != t.data() + t.size()) {
    error = "expected an integer, got '" + std::string(token) + "'";
    return false;
  }
  if (ec == std::errc::result_out_of_range) {
    error = "integer '" + std::string(token) + "' is out of range";
    return false;
  }
  return true;
}

void printDouble(std::string& out, double value) {
  if (std::isnan(value)) {
    out += "nan";
    return;
  }
  if (std::isinf(value)) {
    out += value > 0 ? "inf" : "-inf";
    return;
  }
  char buffer[32];
  auto [ptr, ec] = std::to_chars(buffer, buffer + sizeof buffer, value);
  out.append(buffer, ptr);
}

std::string describeEnumChoices(const std::string_view* names, std::size_t count) {
  std::string text;
  for (std::size_t i = 0; i < count; ++i) {
    if (i) text += i + 1 == count ? " or " : ", ";
    text += '\'';
    text += names[i];
    text += '\'';
  }
  return text;
}

bool parseEnumToken(std::string_view token, const std::string_view* names, std::size_t count,
                    int& index, std::string& error) {
  for (std::size_t i = 0; i < count; ++i) {
    if (names[i] == token) {
      index = static_cast<int>(i);
      return true;
    }
  }
  std::vector<std::string> candidates(names, names + count);
  error = "expected " + describeEnumChoices(names, count) + ", got '" + std::string(token) + "'";
  const auto near = nearestNames(std::string(token), candidates, 1);
  if (!near.empty()) error += "; did you mean '" + near.front() + "'?";
  return false;
}

}  // namespace internal

bool ElementTraits<bool>::parseTokens(TokenReader& in, bool& v, std::string& error) {
  std::string_view token;
  if (!in.next(token)) return (error = "expected a boolean, got nothing"), false;
  if (token == "1" || token == "true" || token == "True" || token == "TRUE") {
    v = true;
    return true;
  }
  if (token == "0" || token == "false" || token == "False" || token == "FALSE") {
    v = false;
    return true;
  }
  error = "expected a boolean (0, 1, true or false), got '" + std::string(token) + "'";
  return false;
}

bool ElementTraits<Quat>::parseTokens(TokenReader& in, Quat& q, std::string& error) {
  double c[4];
  for (double& x : c)
    if (!ElementTraits<double>::parseTokens(in, x, error)) return false;
  q = Quat(c[3], c[0], c[1], c[2]);  // scenes write x y z w
  return true;
}

void ElementTraits<Quat>::print(std::string& out, const Quat& q) {
  const double c[4] = {q.x(), q.y(), q.z(), q.w()};
  for (int i = 0; i < 4; ++i) {
    if (i) out += ' ';
    internal::printDouble(out, c[i]);
  }
}

bool ElementTraits<RigidCoord3>::parseTokens(TokenReader& in, RigidCoord3& c,
                                             std::string& error) {
  return ElementTraits<Vec3d>::parseTokens(in, c.center, error) &&
         ElementTraits<Quat>::parseTokens(in, c.orientation, error);
}

void ElementTraits<RigidCoord3>::print(std::string& out, const RigidCoord3& c) {
  ElementTraits<Vec3d>::print(out, c.center);
  out += ' ';
  ElementTraits<Quat>::print(out, c.orientation);
}

bool ElementTraits<RigidDeriv3>::parseTokens(TokenReader& in, RigidDeriv3& c,
                                             std::string& error) {
  return ElementTraits<Vec3d>::parseTokens(in, c.linear, error) &&
         ElementTraits<Vec3d>::parseTokens(in, c.angular, error);
}

void ElementTraits<RigidDeriv3>::print(std::string& out, const RigidDeriv3& c) {
  ElementTraits<Vec3d>::print(out, c.linear);
  out += ' ';
  ElementTraits<Vec3d>::print(out, c.angular);
}

bool ElementTraits<std::string>::parseTokens(TokenReader& in, std::string& v,
                                             std::string& error) {
  std::string_view token;
  if (!in.next(token)) return (error = "expected a word, got nothing"), false;
  v = std::string(token);
  return true;
}

}  // namespace stroma
