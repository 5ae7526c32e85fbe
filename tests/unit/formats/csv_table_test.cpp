// The numeric CSV both CSV formats are read with: seeded numbers written in the shortest
// round-trip form and as printf's %.17g read back exactly, blank lines skipped, and anything that
// is not one finite number per header column refused naming the file, line and problem.

#include "saltus/formats/csv_table.h"

#include <gtest/gtest.h>

#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include "saltus/base/input_error.h"
#include "support/temp_path.h"

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

std::string temp_file(const std::string& name, const std::string& text) {
  const std::string path = test::temp_path(name).string();
  std::ofstream(path) << text;
  return path;
}

/// The InputError reading `text` as a CSV file raises.
InputError read_error(const std::string& text) {
  const std::string path = temp_file("csv-table-bad.csv", text);
  try {
    read_csv_table(path);
  } catch (const InputError& e) {
    std::filesystem::remove(path);
    return e;
  }
  std::filesystem::remove(path);
  ADD_FAILURE() << "no InputError for:\n" << text;
  return InputError("", "", "");
}

TEST(CsvTable, ReadingErrorsNameTheFileAndLine) {
  EXPECT_EQ(read_error("t,a\n0,1\n0.5,x1\n").json_path(), "line 3");
  EXPECT_EQ(read_error("t,a\n0,1\n0.5,x1\n").problem(), "not a finite number: \"x1\"");
  EXPECT_EQ(read_error("t,a\n0,1,2\n").json_path(), "line 2");
  EXPECT_EQ(read_error("t,a\n0,1,2\n").problem(), "expected 2 values, found 3");
  EXPECT_EQ(read_error("t,a\n0,inf\n").json_path(), "line 2");
  EXPECT_EQ(read_error("").json_path(), "line 1");
  const InputError missing = [] {
    try {
      read_csv_table("/nonexistent/saltus.csv");
    } catch (const InputError& e) {
      return e;
    }
    return InputError("", "", "");
  }();
  EXPECT_EQ(missing.file(), "/nonexistent/saltus.csv");
  EXPECT_EQ(missing.problem(), "cannot open file for reading");
}

TEST(CsvTable, MissingColumnIsNamed) {
  std::stringstream in("t,f\n0,1\n");
  const CsvTable table = parse_csv_table(in, "x.csv");
  try {
    table.column_values("residual", "x.csv");
    ADD_FAILURE() << "found a column that is not there";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("\"residual\""), std::string::npos) << e.what();
  }
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
