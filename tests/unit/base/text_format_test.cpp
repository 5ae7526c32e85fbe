// Numbers as text (base/text_format.h): a printf pattern as the C library applies it, and the six
// significant digits of the stream default, compared here with printf's %g (the same rule).

#include "saltus/base/text_format.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>

namespace saltus {
namespace {

TEST(FormatNumber, AppliesThePrintfPattern) {
  EXPECT_EQ(format_number("%.2f N", 3.14159), "3.14 N");
  EXPECT_EQ(format_number("±%g s", 0.05), "±0.05 s");
  EXPECT_EQ(format_number("%.1f %%", 12.25), "12.2 %");  // round half to even, as printf does
  EXPECT_EQ(format_number("%5.0f|", -2.5), "   -2|");
  // A pattern longer than any buffer is written whole, not cut.
  const std::string text(200, 'x');
  EXPECT_EQ(format_number((text + " %.1f").c_str(), 1.0), text + " 1.0");
  EXPECT_EQ(format_number("%.0f", 1e300).size(), 301u);
}

TEST(MessageNumber, GivesSixSignificantDigitsLikePercentG) {
  for (double v : {1.0 / 3.0, 1e-7, 123456789.0, -0.0001234567, 40.0, 0.1 + 0.2, 1e300}) {
    char expected[64];
    std::snprintf(expected, sizeof expected, "%g", v);
    EXPECT_EQ(message_number(v), expected) << v;
  }
  EXPECT_EQ(message_number(1.4), "1.4");
}

}  // namespace
}  // namespace saltus
