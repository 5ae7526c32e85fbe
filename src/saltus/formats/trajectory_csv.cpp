#include "saltus/formats/trajectory_csv.h"

#include <charconv>
#include <fstream>
#include <iterator>

#include "saltus/base/constants.h"
#include "saltus/base/input_error.h"
#include "saltus/evaluation/yeadon_angles.h"

namespace saltus {

namespace {

/// The columns after the segments' (docs/formats.md): CoM, root wrench F1..F6, residual.
const char* const kTrailingColumns[15] = {"com_x",   "com_y",   "com_z",   "root_fx", "root_fy",
                                          "root_fz", "root_mx", "root_my", "root_mz", "res_fx",
                                          "res_fy",  "res_fz",  "res_mx",  "res_my",  "res_mz"};
const char* const kSegmentColumns[7] = {".x", ".y", ".z", ".qw", ".qx", ".qy", ".qz"};
/// Yeadon's angles of the root (evaluation/yeadon_angles.h), last; files before them end at res_mz.
const char* const kAngleColumns[3] = {"somersault_deg", "tilt_deg", "twist_deg"};

[[noreturn]] void bad_column(const std::string& file, std::size_t index, const std::string& found,
                             const std::string& expected) {
  throw InputError(file, "line 1",
                   "column " + std::to_string(index + 1) + " is \"" + found + "\", expected " +
                       expected + " (trajectory columns, docs/formats.md)");
}

}  // namespace

std::vector<std::string> trajectory_csv_header(const BodyModel& model) {
  std::vector<std::string> h{"t"};
  for (const Segment& s : model.segments)
    for (const char* c : kSegmentColumns)
      h.push_back(s.name + c);
  for (const char* c : kTrailingColumns)
    h.emplace_back(c);
  for (const char* c : kAngleColumns)
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
  std::vector<Eigen::Quaterniond> roots;
  for (const SampleRecord& r : samples)
    roots.push_back(r.segment_rotation.at(0));
  const std::vector<Eigen::Vector3d> angles = unwrapped_angles(roots);
  for (std::size_t k = 0; k < samples.size(); ++k) {
    const SampleRecord& r = samples[k];
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
    for (int i = 0; i < 3; ++i)
      put(angles[k][i] * kDegreesPerRadian);
    line.push_back('\n');
    out << line;
  }
}

TrajectoryCsv read_trajectory_csv(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path, "", "cannot open file for reading");
  return parse_trajectory_csv(in, path);
}

TrajectoryCsv parse_trajectory_csv(std::istream& in, const std::string& file) {
  const CsvTable table = parse_csv_table(in, file);
  const std::vector<std::string>& columns = table.columns;
  const bool has_angles = columns.size() >= 3 && columns.back() == kAngleColumns[2];
  const std::size_t angle_count = has_angles ? std::size(kAngleColumns) : 0;
  const std::size_t trailing = std::size(kTrailingColumns) + angle_count;
  if (columns.empty() || columns[0] != "t")
    bad_column(file, 0, columns.empty() ? "" : columns[0], "\"t\"");
  if (columns.size() < 1 + trailing || (columns.size() - 1 - trailing) % 7 != 0)
    throw InputError(
        file, "line 1",
        std::to_string(columns.size()) +
            " columns: expected t, 7 per segment, then com_x ... res_mz (and somersault_deg, "
            "tilt_deg, twist_deg)");
  TrajectoryCsv out;
  const std::size_t segments = (columns.size() - 1 - trailing) / 7;
  for (std::size_t s = 0; s < segments; ++s) {
    const std::string& first = columns[1 + 7 * s];
    const std::size_t dot = first.rfind(".x");
    if (dot == std::string::npos || dot + 2 != first.size() || dot == 0)
      bad_column(file, 1 + 7 * s, first, "a segment's \"<name>.x\"");
    out.segments.push_back(first.substr(0, dot));
    for (std::size_t c = 0; c < 7; ++c)
      if (columns[1 + 7 * s + c] != out.segments.back() + kSegmentColumns[c])
        bad_column(file, 1 + 7 * s + c, columns[1 + 7 * s + c],
                   "\"" + out.segments.back() + kSegmentColumns[c] + "\"");
  }
  for (std::size_t c = 0; c < trailing; ++c) {
    const char* expected = c < std::size(kTrailingColumns)
                               ? kTrailingColumns[c]
                               : kAngleColumns[c - std::size(kTrailingColumns)];
    if (columns[1 + 7 * segments + c] != expected)
      bad_column(file, 1 + 7 * segments + c, columns[1 + 7 * segments + c],
                 std::string("\"") + expected + "\"");
  }

  out.samples.reserve(table.rows.size());
  for (const std::vector<double>& row : table.rows) {
    SampleRecord r;
    const double* v = row.data();
    r.time = *v++;
    for (std::size_t s = 0; s < segments; ++s, v += 7) {
      r.segment_position.emplace_back(v[0], v[1], v[2]);
      r.segment_rotation.emplace_back(v[3], v[4], v[5], v[6]);  // w, x, y, z
    }
    r.com = Eigen::Vector3d(v[0], v[1], v[2]);
    for (int i = 0; i < 6; ++i) {
      r.root_wrench[i] = v[3 + i];
      r.residual[i] = v[9 + i];
    }
    if (has_angles) out.angles_deg.emplace_back(v[15], v[16], v[17]);
    out.samples.push_back(std::move(r));
  }
  return out;
}

}  // namespace saltus
