// Numbers and user text (base/text_format.h): a printf pattern as the C library applies it, the six
// significant digits of the stream default, compared here with printf's %g (the same rule), and
// user strings made printable (well-formed UTF-8 kept, everything else as \xNN).

#include "saltus/base/text_format.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
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

TEST(ExactNumber, ReadsBackToTheSameDoubleInTheShortestForm) {
  for (double v : {1.0 / 3.0, 0.1 + 0.2, -1e-300, 6.02214076e23, 4.9e-324, 1.7976931348623157e308})
    EXPECT_EQ(std::strtod(exact_number(v).c_str(), nullptr), v) << exact_number(v);
  EXPECT_EQ(exact_number(0.1), "0.1");
  EXPECT_EQ(exact_number(-2.5), "-2.5");
  EXPECT_EQ(exact_number(-0.0), "0") << "no negative zero in a data file";
  EXPECT_EQ(exact_number(12.0), "12");
}

TEST(XmlText, EscapesMarkupAndControlCharacters) {
  EXPECT_EQ(xml_text("thigh_l"), "thigh_l");
  EXPECT_EQ(xml_text("a<b & \"c\" 'd'>"), "a&lt;b &amp; &quot;c&quot; &apos;d&apos;&gt;");
  EXPECT_EQ(xml_text("line\nbreak"), "line\\x0Abreak");
  EXPECT_EQ(xml_text("h\u00e9"), "h\u00e9") << "UTF-8 stays";
}

TEST(MessageNumber, GivesSixSignificantDigitsLikePercentG) {
  for (double v : {1.0 / 3.0, 1e-7, 123456789.0, -0.0001234567, 40.0, 0.1 + 0.2, 1e300}) {
    char expected[64];
    std::snprintf(expected, sizeof expected, "%g", v);
    EXPECT_EQ(message_number(v), expected) << v;
  }
  EXPECT_EQ(message_number(1.4), "1.4");
}

TEST(MessageNumberBeside, NeverPrintsAValueAsABoundItIsNot) {
  EXPECT_EQ(message_number_beside(300.0000001, 10, 300), "300.0000001");
  EXPECT_EQ(std::stod(message_number_beside(300.0000001, 10, 300)), 300.0000001);
  EXPECT_EQ(message_number_beside(9.9999999, 10, 300), "9.9999999");
  EXPECT_EQ(message_number_beside(1.2000001, 0.8, 1.2), "1.2000001");
  EXPECT_EQ(message_number_beside(300, 10, 300), "300");                // the bound itself
  EXPECT_EQ(message_number_beside(450.123456789, 10, 300), "450.123");  // short when apart
  EXPECT_EQ(message_number_beside(1e308, 10, 300), "1e+308");
}

TEST(WithArticle, PicksAOrAnByTheFirstLetter) {
  EXPECT_EQ(with_article("import"), "an import");
  EXPECT_EQ(with_article("body model"), "a body model");
  EXPECT_EQ(with_article("Evaluate"), "an Evaluate");
  EXPECT_EQ(with_article(""), "");
}

TEST(MessageText, KeepsAMessageOnOneLineAndShort) {
  EXPECT_EQ(message_text("Left Up Leg"), "Left Up Leg");
  EXPECT_EQ(message_text("caf\xC3\xA9"), "caf\xC3\xA9");  // UTF-8 stays as it is
  // A newline would split the message, an ESC sequence would recolour the terminal.
  EXPECT_EQ(message_text("a\nb\x1B[31mred\x7F"), "a\\x0Ab\\x1B[31mred\\x7F");
  EXPECT_EQ(message_text("\xFF"), "\\xFF");
  const std::string long_name(5000, 'x');
  EXPECT_EQ(message_text(long_name), std::string(80, 'x') + "... (5000 bytes)");
  EXPECT_EQ(message_text(long_name, 10), "xxxxxxxxxx... (5000 bytes)");
  // The cut falls between characters and escapes, never inside one.
  EXPECT_EQ(message_text("ab\xC3\xA9", 3), "ab... (4 bytes)");
  EXPECT_EQ(message_text("ab\n", 4), "ab... (3 bytes)");
  for (std::size_t limit = 0; limit < 29; ++limit) {  // 29 bytes escaped
    const std::string out = message_text("\x01\xC3\xA9\n\x1B caf\xC3\xA9 \xFF\x02", limit);
    EXPECT_EQ(out.find('\n'), std::string::npos);
    EXPECT_EQ(out.find('\x1B'), std::string::npos);
    EXPECT_LE(out.find("..."), limit) << out;
  }
}

TEST(Printable, ValidatesUtf8AndEscapesWhatIsNotPrintable) {
  EXPECT_TRUE(is_valid_utf8("plain ascii"));
  EXPECT_TRUE(is_valid_utf8("caf\xC3\xA9 \xE2\x82\xAC \xF0\x9F\x98\x80"));
  EXPECT_FALSE(is_valid_utf8("\xFF"));
  EXPECT_FALSE(is_valid_utf8("\xC0\xAF"));          // overlong '/'
  EXPECT_FALSE(is_valid_utf8("\xED\xA0\x80"));      // a surrogate
  EXPECT_FALSE(is_valid_utf8("\xF4\x90\x80\x80"));  // past U+10FFFF
  EXPECT_FALSE(is_valid_utf8("\xE2\x82"));          // truncated
  EXPECT_EQ(printable("a\xFF"
                      "b\n"),
            "a\\xFFb\\x0A");
  EXPECT_EQ(printable("caf\xC3\xA9"), "caf\xC3\xA9");
}

}  // namespace
}  // namespace saltus
