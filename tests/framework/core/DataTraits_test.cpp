// SPDX-License-Identifier: MIT
// Parsing and printing of every Data value type: round trips, exact printed forms, and the
// error text a scene author sees for a bad attribute value.
#include "core/DataTraits.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <array>
#include <bit>
#include <cfloat>
#include <climits>
#include <cmath>
#include <cstdint>
#include <limits>
#include <locale>
#include <numbers>
#include <string>
#include <vector>

namespace stroma {

namespace {
enum class Method { small, large, polar };
}  // namespace

template <>
struct EnumKeywords<Method> {
  static constexpr std::array names{"small", "large", "polar"};
};

namespace {

// Exact comparison: doubles by bit pattern, so that -0.0 differs from 0.0.
bool same(double a, double b) {
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}
bool same(float a, float b) {
  return std::bit_cast<std::uint32_t>(a) == std::bit_cast<std::uint32_t>(b);
}
bool same(bool a, bool b) { return a == b; }
bool same(int a, int b) { return a == b; }
bool same(unsigned a, unsigned b) { return a == b; }
bool same(Method a, Method b) { return a == b; }
bool same(const std::string& a, const std::string& b) { return a == b; }
bool same(const FileName& a, const FileName& b) { return a.original == b.original; }
template <class S, int N>
bool same(const Eigen::Matrix<S, N, 1>& a, const Eigen::Matrix<S, N, 1>& b) {
  for (int i = 0; i < N; ++i)
    if (!same(a[i], b[i])) return false;
  return true;
}
bool same(const Quat& a, const Quat& b) { return same(Vec4d(a.coeffs()), Vec4d(b.coeffs())); }
bool same(const RigidCoord3& a, const RigidCoord3& b) {
  return same(a.center, b.center) && same(a.orientation, b.orientation);
}
bool same(const RigidDeriv3& a, const RigidDeriv3& b) {
  return same(a.linear, b.linear) && same(a.angular, b.angular);
}
template <class T>
bool same(const std::vector<T>& a, const std::vector<T>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (!same(static_cast<T>(a[i]), static_cast<T>(b[i]))) return false;
  return true;
}

template <class T>
std::string printed(const T& value) {
  std::string text;
  DataTraits<T>::print(text, value);
  return text;
}

template <class T>
::testing::AssertionResult parses(std::string_view text, T& value) {
  std::string error;
  if (DataTraits<T>::parse(text, value, error)) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "'" << text << "' refused: " << error;
}

// The error of a parse that must fail; the value must stay untouched.
template <class T>
std::string parseError(std::string_view text) {
  T value{};
  std::string error;
  EXPECT_FALSE(DataTraits<T>::parse(text, value, error)) << "'" << text << "' was accepted";
  return error;
}

// Sample values of each element type, every one a single scene word so that lists of them
// read back too.
template <class T>
struct Samples;

template <>
struct Samples<bool> {
  static std::vector<bool> values() { return {true, false}; }
};
template <>
struct Samples<int> {
  static std::vector<int> values() { return {0, 1, -1, 42, INT_MAX, INT_MIN}; }
};
template <>
struct Samples<unsigned> {
  static std::vector<unsigned> values() { return {0u, 7u, UINT_MAX}; }
};
template <>
struct Samples<double> {
  static std::vector<double> values() {
    return {0.1,           1.0 / 3.0,       1e-300,  -0.0, 0.0,  5e-324,
            DBL_MAX,       -DBL_MAX,        DBL_MIN, 1.0,  -2.5, std::nextafter(1.0, 2.0),
            123456789.125, std::numbers::pi};
  }
};
template <>
struct Samples<float> {
  static std::vector<float> values() {
    return {0.1f,         1.0f / 3.0f, 1e-30f,
            -0.0f,        FLT_MAX,     FLT_MIN,
            FLT_TRUE_MIN, 16777217.0f, std::nextafter(1.0f, 2.0f)};
  }
};
template <>
struct Samples<std::string> {
  static std::vector<std::string> values() { return {"liver", "a.b", "@../dofs", "x_1"}; }
};
template <>
struct Samples<FileName> {
  static std::vector<FileName> values() {
    return {{"mesh/liver.obj", ""}, {"with space.vtk", ""}, {"", ""}};
  }
};
template <>
struct Samples<Method> {
  static std::vector<Method> values() { return {Method::small, Method::large, Method::polar}; }
};
template <>
struct Samples<Vec3d> {
  static std::vector<Vec3d> values() {
    return {Vec3d(0.1, -0.0, 1e-300), Vec3d(1, 2, 3), Vec3d(1.0 / 3, DBL_MAX, -7)};
  }
};
template <>
struct Samples<Vec2i> {
  static std::vector<Vec2i> values() { return {Vec2i(0, -1), Vec2i(INT_MAX, INT_MIN)}; }
};
template <>
struct Samples<Quat> {
  static std::vector<Quat> values() {
    return {Quat::Identity(), Quat(0.5, -0.5, 0.5, -0.5),
            Quat(std::sqrt(0.5), 0, 0, std::sqrt(0.5))};
  }
};
template <>
struct Samples<RigidCoord3> {
  static std::vector<RigidCoord3> values() {
    return {RigidCoord3{}, RigidCoord3{Vec3d(0.1, 0.2, 0.3), Quat(0.5, 0.5, 0.5, 0.5)}};
  }
};
template <>
struct Samples<RigidDeriv3> {
  static std::vector<RigidDeriv3> values() {
    return {RigidDeriv3{}, RigidDeriv3{Vec3d(1, -2, 0.1), Vec3d(1.0 / 3, -0.0, 1e300)}};
  }
};

// Every value type a Data may hold.
template <class T>
class ScalarRoundTrip : public ::testing::Test {};
using ScalarTypes = ::testing::Types<bool, int, unsigned, double, float, std::string, FileName,
                                     Method, Vec3d, Vec2i, Quat, RigidCoord3, RigidDeriv3>;
TYPED_TEST_SUITE(ScalarRoundTrip, ScalarTypes);

TYPED_TEST(ScalarRoundTrip, PrintThenParseGivesTheSameValueAndText) {
  for (const TypeParam& value : Samples<TypeParam>::values()) {
    const std::string text = printed(value);
    TypeParam back{};
    ASSERT_TRUE(parses(text, back));
    EXPECT_TRUE(same(value, back)) << "printed as '" << text << "'";
    EXPECT_EQ(printed(back), text);
  }
}

TYPED_TEST(ScalarRoundTrip, TypeNameIsNotEmpty) {
  EXPECT_FALSE(DataTraits<TypeParam>::typeName().empty());
}

// Every element type a list may hold (FileName is a single value only).
template <class T>
class ListRoundTrip : public ::testing::Test {};
using ElementTypes = ::testing::Types<bool, int, unsigned, double, float, std::string, Method,
                                      Vec3d, Vec2i, Quat, RigidCoord3, RigidDeriv3>;
TYPED_TEST_SUITE(ListRoundTrip, ElementTypes);

TYPED_TEST(ListRoundTrip, PrintThenParseGivesTheSameList) {
  const auto samples = Samples<TypeParam>::values();
  const std::vector<TypeParam> list(samples.begin(), samples.end());
  const std::string text = printed(list);
  std::vector<TypeParam> back;
  ASSERT_TRUE(parses(text, back));
  EXPECT_TRUE(same(list, back)) << "printed as '" << text << "'";
  EXPECT_EQ(printed(back), text);
}

TYPED_TEST(ListRoundTrip, EmptyTextIsAnEmptyList) {
  std::vector<TypeParam> back(2);
  ASSERT_TRUE(parses("", back));
  EXPECT_TRUE(back.empty());
  ASSERT_TRUE(parses(" \t\n ", back));
  EXPECT_TRUE(back.empty());
  EXPECT_EQ(printed(back), "");
}

TYPED_TEST(ListRoundTrip, TypeNameSaysList) {
  EXPECT_EQ(DataTraits<std::vector<TypeParam>>::typeName(),
            "list of " + ElementTraits<TypeParam>::typeName());
}

TEST(BoolTraits, AcceptsDigitsAndWords) {
  bool v = false;
  for (const char* text : {"1", "true", "True", "TRUE", " true "}) {
    v = false;
    ASSERT_TRUE(parses(text, v));
    EXPECT_TRUE(v) << text;
  }
  for (const char* text : {"0", "false", "False", "FALSE"}) {
    v = true;
    ASSERT_TRUE(parses(text, v));
    EXPECT_FALSE(v) << text;
  }
  EXPECT_EQ(printed(true), "1");
  EXPECT_EQ(printed(false), "0");
}

TEST(BoolTraits, RefusesOtherWords) {
  EXPECT_EQ(parseError<bool>("yes"), "expected a boolean (0, 1, true or false), got 'yes'");
  EXPECT_EQ(parseError<bool>("2"), "expected a boolean (0, 1, true or false), got '2'");
  EXPECT_EQ(parseError<bool>("1 0"), "expected one value (bool), got 2");
  EXPECT_EQ(parseError<bool>(""), "expected one value (bool), got 0");
}

TEST(IntegerTraits, ReadsSignedValues) {
  int v = 0;
  ASSERT_TRUE(parses("-42", v));
  EXPECT_EQ(v, -42);
  ASSERT_TRUE(parses("+7", v));
  EXPECT_EQ(v, 7);
  ASSERT_TRUE(parses("  12\n", v));
  EXPECT_EQ(v, 12);
  EXPECT_EQ(printed(-42), "-42");
  EXPECT_EQ(ElementTraits<int>::typeName(), "int");
  EXPECT_EQ(ElementTraits<unsigned>::typeName(), "unsigned int");
}

TEST(IntegerTraits, RefusesNonIntegers) {
  EXPECT_EQ(parseError<int>("4.5"), "expected an integer, got '4.5'");
  EXPECT_EQ(parseError<int>("abc"), "expected an integer, got 'abc'");
  EXPECT_EQ(parseError<int>("1e3"), "expected an integer, got '1e3'");
  EXPECT_EQ(parseError<int>("+"), "expected an integer, got '+'");
  EXPECT_EQ(parseError<int>("1 2"), "expected one value (int), got 2");
}

TEST(IntegerTraits, RefusesValuesOutOfTheTypeRange) {
  EXPECT_EQ(parseError<int>("2147483648"), "integer '2147483648' is out of range");
  EXPECT_EQ(parseError<int>("-2147483649"), "integer '-2147483649' is out of range");
  EXPECT_EQ(parseError<unsigned>("4294967296"), "integer '4294967296' is out of range");
  EXPECT_EQ(parseError<long long>("99999999999999999999"),
            "integer '99999999999999999999' is out of range");
  EXPECT_EQ(parseError<std::uint8_t>("256"), "integer '256' is out of range");
}

TEST(IntegerTraits, UnsignedRefusesNegativeValues) {
  EXPECT_EQ(parseError<unsigned>("-1"), "expected a non-negative integer, got '-1'");
  EXPECT_EQ(parseError<std::vector<unsigned>>("1 -1"), "expected a non-negative integer, got '-1'");
  unsigned v = 5;
  ASSERT_TRUE(parses("-0", v));
  EXPECT_EQ(v, 0u);
}

TEST(RealTraits, PrintsTheShortestTextThatReadsBack) {
  EXPECT_EQ(printed(0.1), "0.1");
  EXPECT_EQ(printed(1.0 / 3.0), "0.3333333333333333");
  EXPECT_EQ(printed(1e-300), "1e-300");
  EXPECT_EQ(printed(-0.0), "-0");
  EXPECT_EQ(printed(1.0), "1");
  EXPECT_EQ(printed(-2.5), "-2.5");
  EXPECT_EQ(printed(1e21), "1e+21");
  EXPECT_EQ(printed(5e-324), "5e-324");
  EXPECT_EQ(printed(0.1f), "0.1");
  EXPECT_EQ(printed(1.0f / 3.0f), "0.33333334");
}

TEST(RealTraits, ReadsEverySpelling) {
  double v = 0;
  ASSERT_TRUE(parses("+1.5", v));
  EXPECT_EQ(v, 1.5);
  ASSERT_TRUE(parses("-2E3", v));
  EXPECT_EQ(v, -2000.0);
  ASSERT_TRUE(parses(".5", v));
  EXPECT_EQ(v, 0.5);
  ASSERT_TRUE(parses("7", v));
  EXPECT_EQ(v, 7.0);
  ASSERT_TRUE(parses("1e-320", v));  // subnormal
  EXPECT_EQ(v, 1e-320);
}

TEST(RealTraits, ReadsNonFiniteSpellingsTheDataThenChecks) {
  // The traits read them; Data refuses them unless allowNonFinite (see Data_test).
  double v = 0;
  ASSERT_TRUE(parses("nan", v));
  EXPECT_TRUE(std::isnan(v));
  ASSERT_TRUE(parses("NaN", v));
  EXPECT_TRUE(std::isnan(v));
  ASSERT_TRUE(parses("inf", v));
  EXPECT_EQ(v, HUGE_VAL);
  ASSERT_TRUE(parses("-Infinity", v));
  EXPECT_EQ(v, -HUGE_VAL);
  EXPECT_EQ(printed(std::numeric_limits<double>::quiet_NaN()), "nan");
  EXPECT_EQ(printed(-HUGE_VAL), "-inf");
}

TEST(RealTraits, RefusesGarbage) {
  EXPECT_EQ(parseError<double>("abc"), "expected a number, got 'abc'");
  EXPECT_EQ(parseError<double>("1.5x"), "expected a number, got '1.5x'");
  EXPECT_EQ(parseError<double>("1,5"), "expected a number, got '1,5'");
  EXPECT_EQ(parseError<double>("0x10"), "expected a number, got '0x10'");
  EXPECT_EQ(parseError<double>("+"), "expected a number, got '+'");
  EXPECT_EQ(parseError<double>("1e999"), "number '1e999' is out of the range of double precision");
  EXPECT_EQ(parseError<double>(""), "expected one value (real), got 0");
  EXPECT_EQ(parseError<double>("1 2"), "expected one value (real), got 2");
}

TEST(RealTraits, FloatRoundTripsForManyBitPatterns) {
  // Every printed float must read back to the same float (through the double parser).
  std::uint32_t bits = 0x12345678;
  for (int i = 0; i < 20000; ++i) {
    bits = bits * 1664525u + 1013904223u;
    const float value = std::bit_cast<float>(bits);
    if (!std::isfinite(value)) continue;
    const std::string text = printed(value);
    float back = 0;
    ASSERT_TRUE(parses(text, back));
    ASSERT_TRUE(same(value, back)) << "printed as '" << text << "'";
  }
}

TEST(RealTraits, DoubleRoundTripsForManyBitPatterns) {
  std::uint64_t bits = 0x0123456789abcdefULL;
  for (int i = 0; i < 20000; ++i) {
    bits = bits * 6364136223846793005ULL + 1442695040888963407ULL;
    const double value = std::bit_cast<double>(bits);
    if (!std::isfinite(value)) continue;
    const std::string text = printed(value);
    double back = 0;
    ASSERT_TRUE(parses(text, back));
    ASSERT_TRUE(same(value, back)) << "printed as '" << text << "'";
    ASSERT_LE(text.size(), 24u) << text;
  }
}

// A C++ locale whose decimal separator is a comma and whose thousands are grouped.
struct CommaDecimal : std::numpunct<char> {
  char do_decimal_point() const override { return ','; }
  char do_thousands_sep() const override { return '.'; }
  std::string do_grouping() const override { return "\3"; }
};

TEST(RealTraits, IgnoresTheGlobalLocale) {
  const std::locale previous =
      std::locale::global(std::locale(std::locale::classic(), new CommaDecimal));
  double v = 0;
  const bool ok = parses("1234.5", v);
  const std::string text = printed(1234.5);
  const std::string integer = printed(1234567);
  std::locale::global(previous);
  EXPECT_TRUE(ok);
  EXPECT_EQ(v, 1234.5);
  EXPECT_EQ(text, "1234.5");
  EXPECT_EQ(integer, "1234567");
}

TEST(StringTraits, KeepsTheWholeText) {
  std::string v;
  ASSERT_TRUE(parses("  two words\tand a tab ", v));
  EXPECT_EQ(v, "  two words\tand a tab ");
  ASSERT_TRUE(parses("", v));
  EXPECT_EQ(v, "");
  EXPECT_EQ(printed(std::string("a b")), "a b");
  EXPECT_EQ(DataTraits<std::string>::typeName(), "string");
}

TEST(StringTraits, ListsSplitIntoWords) {
  std::vector<std::string> v;
  ASSERT_TRUE(parses(" red  green\nblue ", v));
  EXPECT_EQ(v, (std::vector<std::string>{"red", "green", "blue"}));
  EXPECT_EQ(printed(v), "red green blue");
}

TEST(FileNameTraits, KeepsWhatTheSceneWroteAndForgetsTheResolvedPath) {
  FileName f{"old", "/abs/old"};
  ASSERT_TRUE(parses("mesh/liver.obj", f));
  EXPECT_EQ(f.original, "mesh/liver.obj");
  EXPECT_EQ(f.resolved, "");
  EXPECT_EQ(f.path(), "mesh/liver.obj");
  f.resolved = "/data/mesh/liver.obj";
  EXPECT_EQ(f.path(), "/data/mesh/liver.obj");
  EXPECT_EQ(printed(f), "mesh/liver.obj");  // prints the scene's text, not the resolved one
  EXPECT_EQ(DataTraits<FileName>::typeName(), "file name");
}

TEST(EnumTraits, ReadsAndPrintsKeywords) {
  Method m = Method::small;
  ASSERT_TRUE(parses("polar", m));
  EXPECT_EQ(m, Method::polar);
  ASSERT_TRUE(parses(" large ", m));
  EXPECT_EQ(m, Method::large);
  EXPECT_EQ(printed(Method::small), "small");
  EXPECT_EQ(DataTraits<Method>::typeName(), "one of 'small', 'large' or 'polar'");
}

TEST(EnumTraits, UnknownKeywordSuggestsTheNearest) {
  EXPECT_EQ(parseError<Method>("larg"),
            "expected 'small', 'large' or 'polar', got 'larg'; did you mean 'large'?");
  EXPECT_EQ(parseError<Method>("Polar"),
            "expected 'small', 'large' or 'polar', got 'Polar'; did you mean 'polar'?");
  EXPECT_EQ(parseError<Method>("1"), "expected 'small', 'large' or 'polar', got '1'");
  EXPECT_EQ(parseError<Method>("small large"),
            "expected one value (one of 'small', 'large' or 'polar'), got 2");
}

TEST(VectorTraits, ReadsFixedSizeVectors) {
  Vec3d v;
  ASSERT_TRUE(parses("1 -2.5 3e2", v));
  EXPECT_EQ(v, Vec3d(1, -2.5, 300));
  EXPECT_EQ(printed(Vec3d(0.1, 0, -1)), "0.1 0 -1");
  Vec2i i;
  ASSERT_TRUE(parses("4 -5", i));
  EXPECT_EQ(i, Vec2i(4, -5));
  EXPECT_EQ(DataTraits<Vec3d>::typeName(), "Vec3d");
  EXPECT_EQ(DataTraits<Vec2i>::typeName(), "Vec2i");
}

TEST(VectorTraits, RefusesWrongCountsAndGarbage) {
  EXPECT_EQ(parseError<Vec3d>("1 2"), "expected 3 numbers (Vec3d), got 2");
  EXPECT_EQ(parseError<Vec3d>("1 2 3 4"), "expected 3 numbers (Vec3d), got 4");
  EXPECT_EQ(parseError<Vec3d>(""), "expected 3 numbers (Vec3d), got 0");
  EXPECT_EQ(parseError<Vec3d>("1 2 abc"), "expected a number, got 'abc'");
  EXPECT_EQ(parseError<Vec2i>("1 2.5"), "expected an integer, got '2.5'");
  EXPECT_EQ(parseError<Vec2i>("1"), "expected 2 numbers (Vec2i), got 1");
}

TEST(QuatTraits, SceneOrderIsXYZW) {
  Quat q;
  ASSERT_TRUE(parses("0.1 0.2 0.3 0.9", q));
  EXPECT_EQ(q.x(), 0.1);
  EXPECT_EQ(q.y(), 0.2);
  EXPECT_EQ(q.z(), 0.3);
  EXPECT_EQ(q.w(), 0.9);  // read as written, not normalized
  EXPECT_EQ(printed(Quat::Identity()), "0 0 0 1");
  EXPECT_EQ(printed(Quat(0.9, 0.1, 0.2, 0.3)), "0.1 0.2 0.3 0.9");
  EXPECT_EQ(parseError<Quat>("0 0 1"), "expected 4 numbers (Quat), got 3");
}

TEST(RigidTraits, CoordinatesAreSevenNumbers) {
  RigidCoord3 c;
  ASSERT_TRUE(parses("1 2 3 0 0 0.6 0.8", c));
  EXPECT_EQ(c.center, Vec3d(1, 2, 3));
  EXPECT_EQ(c.orientation.z(), 0.6);
  EXPECT_EQ(c.orientation.w(), 0.8);
  EXPECT_EQ(printed(RigidCoord3{}), "0 0 0 0 0 0 1");
  EXPECT_EQ(parseError<RigidCoord3>("1 2 3 0 0 0"),
            "expected 7 numbers (Rigid3d coordinates), got 6");
  EXPECT_EQ(parseError<RigidCoord3>("1 2 3 0 0 0 w"), "expected a number, got 'w'");
}

TEST(RigidTraits, DerivativesAreSixNumbersLinearThenAngular) {
  RigidDeriv3 d;
  ASSERT_TRUE(parses("1 2 3 4 5 6", d));
  EXPECT_EQ(d.linear, Vec3d(1, 2, 3));
  EXPECT_EQ(d.angular, Vec3d(4, 5, 6));
  EXPECT_EQ(printed(RigidDeriv3{}), "0 0 0 0 0 0");
  EXPECT_EQ(parseError<RigidDeriv3>("1 2 3 4 5 6 7"),
            "expected 6 numbers (Rigid3d derivative), got 7");
}

TEST(ListTraits, MultiTokenElementsNeedAMultipleOfTheirSize) {
  std::vector<Vec3d> points;
  ASSERT_TRUE(parses("0 0 0  1 0 0\n0 1 0", points));
  ASSERT_EQ(points.size(), 3u);
  EXPECT_EQ(points[2], Vec3d(0, 1, 0));
  EXPECT_EQ(parseError<std::vector<Vec3d>>("1 2 3 4"),
            "expected a multiple of 3 numbers (list of Vec3d), got 4");
  EXPECT_EQ(parseError<std::vector<RigidCoord3>>("0 0 0 0 0 0 1 0"),
            "expected a multiple of 7 numbers (list of Rigid3d coordinates), got 8");
  EXPECT_EQ(parseError<std::vector<Vec3d>>("1 2 3 4 x 6"), "expected a number, got 'x'");
}

TEST(ListTraits, FailedParseLeavesTheListUnchanged) {
  std::vector<double> v{1, 2};
  std::string error;
  EXPECT_FALSE(DataTraits<std::vector<double>>::parse("3 4 five", v, error));
  EXPECT_EQ(v, (std::vector<double>{1, 2}));
  std::vector<int> indices{9};
  EXPECT_FALSE(DataTraits<std::vector<int>>::parse("1 2 x", indices, error));
  EXPECT_EQ(indices, std::vector<int>{9});
}

TEST(ListTraits, IntegerListsAcceptRanges) {
  std::vector<int> v;
  ASSERT_TRUE(parses("0-3", v));
  EXPECT_EQ(v, (std::vector<int>{0, 1, 2, 3}));
  ASSERT_TRUE(parses("7 2-2 10-12", v));
  EXPECT_EQ(v, (std::vector<int>{7, 2, 10, 11, 12}));
  ASSERT_TRUE(parses("-3--1 -5", v));
  EXPECT_EQ(v, (std::vector<int>{-3, -2, -1, -5}));
  std::vector<unsigned> u;
  ASSERT_TRUE(parses("4-6", u));
  EXPECT_EQ(u, (std::vector<unsigned>{4, 5, 6}));
  // A range ending at the largest value of the type ends.
  ASSERT_TRUE(parses("2147483646-2147483647", v));
  EXPECT_EQ(v, (std::vector<int>{INT_MAX - 1, INT_MAX}));
  std::vector<std::uint8_t> bytes;
  ASSERT_TRUE(parses("253-255", bytes));
  EXPECT_EQ(bytes, (std::vector<std::uint8_t>{253, 254, 255}));
}

TEST(ListTraits, BadRangesAreRefused) {
  // Reversed or huge (a typo's way to exhaust memory).
  EXPECT_THAT(parseError<std::vector<int>>("3-1"), ::testing::StartsWith("bad range '3-1'"));
  EXPECT_THAT(parseError<std::vector<int>>("0-200000000"),
              ::testing::StartsWith("bad range '0-200000000'"));
  EXPECT_EQ(parseError<std::vector<int>>("1-"), "expected an integer or a range 'a-b', got '1-'");
  EXPECT_EQ(parseError<std::vector<int>>("a-b"), "expected an integer or a range 'a-b', got 'a-b'");
  EXPECT_EQ(parseError<std::vector<int>>("1 abc"), "expected an integer, got 'abc'");
}

TEST(TokenReader, SplitsOnAnyWhitespace) {
  TokenReader in(" a\tbb\n\r ccc  ");
  EXPECT_EQ(in.remaining(), 3u);
  std::string_view token;
  ASSERT_TRUE(in.next(token));
  EXPECT_EQ(token, "a");
  EXPECT_EQ(in.remaining(), 2u);
  ASSERT_TRUE(in.next(token));
  EXPECT_EQ(token, "bb");
  EXPECT_FALSE(in.atEnd());
  ASSERT_TRUE(in.next(token));
  EXPECT_EQ(token, "ccc");
  EXPECT_TRUE(in.atEnd());
  EXPECT_FALSE(in.next(token));
  EXPECT_EQ(in.remaining(), 0u);
}

TEST(ForEachNumber, VisitsEveryRealAndInteger) {
  std::vector<double> reals;
  forEachReal(std::vector<RigidCoord3>{RigidCoord3{}}, [&](double x) { reals.push_back(x); });
  EXPECT_EQ(reals, (std::vector<double>{0, 0, 0, 0, 0, 0, 1}));
  std::vector<long long> integers;
  forEachInteger(std::vector<Vec2i>{Vec2i(1, 2), Vec2i(3, 4)},
                 [&](long long x) { integers.push_back(x); });
  EXPECT_EQ(integers, (std::vector<long long>{1, 2, 3, 4}));
  int visited = 0;
  forEachReal(std::string("1 2"), [&](double) { ++visited; });
  forEachInteger(true, [&](long long) { ++visited; });
  forEachInteger(Vec3d(1, 2, 3), [&](long long) { ++visited; });
  EXPECT_EQ(visited, 0);
}

}  // namespace
}  // namespace stroma
