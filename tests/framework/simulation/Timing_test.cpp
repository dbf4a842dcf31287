// SPDX-License-Identifier: MIT
// Timing: wall time per named phase, accumulated in order of first appearance.
#include "simulation/Timing.h"

#include <gtest/gtest.h>

#include <chrono>
#include <thread>

namespace stroma {
namespace {

TEST(Timing, AccumulatesSecondsAndCallsPerPhase) {
  Timing t;
  t.add("step", 0.5);
  t.add("load", 2.0);
  t.add("step", 0.25);
  ASSERT_EQ(t.phases().size(), 2u);
  EXPECT_EQ(t.phases()[0].name, "step");  // order of first appearance
  EXPECT_EQ(t.phases()[0].seconds, 0.75);
  EXPECT_EQ(t.phases()[0].calls, 2);
  EXPECT_EQ(t.phases()[1].name, "load");
  EXPECT_EQ(t.phases()[1].calls, 1);
  EXPECT_EQ(t.seconds("step"), 0.75);
  EXPECT_EQ(t.seconds("load"), 2.0);
  EXPECT_EQ(t.seconds("unknown"), 0.0);
}

TEST(Timing, ClearForgetsEveryPhase) {
  Timing t;
  t.add("init", 1.0);
  t.clear();
  EXPECT_TRUE(t.phases().empty());
  EXPECT_EQ(t.seconds("init"), 0.0);
}

TEST(ScopedPhase, AddsTheTimeOfItsScope) {
  Timing t;
  {
    ScopedPhase phase(t, "sleep");
    EXPECT_TRUE(t.phases().empty());  // added when the scope ends
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  ASSERT_EQ(t.phases().size(), 1u);
  EXPECT_EQ(t.phases()[0].calls, 1);
  EXPECT_GE(t.seconds("sleep"), 0.019);
  EXPECT_LT(t.seconds("sleep"), 10.0);
  { ScopedPhase again(t, "sleep"); }
  EXPECT_EQ(t.phases()[0].calls, 2);
  EXPECT_GE(t.seconds("sleep"), 0.019);
}

}  // namespace
}  // namespace stroma
