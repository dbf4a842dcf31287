// SPDX-License-Identifier: MIT
// How each value type of a Data is named, parsed from and printed to a scene attribute.
//
// A scene writes values as whitespace-separated tokens, as SOFA does: "1 0 0" is a Vec3d,
// "0 1 2 3" a list of indices, "0-50" (integer lists only) the indices 0 to 50. Numbers are read
// and printed locale-independently, and printed in the shortest form that reads back exactly.
#pragma once

#include <array>
#include <charconv>
#include <cmath>
#include <concepts>
#include <cstdint>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "core/Types.h"

namespace stroma {

/// Splits a text into whitespace-separated tokens.
class TokenReader {
 public:
  explicit TokenReader(std::string_view text) : m_text(text) {}
  /// Next token, or false at the end.
  bool next(std::string_view& token);
  bool atEnd();
  /// Counts the remaining tokens without consuming them.
  std::size_t remaining() const;

 private:
  std::string_view m_text;
  std::size_t m_pos = 0;
};

/// Keywords of an enumeration used as a Data: specialize with
/// `static constexpr std::array names{"small", "large", ...};` in the order of the enumerators
/// (which must be 0, 1, 2, ...). The keywords are what scenes write.
template <class E>
struct EnumKeywords;

template <class E>
concept KeywordEnum = std::is_enum_v<E> && requires { EnumKeywords<E>::names; };

namespace internal {
bool parseDouble(std::string_view token, double& out, std::string& error);
bool parseInt64(std::string_view token, long long& out, std::string& error);
void printDouble(std::string& out, double value);
std::string describeEnumChoices(const std::string_view* names, std::size_t count);
bool parseEnumToken(std::string_view token, const std::string_view* names, std::size_t count,
                    int& index, std::string& error);
}  // namespace internal

/// Traits of one element type. `tokens` is how many tokens one value takes (0: the whole text,
/// for strings). parseTokens reads exactly one value.
template <class T>
struct ElementTraits;

template <>
struct ElementTraits<bool> {
  static constexpr int tokens = 1;
  static std::string typeName() { return "bool"; }
  static bool parseTokens(TokenReader& in, bool& v, std::string& error);
  static void print(std::string& out, bool v) { out += v ? '1' : '0'; }
};

template <class T>
  requires(std::is_integral_v<T> && !std::is_same_v<T, bool>)
struct ElementTraits<T> {
  static constexpr int tokens = 1;
  static std::string typeName() {
    return std::is_signed_v<T> ? "int" : "unsigned int";
  }
  static bool parseTokens(TokenReader& in, T& v, std::string& error) {
    std::string_view token;
    if (!in.next(token)) return (error = "expected an integer, got nothing"), false;
    return fromToken(token, v, error);
  }
  static bool fromToken(std::string_view token, T& v, std::string& error) {
    long long value = 0;
    if (!internal::parseInt64(token, value, error)) return false;
    if (std::is_unsigned_v<T> && value < 0) {
      error = "expected a non-negative integer, got '" + std::string(token) + "'";
      return false;
    }
    if (value < static_cast<long long>(std::numeric_limits<T>::min()) ||
        (value > 0 && static_cast<unsigned long long>(value) >
                          static_cast<unsigned long long>(std::numeric_limits<T>::max()))) {
      error = "integer '" + std::string(token) + "' is out of range";
      return false;
    }
    v = static_cast<T>(value);
    return true;
  }
  static void print(std::string& out, T v) { out += std::to_string(v); }
};

template <class T>
  requires std::is_floating_point_v<T>
struct ElementTraits<T> {
  static constexpr int tokens = 1;
  static std::string typeName() { return "real"; }
  static bool parseTokens(TokenReader& in, T& v, std::string& error) {
    std::string_view token;
    if (!in.next(token)) return (error = "expected a number, got nothing"), false;
    double d = 0;
    if (!internal::parseDouble(token, d, error)) return false;
    v = static_cast<T>(d);
    return true;
  }
  static void print(std::string& out, T v) {
    if constexpr (std::is_same_v<T, float>) {
      // The shortest text that reads back to this float, not to the double it widens to.
      if (std::isfinite(v)) {
        char buffer[32];
        out.append(buffer, std::to_chars(buffer, buffer + sizeof buffer, v).ptr);
        return;
      }
    }
    internal::printDouble(out, static_cast<double>(v));
  }
};

template <class S, int N>
struct ElementTraits<Eigen::Matrix<S, N, 1>> {
  static_assert(N > 0, "Data holds fixed-size vectors only (Vec3d, Vec3i, ...).");
  using Value = Eigen::Matrix<S, N, 1>;
  static constexpr int tokens = N;
  static std::string typeName() {
    return std::string(std::is_integral_v<S> ? "Vec" : "Vec") + std::to_string(N) +
           (std::is_integral_v<S> ? "i" : "d");
  }
  static bool parseTokens(TokenReader& in, Value& v, std::string& error) {
    for (int i = 0; i < N; ++i)
      if (!ElementTraits<S>::parseTokens(in, v[i], error)) return false;
    return true;
  }
  static void print(std::string& out, const Value& v) {
    for (int i = 0; i < N; ++i) {
      if (i) out += ' ';
      ElementTraits<S>::print(out, v[i]);
    }
  }
};

template <class S, std::size_t N>
  requires std::is_integral_v<S>
struct ElementTraits<std::array<S, N>> {
  using Value = std::array<S, N>;
  static constexpr int tokens = static_cast<int>(N);
  static std::string typeName() { return std::to_string(N) + " indices"; }
  static bool parseTokens(TokenReader& in, Value& v, std::string& error) {
    for (auto& x : v)
      if (!ElementTraits<S>::parseTokens(in, x, error)) return false;
    return true;
  }
  static void print(std::string& out, const Value& v) {
    for (std::size_t i = 0; i < N; ++i) {
      if (i) out += ' ';
      ElementTraits<S>::print(out, v[i]);
    }
  }
};

template <>
struct ElementTraits<Quat> {
  static constexpr int tokens = 4;
  static std::string typeName() { return "Quat"; }
  static bool parseTokens(TokenReader& in, Quat& q, std::string& error);
  static void print(std::string& out, const Quat& q);
};

template <>
struct ElementTraits<RigidCoord3> {
  static constexpr int tokens = 7;
  static std::string typeName() { return "Rigid3d coordinates"; }
  static bool parseTokens(TokenReader& in, RigidCoord3& c, std::string& error);
  static void print(std::string& out, const RigidCoord3& c);
};

template <>
struct ElementTraits<RigidDeriv3> {
  static constexpr int tokens = 6;
  static std::string typeName() { return "Rigid3d derivative"; }
  static bool parseTokens(TokenReader& in, RigidDeriv3& c, std::string& error);
  static void print(std::string& out, const RigidDeriv3& c);
};

template <>
struct ElementTraits<std::string> {
  static constexpr int tokens = 1;  // inside a vector: one word per item
  static std::string typeName() { return "string"; }
  static bool parseTokens(TokenReader& in, std::string& v, std::string& error);
  static void print(std::string& out, const std::string& v) { out += v; }
};

template <KeywordEnum E>
struct ElementTraits<E> {
  static constexpr int tokens = 1;
  static constexpr auto& names = EnumKeywords<E>::names;
  static std::string typeName() {
    std::array<std::string_view, names.size()> views{};
    for (std::size_t i = 0; i < names.size(); ++i) views[i] = names[i];
    return "one of " + internal::describeEnumChoices(views.data(), views.size());
  }
  static bool parseTokens(TokenReader& in, E& v, std::string& error) {
    std::string_view token;
    if (!in.next(token)) return (error = "expected a keyword, got nothing"), false;
    std::array<std::string_view, names.size()> views{};
    for (std::size_t i = 0; i < names.size(); ++i) views[i] = names[i];
    int index = 0;
    if (!internal::parseEnumToken(token, views.data(), views.size(), index, error)) return false;
    v = static_cast<E>(index);
    return true;
  }
  static void print(std::string& out, E v) { out += names[static_cast<std::size_t>(v)]; }
};

/// Traits of a whole Data value: one element, or a list of elements.
template <class T>
struct DataTraits {
  using Element = ElementTraits<T>;
  static std::string typeName() { return Element::typeName(); }
  static bool parse(std::string_view text, T& v, std::string& error) {
    TokenReader in(text);
    const std::size_t count = in.remaining();
    if constexpr (Element::tokens > 1) {
      if (count != static_cast<std::size_t>(Element::tokens)) {
        error = "expected " + std::to_string(Element::tokens) + " numbers (" + typeName() +
                "), got " + std::to_string(count);
        return false;
      }
    } else if (count != 1) {
      error = "expected one value (" + typeName() + "), got " + std::to_string(count);
      return false;
    }
    return Element::parseTokens(in, v, error);
  }
  static void print(std::string& out, const T& v) { Element::print(out, v); }
};

template <>
struct DataTraits<std::string> {
  static std::string typeName() { return "string"; }
  static bool parse(std::string_view text, std::string& v, std::string&) {
    v = std::string(text);
    return true;
  }
  static void print(std::string& out, const std::string& v) { out += v; }
};

template <>
struct DataTraits<FileName> {
  static std::string typeName() { return "file name"; }
  static bool parse(std::string_view text, FileName& v, std::string&) {
    v.original = std::string(text);
    v.resolved.clear();
    return true;
  }
  static void print(std::string& out, const FileName& v) { out += v.original; }
};

template <class T>
struct DataTraits<std::vector<T>> {
  using Element = ElementTraits<T>;
  static std::string typeName() { return "list of " + Element::typeName(); }
  static bool parse(std::string_view text, std::vector<T>& v, std::string& error) {
    TokenReader in(text);
    std::vector<T> result;
    if constexpr (std::is_integral_v<T> && !std::is_same_v<T, bool>) {
      // Integer lists accept ranges "a-b" as SOFA's index lists do.
      std::string_view token;
      while (in.next(token)) {
        const auto dash = token.find('-', 1);
        if (dash == std::string_view::npos) {
          T value{};
          if (!Element::fromToken(token, value, error)) return false;
          result.push_back(value);
          continue;
        }
        T first{}, last{};
        if (!Element::fromToken(token.substr(0, dash), first, error) ||
            !Element::fromToken(token.substr(dash + 1), last, error))
          return (error = "expected an integer or a range 'a-b', got '" + std::string(token) +
                          "'"),
                 false;
        if (last < first || static_cast<long long>(last) - first > 10000000)
          return (error = "bad range '" + std::string(token) + "' (expected a <= b and at most 10^7 values)"), false;
        for (T i = first;; ++i) {  // stops at `last` without overflowing past the type's max
          result.push_back(i);
          if (i == last) break;
        }
      }
    } else {
      const std::size_t count = in.remaining();
      if (Element::tokens > 1 && count % Element::tokens != 0) {
        error = "expected a multiple of " + std::to_string(Element::tokens) + " numbers (" +
                typeName() + "), got " + std::to_string(count);
        return false;
      }
      result.reserve(count / Element::tokens);
      while (!in.atEnd()) {
        T value{};
        if (!Element::parseTokens(in, value, error)) return false;
        result.push_back(std::move(value));
      }
    }
    v = std::move(result);
    return true;
  }
  static void print(std::string& out, const std::vector<T>& v) {
    for (std::size_t i = 0; i < v.size(); ++i) {
      if (i) out += ' ';
      Element::print(out, v[i]);
    }
  }
};

/// Calls f(double) on every floating-point number of a value, for range and finiteness checks.
template <class T, class F>
void forEachReal(const T& v, F&& f) {
  if constexpr (std::is_floating_point_v<T>) {
    f(static_cast<double>(v));
  } else if constexpr (requires { typename T::Scalar; T::RowsAtCompileTime; }) {
    if constexpr (std::is_floating_point_v<typename T::Scalar>)
      for (int i = 0; i < v.size(); ++i) f(static_cast<double>(v[i]));
  } else if constexpr (std::is_same_v<T, Quat>) {
    for (int i = 0; i < 4; ++i) f(v.coeffs()[i]);
  } else if constexpr (std::is_same_v<T, RigidCoord3>) {
    forEachReal(v.center, f);
    forEachReal(v.orientation, f);
  } else if constexpr (std::is_same_v<T, RigidDeriv3>) {
    forEachReal(v.linear, f);
    forEachReal(v.angular, f);
  } else if constexpr (requires { v.begin(); typename T::value_type; } &&
                       !std::is_same_v<T, std::string>) {
    for (const auto& e : v) forEachReal(e, f);
  }
}

/// Calls f(long long) on every integer of a value (integers, integer vectors, lists of them).
template <class T, class F>
void forEachInteger(const T& v, F&& f) {
  if constexpr (std::is_integral_v<T> && !std::is_same_v<T, bool>) {
    f(static_cast<long long>(v));
  } else if constexpr (requires { typename T::Scalar; T::RowsAtCompileTime; }) {
    if constexpr (std::is_integral_v<typename T::Scalar>)
      for (int i = 0; i < v.size(); ++i) f(static_cast<long long>(v[i]));
  } else if constexpr (requires { v.begin(); typename T::value_type; } &&
                       !std::is_same_v<T, std::string>) {
    for (const auto& e : v) forEachInteger(e, f);
  }
}

}  // namespace stroma
