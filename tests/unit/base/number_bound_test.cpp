// A number's accepted interval (base/number_bound.h): closed, open and unbounded ends, whole
// numbers, NaN and ±inf never inside, and the one message with short numbers that still tell a
// value just past a bound from the bound.

#include "saltus/base/number_bound.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "saltus/base/input_error.h"

namespace saltus {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

NumberBound closed(double lower, double upper, const char* unit = "") {
  NumberBound b;
  b.lower = lower;
  b.upper = upper;
  b.unit = unit;
  return b;
}

TEST(NumberBound, TakesItsClosedEndsAndRefusesOneStepPastThem) {
  const NumberBound b = closed(0.5, 2.8, "m");
  EXPECT_TRUE(within(b, 0.5));
  EXPECT_TRUE(within(b, 2.8));
  EXPECT_FALSE(within(b, std::nextafter(0.5, 0.0)));
  EXPECT_FALSE(within(b, std::nextafter(2.8, 3.0)));
  EXPECT_EQ(bound_problem(b, 1.0), "");
  EXPECT_EQ(bound_problem(b, 3.0), "3 m is outside [0.5, 2.8] m");
  // Six digits would print the bound itself ("2.8 m is outside [0.5, 2.8]"): every digit then.
  EXPECT_EQ(bound_problem(b, 2.8000001), "2.8000001 m is outside [0.5, 2.8] m");
  EXPECT_EQ(bound_problem(b, 1e300, "the human range"),
            "1e+300 m is outside [0.5, 2.8] m (the human range)");
}

TEST(NumberBound, AnOpenEndIsRefusedAndAnInfiniteEndIsNeverReached) {
  NumberBound positive = closed(0.0, kInf, "N");
  positive.lower_open = true;
  EXPECT_FALSE(within(positive, 0.0));
  EXPECT_TRUE(within(positive, std::numeric_limits<double>::denorm_min()));
  EXPECT_TRUE(within(positive, std::numeric_limits<double>::max()));
  EXPECT_FALSE(within(positive, kInf));
  EXPECT_EQ(bound_text(positive), "(0, ∞) N");
  EXPECT_EQ(bound_problem(positive, 0.0), "0 N is outside (0, ∞) N");
  NumberBound below = closed(-kInf, 120.0);
  below.upper_open = true;
  EXPECT_EQ(bound_text(below), "(-∞, 120)");
  EXPECT_FALSE(within(below, 120.0));
  EXPECT_TRUE(within(below, std::nextafter(120.0, 0.0)));
  EXPECT_FALSE(within(below, -kInf));
}

TEST(NumberBound, NaNAndInfinitiesAreNeverWithin) {
  const NumberBound anything = closed(-kInf, kInf, "s");
  EXPECT_TRUE(within(anything, -std::numeric_limits<double>::max()));
  for (double v : {std::nan(""), kInf, -kInf}) {
    EXPECT_FALSE(within(anything, v)) << v;
    EXPECT_NE(bound_problem(anything, v).find(" is outside (-∞, ∞) s"), std::string::npos)
        << bound_problem(anything, v);
  }
}

TEST(NumberBound, AWholeBoundTakesWholeNumbersOnlyAndPrintsItsEndsInFull) {
  NumberBound b = closed(0, 4294967295.0);
  b.whole = true;
  EXPECT_TRUE(within(b, 4294967295.0));
  EXPECT_FALSE(within(b, 4294967296.0));
  EXPECT_FALSE(within(b, 2.5));
  EXPECT_EQ(bound_text(b), "[0, 4294967295]");
  EXPECT_EQ(bound_problem(b, 2.5), "2.5 is not a whole number (allowed: [0, 4294967295])");
}

TEST(NumberBound, CheckBoundThrowsAnInputErrorNamingTheFlag) {
  EXPECT_NO_THROW(check_bound("--age", closed(5, 100, "years"), 5));
  try {
    check_bound("--age", closed(5, 100, "years"), 101);
    FAIL() << "101 years taken";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "--age: 101 years is outside [5, 100] years");
    EXPECT_EQ(e.file(), "--age");
  }
}

}  // namespace
}  // namespace saltus
