// A user's text as a CSV field and a Markdown table cell (formats/table_cells.h): quoted and
// escaped only where the format needs it, and read back as the text (a CSV reader's unquoting
// and GFM's backslash escapes, done here by hand).

#include "saltus/formats/table_cells.h"

#include <gtest/gtest.h>

namespace saltus {
namespace {

/// A quoted RFC 4180 field without its quotes and doubled quotes.
std::string unquoted_csv(const std::string& field) {
  if (field.empty() || field.front() != '"') return field;
  std::string out;
  for (std::size_t i = 1; i + 1 < field.size(); ++i) {
    out += field[i];
    if (field[i] == '"') ++i;  // the second of a pair
  }
  return out;
}

TEST(CsvField, QuotesOnlyWhatRfc4180Requires) {
  EXPECT_EQ(csv_field("junior"), "junior");
  EXPECT_EQ(csv_field("Jüngste | 1"), "Jüngste | 1");
  EXPECT_EQ(csv_field("Smith, Anna"), "\"Smith, Anna\"");
  EXPECT_EQ(csv_field("the \"rocket\""), "\"the \"\"rocket\"\"\"");
  EXPECT_EQ(csv_field("two\nlines"), "\"two\nlines\"");
  EXPECT_EQ(csv_field("cr\r"), "\"cr\r\"");
  for (const std::string text : {"a,b", "\"", "\"\"x\"", "x\r\ny", ",", ""})
    EXPECT_EQ(unquoted_csv(csv_field(text)), text) << text;
}

TEST(MarkdownCell, EscapesPipesBackslashesAndControlCharacters) {
  EXPECT_EQ(markdown_cell("junior"), "junior");
  EXPECT_EQ(markdown_cell("a|b"), "a\\|b");
  EXPECT_EQ(markdown_cell("ends\\"), "ends\\\\");  // would have escaped the cell's closing pipe
  EXPECT_EQ(markdown_cell("two\nlines"), "two\\\\x0Alines");
  EXPECT_EQ(markdown_cell("\x1b[31mred"), "\\\\x1B[31mred");
  EXPECT_EQ(markdown_cell("Jüngste"), "Jüngste");
  EXPECT_EQ(markdown_cell("bad\xff"), "bad\\\\xFF");
}

}  // namespace
}  // namespace saltus
