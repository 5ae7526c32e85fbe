#include "saltus/body/strength_tables.h"

#include <charconv>
#include <sstream>
#include <stdexcept>

#include "saltus/base/embedded_text.h"

namespace saltus {

namespace {

/// The rows of a small CSV file with a header line, as cells; every row as wide as the header.
std::vector<std::vector<std::string>> csv_rows(const std::string& text, const char* name) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream lines(text);
  std::string line;
  std::size_t width = 0;
  while (std::getline(lines, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) continue;
    std::vector<std::string> cells;
    std::istringstream fields(line);
    std::string cell;
    while (std::getline(fields, cell, ','))
      cells.push_back(cell);
    if (width == 0) {
      width = cells.size();
      continue;  // the header
    }
    if (cells.size() != width)
      throw std::logic_error(std::string("strength table ") + name + ": a row of " +
                             std::to_string(cells.size()) + " cells");
    rows.push_back(std::move(cells));
  }
  return rows;
}

/// A number in C's format whatever the process's locale (the app sets the user's).
double number(const std::string& cell) {
  double value = 0.0;
  const auto [end, error] = std::from_chars(cell.data(), cell.data() + cell.size(), value);
  if (error != std::errc() || end != cell.data() + cell.size())
    throw std::logic_error("strength table: not a number: " + cell);
  return value;
}

}  // namespace

const std::vector<AndersonRow>& anderson2007_table3() {
  static const std::vector<AndersonRow> table = [] {
    std::vector<AndersonRow> out;
    for (const auto& c :
         csv_rows(embedded_text(kAnderson2007Table3Csv), "anderson2007-table3.csv")) {
      if (c[4] != "mean") continue;
      out.push_back({c[0], c[1], c[2], c[3], number(c[5]), number(c[6]), number(c[7]), number(c[8]),
                     number(c[9]), number(c[10]), number(c[11]), number(c[12]), number(c[13]),
                     number(c[14])});
    }
    return out;
  }();
  return table;
}

const std::vector<GymnastRow>& gymnast_whole_body() {
  static const std::vector<GymnastRow> table = [] {
    std::vector<GymnastRow> out;
    for (const auto& c : csv_rows(embedded_text(kGymnastWholeBodyCsv), "gymnast-whole-body.csv"))
      out.push_back({c[0], c[1], number(c[2]), number(c[3]), number(c[4]), number(c[5]),
                     number(c[6]), number(c[7]), number(c[8]), number(c[9])});
    return out;
  }();
  return table;
}

}  // namespace saltus
