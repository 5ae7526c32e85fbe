// The numeric CSV both CSV formats are read with: seeded numbers written in the shortest
// round-trip form and as printf's %.17g read back exactly, blank lines skipped, and anything that
// is not one finite number per header column refused naming the file and line.

#include "saltus/formats/csv_table.h"

#include <gtest/gtest.h>

#include <charconv>
#include <cmath>
#include <cstdio>
#include <random>
#include <sstream>

#include "saltus/base/input_error.h"

namespace saltus {
namespace {

TEST(CsvTable, NumbersAndErrors) {
  std::stringstream good("a,b\n1,-2.5e-3\n\n3,4\n");
  const CsvTable t = parse_csv_table(good, "x.csv");
  EXPECT_EQ(t.columns, (std::vector<std::string>{"a", "b"}));
  EXPECT_EQ(t.rows, (std::vector<std::vector<double>>{{1, -2.5e-3}, {3, 4}}));
  EXPECT_EQ(t.column("b"), 1);
  EXPECT_EQ(t.column("c"), -1);
  EXPECT_EQ(t.column_values("b", "x.csv"), (std::vector<double>{-2.5e-3, 4}));
  EXPECT_THROW(t.column_values("c", "x.csv"), InputError);
  for (const char* bad :
       {"a\n1,2\n", "a\nnan\n", "a\ninf\n", "a\n1.5x\n", "a\n\"1\"\n", "a\n,\n", "a\n 1\n", ""}) {
    std::stringstream in(bad);
    EXPECT_THROW(parse_csv_table(in, "x.csv"), InputError) << bad;
  }
}

TEST(CsvTable, ErrorsNameTheFileAndLine) {
  const std::vector<std::pair<std::string, std::string>> cases{
      {"a,b\n1,2\n3\n", "line 3"},
      {"a,b\n1,2\n\n3,x\n", "line 4"},
      {"", "line 1"},
  };
  for (const auto& [text, where] : cases) {
    std::stringstream in(text);
    try {
      parse_csv_table(in, "dir/table.csv");
      ADD_FAILURE() << "accepted " << text;
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("dir/table.csv"), std::string::npos) << what;
      EXPECT_NE(what.find(where), std::string::npos) << what;
    }
  }
  std::stringstream in("t,f\n0,1\n");
  const CsvTable table = parse_csv_table(in, "x.csv");
  try {
    table.column_values("residual", "x.csv");
    ADD_FAILURE() << "found a column that is not there";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("\"residual\""), std::string::npos) << e.what();
  }
  EXPECT_THROW(read_csv_table("/nonexistent/table.csv"), InputError);
}

TEST(CsvTable, SeededNumbersReadBackExactly) {
  for (unsigned seed = 1; seed <= 5; ++seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> mantissa(-10, 10);
    std::uniform_int_distribution<int> exponent(-300, 300);
    std::vector<std::vector<double>> rows(40, std::vector<double>(3));
    std::string shortest = "x,y,z\n", printf_form = "x,y,z\n";
    for (auto& row : rows) {
      for (std::size_t c = 0; c < row.size(); ++c) {
        row[c] = mantissa(rng) * std::pow(10.0, exponent(rng) / (c + 1.0));
        char buffer[40];
        const auto end = std::to_chars(buffer, buffer + sizeof buffer, row[c]).ptr;
        shortest += std::string(buffer, end) + (c + 1 < row.size() ? "," : "\n");
        std::snprintf(buffer, sizeof buffer, "%.17g", row[c]);
        printf_form += std::string(buffer) + (c + 1 < row.size() ? "," : "\n");
      }
    }
    std::stringstream a(shortest), b(printf_form);
    EXPECT_EQ(parse_csv_table(a, "a.csv").rows, rows) << seed;
    EXPECT_EQ(parse_csv_table(b, "b.csv").rows, rows) << seed;
  }
}

}  // namespace
}  // namespace saltus
