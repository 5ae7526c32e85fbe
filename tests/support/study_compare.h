#pragma once
// Compares two study folders file by file, ignoring only the measured wall times: the `seconds`
// column of CSV files, the "seconds" and "solve_seconds" members of JSON files and the cells of
// Markdown table columns headed "time (s)". Everything else must be byte for byte the same.

#include <algorithm>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "support/cli_runner.h"

namespace saltus::test {

namespace study_compare_detail {

inline std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::string part;
  std::istringstream in(text);
  while (std::getline(in, part, separator))
    parts.push_back(part);
  return parts;
}

inline std::string without_csv_column(const std::string& text, const std::string& column) {
  const std::vector<std::string> lines = split(text, '\n');
  if (lines.empty()) return text;
  const std::vector<std::string> header = split(lines[0], ',');
  const auto at = std::find(header.begin(), header.end(), column);
  if (at == header.end()) return text;
  const std::size_t drop = static_cast<std::size_t>(at - header.begin());
  std::string out;
  for (const std::string& line : lines) {
    const std::vector<std::string> cells = split(line, ',');
    for (std::size_t i = 0; i < cells.size(); ++i)
      if (i != drop) out += cells[i] + ",";
    out += "\n";
  }
  return out;
}

inline void drop_wall_times(nlohmann::json& j) {
  if (j.is_object()) {
    j.erase("seconds");
    j.erase("solve_seconds");
    for (auto& [key, value] : j.items())
      drop_wall_times(value);
  } else if (j.is_array()) {
    for (auto& value : j)
      drop_wall_times(value);
  }
}

/// Blanks the cells of Markdown table columns whose header cell contains "time (s)".
inline std::string without_time_columns(const std::string& text) {
  std::string out;
  std::set<std::size_t> blank;
  for (const std::string& line : split(text, '\n')) {
    if (line.rfind("|", 0) != 0) {
      blank.clear();
      out += line + "\n";
      continue;
    }
    std::vector<std::string> cells = split(line, '|');
    if (line.find("time (s)") != std::string::npos) {
      blank.clear();
      for (std::size_t i = 0; i < cells.size(); ++i)
        if (cells[i].find("time (s)") != std::string::npos) blank.insert(i);
    } else {
      for (std::size_t i : blank)
        if (i < cells.size()) cells[i] = " ";
    }
    for (const std::string& cell : cells)
      out += cell + "|";
    out += "\n";
  }
  return out;
}

inline std::set<std::string> files_under(const std::filesystem::path& root) {
  std::set<std::string> files;
  if (!std::filesystem::is_directory(root)) return files;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(root))
    if (entry.is_regular_file())
      files.insert(std::filesystem::relative(entry.path(), root).string());
  return files;
}

}  // namespace study_compare_detail

/// The differences between two folders (empty: the same apart from wall times), one line each.
inline std::vector<std::string> study_folder_differences(const std::string& a,
                                                         const std::string& b) {
  namespace d = study_compare_detail;
  std::vector<std::string> differences;
  const std::set<std::string> in_a = d::files_under(a), in_b = d::files_under(b);
  if (in_a.empty()) differences.push_back(a + " holds no files");
  for (const std::string& f : in_a)
    if (!in_b.count(f)) differences.push_back(f + " only in " + a);
  for (const std::string& f : in_b)
    if (!in_a.count(f)) differences.push_back(f + " only in " + b);
  for (const std::string& f : in_a) {
    if (!in_b.count(f)) continue;
    std::string x = read_text(a + "/" + f), y = read_text(b + "/" + f);
    const std::string extension = std::filesystem::path(f).extension().string();
    if (extension == ".csv") {
      x = d::without_csv_column(x, "seconds");
      y = d::without_csv_column(y, "seconds");
    } else if (extension == ".json") {
      nlohmann::json jx = nlohmann::json::parse(x), jy = nlohmann::json::parse(y);
      d::drop_wall_times(jx);
      d::drop_wall_times(jy);
      x = jx.dump(1);
      y = jy.dump(1);
    } else if (extension == ".md") {
      x = d::without_time_columns(x);
      y = d::without_time_columns(y);
    }
    if (x != y) differences.push_back(f + " differs");
  }
  return differences;
}

}  // namespace saltus::test
