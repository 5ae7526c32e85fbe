#pragma once
/// @file
/// The numeric CSV both CSV formats are read with (trajectory_csv, mass_files): a header line of
/// column names, then rows of finite numbers.

#include <istream>
#include <string>
#include <vector>

namespace saltus {

/// A parsed numeric CSV: column names and rows of numbers, each row as long as the header.
struct CsvTable {
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;
  /// Index of a column, -1 if absent.
  int column(const std::string& name) const;
  /// The values of column `name`; throws InputError naming `file` and the missing column.
  std::vector<double> column_values(const std::string& name, const std::string& file) const;
};

/// Reads a numeric CSV with a header line. Throws InputError naming the file and line.
CsvTable read_csv_table(const std::string& path);
/// The same from a stream; `file` names it in errors.
CsvTable parse_csv_table(std::istream& in, const std::string& file);

}  // namespace saltus
