// SPDX-License-Identifier: MIT
// Data<T>: reading scene text with the declared options, links between Data (lazy copies,
// conversions through text, cycles) and DataEngine's lazy recomputation.
#include "core/Data.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "core/Base.h"

namespace stroma {
namespace {

// A component with one Data of each option kind.
struct Material : Base {
  Data<double> d_youngModulus{
      this, "youngModulus", 5000.0, "Young's modulus", {.unit = "Pa", .min = 0.0}};
  Data<double> d_poissonRatio{
      this, "poissonRatio", 0.3, "Poisson's ratio", {.min = 0.0, .max = 0.5}};
  Data<int> d_level{this, "level", 2, "Refinement level", {.min = 0, .max = 10}};
  Data<int> d_minOnly{this, "minOnly", 1, "At least one", {.min = 1}};
  Data<int> d_maxOnly{this, "maxOnly", 1, "At most three", {.max = 3}};
  Data<double> d_free{this, "free", 1.0, "Any number, also NaN", {.allowNonFinite = true}};
  Data<std::vector<double>> d_weights{this, "weights", {}, "Weights", {.min = 0.0}};
  Data<Vec3d> d_gravity{this, "gravity", Vec3d(0, -9.81, 0), "Gravity"};
};

std::string readError(BaseData& data, std::string_view text) {
  std::string error;
  EXPECT_FALSE(data.read(text, error)) << "'" << text << "' was accepted by " << data.name();
  return error;
}

TEST(Data, DeclarationRegistersTheFieldWithItsDocumentation) {
  Material m;
  BaseData* young = m.findData("youngModulus");
  ASSERT_EQ(young, &m.d_youngModulus);
  EXPECT_EQ(young->owner(), &m);
  EXPECT_EQ(young->help(), "Young's modulus");
  EXPECT_EQ(young->options().unit, "Pa");
  EXPECT_EQ(young->typeName(), "real");
  EXPECT_EQ(young->defaultText(), "5000");
  EXPECT_EQ(young->valueText(), "5000");
  EXPECT_FALSE(young->isSet());
  EXPECT_EQ(m.findData("nothing"), nullptr);
}

TEST(Data, ReadSetsTheValueAndCountsAVersion) {
  Material m;
  const auto before = m.d_youngModulus.version();
  std::string error;
  ASSERT_TRUE(m.d_youngModulus.read("1e6", error)) << error;
  EXPECT_EQ(m.d_youngModulus.value(), 1e6);
  EXPECT_EQ(m.d_youngModulus.valueText(), "1e+06");  // the shorter of the exact forms
  EXPECT_EQ(m.d_youngModulus.defaultText(), "5000");
  EXPECT_EQ(m.d_youngModulus.defaultValue(), 5000.0);
  EXPECT_TRUE(m.d_youngModulus.isSet());
  EXPECT_EQ(m.d_youngModulus.version(), before + 1);
}

TEST(Data, FailedReadLeavesTheValueUnchangedAndUnset) {
  Material m;
  const auto before = m.d_gravity.version();
  EXPECT_EQ(readError(m.d_gravity, "0 -9.81"), "expected 3 numbers (Vec3d), got 2");
  EXPECT_EQ(readError(m.d_gravity, "0 abc 0"), "expected a number, got 'abc'");
  EXPECT_EQ(m.d_gravity.value(), Vec3d(0, -9.81, 0));
  EXPECT_FALSE(m.d_gravity.isSet());
  EXPECT_EQ(m.d_gravity.version(), before);

  EXPECT_EQ(readError(m.d_youngModulus, "-1"), "expected a value >= 0, got -1");
  EXPECT_EQ(m.d_youngModulus.value(), 5000.0);
  EXPECT_FALSE(m.d_youngModulus.isSet());
}

TEST(Data, NonFiniteNumbersAreRefusedUnlessAllowed) {
  Material m;
  EXPECT_EQ(readError(m.d_gravity, "0 nan 0"), "expected a finite number, got NaN");
  EXPECT_EQ(readError(m.d_gravity, "0 inf 0"), "expected a finite number, got infinity");
  EXPECT_EQ(readError(m.d_gravity, "-inf 0 0"), "expected a finite number, got infinity");
  EXPECT_EQ(readError(m.d_weights, "1 NaN"), "expected a finite number, got NaN");
  EXPECT_TRUE(m.d_weights.value().empty());

  std::string error;
  ASSERT_TRUE(m.d_free.read("nan", error)) << error;
  EXPECT_TRUE(std::isnan(m.d_free.value()));
  EXPECT_EQ(m.d_free.valueText(), "nan");
  ASSERT_TRUE(m.d_free.read("-inf", error)) << error;
  EXPECT_EQ(m.d_free.value(), -std::numeric_limits<double>::infinity());
  EXPECT_EQ(m.d_free.valueText(), "-inf");
}

TEST(Data, RealBoundsAreInclusive) {
  Material m;
  std::string error;
  EXPECT_TRUE(m.d_poissonRatio.read("0", error)) << error;
  EXPECT_TRUE(m.d_poissonRatio.read("0.5", error)) << error;
  EXPECT_EQ(readError(m.d_poissonRatio, "0.50001"), "expected a value <= 0.5, got 0.50001");
  EXPECT_EQ(readError(m.d_poissonRatio, "-0.1"), "expected a value >= 0, got -0.1");
  EXPECT_EQ(m.d_poissonRatio.value(), 0.5);
  // Bounds apply to every number of a list.
  EXPECT_EQ(readError(m.d_weights, "1 2 -3 4"), "expected a value >= 0, got -3");
  EXPECT_TRUE(m.d_weights.read("1 2 3", error)) << error;
  EXPECT_EQ(m.d_weights.value(), (std::vector<double>{1, 2, 3}));
}

TEST(Data, IntegerBoundsNameTheAllowedRange) {
  Material m;
  std::string error;
  EXPECT_TRUE(m.d_level.read("10", error)) << error;
  EXPECT_EQ(readError(m.d_level, "11"), "value 11 is outside the allowed range [0, 10]");
  EXPECT_EQ(readError(m.d_level, "-1"), "value -1 is outside the allowed range [0, 10]");
  EXPECT_EQ(readError(m.d_minOnly, "0"), "value 0 is outside the allowed range [1, +inf)");
  EXPECT_EQ(readError(m.d_maxOnly, "4"), "value 4 is outside the allowed range (-inf, 3]");
  EXPECT_EQ(m.d_level.value(), 10);
}

TEST(Data, SetValueAndEditCountAsChanges) {
  Material m;
  auto v = m.d_weights.version();
  m.d_weights.setValue({1, 2});
  EXPECT_EQ(m.d_weights.version(), ++v);
  EXPECT_TRUE(m.d_weights.isSet());
  m.d_weights.edit().push_back(3);
  EXPECT_EQ(m.d_weights.version(), ++v);
  EXPECT_EQ(m.d_weights.valueText(), "1 2 3");
  // Reading does not change the version.
  (void)m.d_weights.value();
  EXPECT_EQ(m.d_weights.version(), v);
}

TEST(DataLink, ChildTakesTheParentValueLazily) {
  Data<double> parent{nullptr, "parent", 1.0, "parent"};
  Data<double> child{nullptr, "child", 0.0, "child"};
  std::string error;
  ASSERT_TRUE(child.setParent(&parent, error)) << error;
  EXPECT_EQ(child.parent(), &parent);
  EXPECT_EQ(child.value(), 1.0);
  EXPECT_TRUE(child.isSet());

  const auto v = child.version();
  parent.setValue(2.0);
  parent.setValue(3.0);
  // Two changes of the parent, one copy when the child is read.
  EXPECT_EQ(child.value(), 3.0);
  EXPECT_EQ(child.version(), v + 1);
  EXPECT_EQ(child.value(), 3.0);
  EXPECT_EQ(child.version(), v + 1);
  EXPECT_EQ(child.valueText(), "3");
}

TEST(DataLink, ChainsPropagateThroughEveryLevel) {
  Data<int> a{nullptr, "a", 1, ""};
  Data<int> b{nullptr, "b", 0, ""};
  Data<int> c{nullptr, "c", 0, ""};
  std::string error;
  ASSERT_TRUE(b.setParent(&a, error)) << error;
  ASSERT_TRUE(c.setParent(&b, error)) << error;
  a.setValue(7);
  EXPECT_EQ(c.value(), 7);
  EXPECT_EQ(b.value(), 7);
}

TEST(DataLink, StoppingToFollowKeepsTheLastValue) {
  Data<double> parent{nullptr, "parent", 1.0, ""};
  Data<double> child{nullptr, "child", 0.0, ""};
  std::string error;
  ASSERT_TRUE(child.setParent(&parent, error)) << error;
  ASSERT_TRUE(child.setParent(nullptr, error)) << error;
  EXPECT_EQ(child.parent(), nullptr);
  parent.setValue(5.0);
  EXPECT_EQ(child.value(), 1.0);
}

TEST(DataLink, DifferentTypesConvertThroughText) {
  Data<std::vector<Vec3d>> points{nullptr, "position", {Vec3d(1, 2, 3), Vec3d(4, 5, 6)}, ""};
  Data<std::vector<double>> flat{nullptr, "flat", {}, ""};
  std::string error;
  ASSERT_TRUE(flat.setParent(&points, error)) << error;
  EXPECT_EQ(flat.value(), (std::vector<double>{1, 2, 3, 4, 5, 6}));
  points.edit().push_back(Vec3d(0.1, 0.2, 0.3));
  EXPECT_EQ(flat.value().size(), 9u);
  EXPECT_EQ(flat.value().back(), 0.3);

  Data<std::vector<Vec3d>> back{nullptr, "back", {}, ""};
  ASSERT_TRUE(back.setParent(&flat, error)) << error;
  EXPECT_EQ(back.value(), points.value());

  Data<int> count{nullptr, "count", 3, ""};
  Data<double> real{nullptr, "real", 0.0, ""};
  ASSERT_TRUE(real.setParent(&count, error)) << error;
  EXPECT_EQ(real.value(), 3.0);
}

TEST(DataLink, IncompatibleTypesAreRefusedAndNothingChanges) {
  Data<std::vector<double>> four{nullptr, "four", {1, 2, 3, 4}, ""};
  Data<std::vector<Vec3d>> points{nullptr, "points", {Vec3d(9, 9, 9)}, ""};
  std::string error;
  EXPECT_FALSE(points.setParent(&four, error));
  EXPECT_EQ(error,
            "cannot take the value of 'four' (list of real): expected a multiple of 3 numbers "
            "(list of Vec3d), got 4");
  EXPECT_EQ(points.parent(), nullptr);
  EXPECT_FALSE(points.isSet());
  EXPECT_EQ(points.value(), std::vector<Vec3d>{Vec3d(9, 9, 9)});

  Data<double> real{nullptr, "real", 2.5, ""};
  Data<int> integer{nullptr, "integer", 1, ""};
  EXPECT_FALSE(integer.setParent(&real, error));
  EXPECT_EQ(error, "cannot take the value of 'real' (real): expected an integer, got '2.5'");
  EXPECT_EQ(integer.value(), 1);

  Data<std::string> word{nullptr, "word", "hello", ""};
  EXPECT_FALSE(real.setParent(&word, error));
  EXPECT_EQ(error, "cannot take the value of 'word' (string): expected a number, got 'hello'");
}

TEST(DataLink, LinkedValuesRespectTheChildOptions) {
  Material m;
  Data<int> negative{nullptr, "negative", -1, ""};
  std::string error;
  EXPECT_FALSE(m.d_youngModulus.setParent(&negative, error));
  EXPECT_EQ(error, "cannot take the value of 'negative' (int): expected a value >= 0, got -1");

  // The same check when the types are the same and the value is copied directly.
  Data<double> negativeReal{nullptr, "negativeReal", -2.0, ""};
  EXPECT_FALSE(m.d_youngModulus.setParent(&negativeReal, error));
  EXPECT_EQ(error, "cannot take the value of 'negativeReal' (real): expected a value >= 0, got -2");
  EXPECT_EQ(m.d_youngModulus.value(), 5000.0);
  EXPECT_EQ(m.d_youngModulus.parent(), nullptr);
}

TEST(DataLink, LaterConversionFailureKeepsTheOldValue) {
  Data<std::string> text{nullptr, "text", "1.5", ""};
  Data<double> real{nullptr, "real", 0.0, ""};
  std::string error;
  ASSERT_TRUE(real.setParent(&text, error)) << error;
  EXPECT_EQ(real.value(), 1.5);
  text.setValue("not a number");
  EXPECT_EQ(real.value(), 1.5);
  text.setValue("2.5");
  EXPECT_EQ(real.value(), 2.5);
}

TEST(DataLink, CyclesAreRefused) {
  Data<int> a{nullptr, "a", 1, ""};
  Data<int> b{nullptr, "b", 2, ""};
  Data<int> c{nullptr, "c", 3, ""};
  std::string error;
  EXPECT_FALSE(a.setParent(&a, error));
  EXPECT_EQ(error, "a Data cannot follow itself");
  ASSERT_TRUE(b.setParent(&a, error)) << error;
  ASSERT_TRUE(c.setParent(&b, error)) << error;
  EXPECT_FALSE(a.setParent(&c, error));
  EXPECT_EQ(error, "following 'c' would make a cycle of links");
  EXPECT_FALSE(a.setParent(&b, error));
  EXPECT_EQ(error, "following 'b' would make a cycle of links");
  EXPECT_EQ(a.parent(), nullptr);
  EXPECT_EQ(a.value(), 1);
  EXPECT_EQ(c.value(), 1);
}

TEST(DataLink, LinkTextIsKeptForTheLoader) {
  Data<double> d{nullptr, "d", 0.0, ""};
  EXPECT_EQ(d.linkText(), "");
  d.setLinkText("@loader.position");
  EXPECT_EQ(d.linkText(), "@loader.position");
}

// Sum of two inputs, counting its computations.
struct SumEngine : Base, DataEngine {
  Data<double> d_a{this, "a", 1.0, "first term"};
  Data<double> d_b{this, "b", 2.0, "second term"};
  Data<double> d_sum{this, "sum", 0.0, "a + b", {.output = true}};
  int updates = 0;

  SumEngine() {
    addInput(&d_a);
    addInput(&d_b);
    addOutput(&d_sum);
  }

 protected:
  void doUpdate() override {
    ++updates;
    // Reading its own output while computing must not recurse.
    d_sum.setValue(d_a.value() + d_b.value() + 0.0 * d_sum.value());
  }
};

TEST(DataEngine, OutputIsComputedOnFirstReadOnly) {
  SumEngine e;
  EXPECT_EQ(e.updates, 0);
  EXPECT_EQ(e.d_sum.value(), 3.0);
  EXPECT_EQ(e.updates, 1);
  EXPECT_EQ(e.d_sum.value(), 3.0);
  EXPECT_EQ(e.d_sum.valueText(), "3");
  EXPECT_EQ(e.updates, 1);
  EXPECT_TRUE(e.d_sum.options().output);
}

TEST(DataEngine, OutputIsRecomputedOnceAfterInputsChanged) {
  SumEngine e;
  (void)e.d_sum.value();
  e.d_a.setValue(10.0);
  e.d_b.setValue(20.0);
  EXPECT_EQ(e.updates, 1);  // lazily: nothing until the output is read
  EXPECT_EQ(e.d_sum.value(), 30.0);
  EXPECT_EQ(e.updates, 2);
  std::string error;
  ASSERT_TRUE(e.d_b.read("5", error)) << error;
  EXPECT_EQ(e.d_sum.value(), 15.0);
  EXPECT_EQ(e.updates, 3);
  // A failed read is no change.
  EXPECT_FALSE(e.d_b.read("x", error));
  EXPECT_EQ(e.d_sum.value(), 15.0);
  EXPECT_EQ(e.updates, 3);
}

TEST(DataEngine, SetDirtyForcesOneRecomputation) {
  SumEngine e;
  (void)e.d_sum.value();
  e.setDirty();
  EXPECT_EQ(e.d_sum.value(), 3.0);
  EXPECT_EQ(e.updates, 2);
  EXPECT_EQ(e.d_sum.value(), 3.0);
  EXPECT_EQ(e.updates, 2);
}

TEST(DataEngine, InputsFollowingParentsTriggerRecomputation) {
  SumEngine e;
  Data<double> source{nullptr, "source", 4.0, ""};
  std::string error;
  ASSERT_TRUE(e.d_a.setParent(&source, error)) << error;
  EXPECT_EQ(e.d_sum.value(), 6.0);
  const int updates = e.updates;
  source.setValue(100.0);
  EXPECT_EQ(e.d_sum.value(), 102.0);
  EXPECT_EQ(e.updates, updates + 1);

  // A Data following the output sees the recomputed value.
  Data<double> follower{nullptr, "follower", 0.0, ""};
  ASSERT_TRUE(follower.setParent(&e.d_sum, error)) << error;
  EXPECT_EQ(follower.value(), 102.0);
  source.setValue(0.0);
  EXPECT_EQ(follower.value(), 2.0);
  EXPECT_EQ(e.updates, updates + 2);
}

}  // namespace
}  // namespace stroma
