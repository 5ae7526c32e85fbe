#include "saltus/formats/trajectory_csv.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "saltus/base/input_error.h"

namespace saltus {

std::vector<std::string> trajectory_csv_header(const BodyModel& model) {
  std::vector<std::string> h{"t"};
  for (const Segment& s : model.segments)
    for (const char* c : {".x", ".y", ".z", ".qw", ".qx", ".qy", ".qz"})
      h.push_back(s.name + c);
  for (const char* c :
       {"com_x", "com_y", "com_z", "root_fx", "root_fy", "root_fz", "root_mx", "root_my", "root_mz",
        "res_fx", "res_fy", "res_fz", "res_mx", "res_my", "res_mz"})
    h.emplace_back(c);
  return h;
}

void write_trajectory_csv(std::ostream& out, const BodyModel& model,
                          const std::vector<SampleRecord>& samples) {
  const auto header = trajectory_csv_header(model);
  for (std::size_t i = 0; i < header.size(); ++i)
    out << (i ? "," : "") << header[i];
  out << '\n';
  // std::to_chars writes the shortest text that reads back to the same double: exact, and several
  // times faster than printf's %.17g (it dominated `saltus evaluate` at 1000 samples).
  std::string line;
  char buffer[32];
  auto append = [&](double v) {
    const auto end = std::to_chars(buffer, buffer + sizeof buffer, v).ptr;
    line.append(buffer, end);
  };
  auto put = [&](double v) {
    line.push_back(',');
    append(v);
  };
  for (const SampleRecord& r : samples) {
    line.clear();
    append(r.time);
    for (int s = 0; s < model.size(); ++s) {
      const Eigen::Vector3d& p = r.segment_position[s];
      Eigen::Quaterniond q = r.segment_rotation[s];
      if (q.w() < 0) q.coeffs() = -q.coeffs();  // one hemisphere: readers need not care
      put(p.x()), put(p.y()), put(p.z());
      put(q.w()), put(q.x()), put(q.y()), put(q.z());
    }
    for (int i = 0; i < 3; ++i)
      put(r.com[i]);
    for (int i = 0; i < 6; ++i)
      put(r.root_wrench[i]);
    for (int i = 0; i < 6; ++i)
      put(r.residual[i]);
    line.push_back('\n');
    out << line;
  }
}

int CsvTable::column(const std::string& name) const {
  for (std::size_t i = 0; i < columns.size(); ++i)
    if (columns[i] == name) return static_cast<int>(i);
  return -1;
}

CsvTable read_csv_table(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path, "", "cannot open file for reading");
  CsvTable table;
  std::string line;
  if (!std::getline(in, line)) throw InputError(path, "line 1", "empty file, expected a header");
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
      char* end = nullptr;
      const double v = std::strtod(cell.c_str(), &end);
      if (end == cell.c_str() || *end != '\0' || !std::isfinite(v))
        throw InputError(path, "line " + std::to_string(line_number),
                         "not a finite number: \"" + cell + "\"");
      row.push_back(v);
    }
    if (row.size() != table.columns.size())
      throw InputError(path, "line " + std::to_string(line_number),
                       "expected " + std::to_string(table.columns.size()) + " values, found " +
                           std::to_string(row.size()));
    table.rows.push_back(std::move(row));
  }
  return table;
}

}  // namespace saltus
