// SPDX-License-Identifier: MIT
// parseColor: SOFA's color forms (names, #hex, 3 or 4 numbers) and clear refusals.
#include <gtest/gtest.h>

#include "simulation/Color.h"

namespace stroma {
namespace {

Vec4d color(const char* text) {
  Vec4d c(-1, -1, -1, -1);
  std::string error;
  EXPECT_TRUE(parseColor(text, c, error)) << text << ": " << error;
  return c;
}

std::string refusal(const char* text) {
  Vec4d c;
  std::string error;
  EXPECT_FALSE(parseColor(text, c, error)) << text;
  return error;
}

TEST(Color, ReadsSofasForms) {
  EXPECT_EQ(color("red"), Vec4d(1, 0, 0, 1));
  EXPECT_EQ(color(" gray "), Vec4d(0.5, 0.5, 0.5, 1));
  EXPECT_EQ(color("0.23 0.25 0.42"), Vec4d(0.23, 0.25, 0.42, 1));
  EXPECT_EQ(color("0.1 .8 .3 .5"), Vec4d(0.1, 0.8, 0.3, 0.5));
  EXPECT_EQ(color("#ff8000"), Vec4d(1, 128 / 255.0, 0, 1));
  EXPECT_EQ(color("#00000080"), Vec4d(0, 0, 0, 128 / 255.0));
}

TEST(Color, RefusesWithAReason) {
  EXPECT_NE(refusal("redd").find("unknown color name 'redd'"), std::string::npos);
  EXPECT_NE(refusal("1 0").find("expected 3 (r g b) or 4"), std::string::npos);
  EXPECT_NE(refusal("1 0 x").find("'x'"), std::string::npos);
  EXPECT_NE(refusal("2 0 0").find("outside [0, 1]"), std::string::npos);
  EXPECT_NE(refusal("#12345").find("#rrggbb"), std::string::npos);
  EXPECT_NE(refusal("#gg0000").find("hexadecimal"), std::string::npos);
  EXPECT_NE(refusal("").find("empty"), std::string::npos);
}

}  // namespace
}  // namespace stroma
