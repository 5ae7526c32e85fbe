#include "saltus/formats/csv_table.h"

#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

#include "saltus/base/input_error.h"

namespace saltus {

int CsvTable::column(const std::string& name) const {
  for (std::size_t i = 0; i < columns.size(); ++i)
    if (columns[i] == name) return static_cast<int>(i);
  return -1;
}

std::vector<double> CsvTable::column_values(const std::string& name,
                                            const std::string& file) const {
  const int c = column(name);
  if (c < 0) throw InputError(file, "", "missing column \"" + name + "\"");
  std::vector<double> out;
  out.reserve(rows.size());
  for (const std::vector<double>& row : rows)
    out.push_back(row[static_cast<std::size_t>(c)]);
  return out;
}

CsvTable read_csv_table(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path, "", "cannot open file for reading");
  return parse_csv_table(in, path);
}

CsvTable parse_csv_table(std::istream& in, const std::string& file) {
  CsvTable table;
  std::string line;
  if (!std::getline(in, line)) throw InputError(file, "line 1", "empty file, expected a header");
  {
    std::stringstream ss(line);
    std::string cell;
    while (std::getline(ss, cell, ','))
      table.columns.push_back(cell);
  }
  int line_number = 1;
  while (std::getline(in, line)) {
    ++line_number;
    if (line.empty()) continue;
    std::vector<double> row;
    std::stringstream ss(line);
    std::string cell;
    while (std::getline(ss, cell, ',')) {
      // from_chars, not strtod: a comma-decimal locale (the app runs in the user's) must not
      // change how a file reads.
      double v = 0.0;
      const char* last = cell.data() + cell.size();
      const auto [end, error] = std::from_chars(cell.data(), last, v);
      if (cell.empty() || error != std::errc() || end != last || !std::isfinite(v))
        throw InputError(file, "line " + std::to_string(line_number),
                         "not a finite number: \"" + cell + "\"");
      row.push_back(v);
    }
    if (row.size() != table.columns.size())
      throw InputError(file, "line " + std::to_string(line_number),
                       "expected " + std::to_string(table.columns.size()) + " values, found " +
                           std::to_string(row.size()));
    table.rows.push_back(std::move(row));
  }
  return table;
}

}  // namespace saltus
