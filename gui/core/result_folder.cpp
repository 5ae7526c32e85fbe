#include "core/result_folder.h"

#include <filesystem>
#include <set>

#include "saltus/base/input_error.h"
#include "saltus/base/json_reader.h"

namespace saltus::gui {

namespace {

std::vector<double> optional_times(const JsonNode& root, const std::string& key) {
  const std::optional<JsonNode> node = root.find(key);
  if (!node) return {};
  return node->as_double_array();
}

std::string file_safe(const std::string& name) {
  std::string out;
  for (char c : name) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                    c == '-' || c == '_' || c == '.';
    out += ok ? c : '_';
  }
  return out.empty() ? std::string("result") : out;
}

std::string title_prefix(const ResultFolder& f) {
  return f.motion.empty() ? f.name : f.motion;
}

/// Unique file-safe stems, so two folders with the same name write different figures.
class StemSet {
 public:
  std::string make(const std::string& name) {
    std::string stem = file_safe(name);
    for (int k = 2; used_.count(stem); ++k)
      stem = file_safe(name) + "-" + std::to_string(k);
    used_.insert(stem);
    return stem;
  }

 private:
  std::set<std::string> used_;
};

std::vector<double> csv_column(const CsvTable& table, const std::string& name,
                               const std::string& file) {
  const int c = table.column(name);
  if (c < 0) throw InputError(file, "", "missing column `" + name + "`");
  std::vector<double> out;
  out.reserve(table.rows.size());
  for (const std::vector<double>& row : table.rows)
    out.push_back(row.at(static_cast<std::size_t>(c)));
  return out;
}

Rgb given_run_colour() {
  return {0.16, 0.36, 0.74};
}
Rgb scaled_run_colour() {
  return {0.90, 0.45, 0.08};
}

}  // namespace

ResultFolder read_result_folder(const std::string& dir) {
  namespace fs = std::filesystem;
  const fs::path folder(dir);
  if (!fs::is_directory(folder))
    throw InputError(dir, "", "not a folder (expected a `saltus optimize` output folder)");
  ResultFolder out;
  out.path = dir;
  out.name = folder.filename().empty() ? folder.parent_path().filename().string()
                                       : folder.filename().string();

  const std::string result_path = (folder / "result.json").string();
  if (!fs::exists(result_path))
    throw InputError(result_path, "", "missing (not a `saltus optimize` output folder)");
  const nlohmann::json document = read_json_file(result_path);
  const JsonNode root(document, result_path);
  root.require_object();
  if (const auto motion = root.find("motion")) out.motion = motion->as_string();
  if (const auto status = root.find("status")) out.status = status->as_string();
  if (const auto formulation = root.find("formulation")) out.formulation = formulation->as_string();
  if (const auto iterations = root.find("iterations")) out.iterations = iterations->as_int();
  if (const auto seconds = root.find("solve_seconds")) out.solve_seconds = seconds->as_double();
  out.avg_root_force_before = root.at("before").at("avg_root_force").as_double();
  const std::optional<JsonNode> after = root.find("after");
  if (!after)
    throw InputError(result_path, "/after",
                     "missing: this is not an optimisation result (run `saltus optimize`)");
  out.avg_root_force_after = after->at("avg_root_force").as_double();
  out.keyframe_times_before = optional_times(root, "keyframe_times_before");
  out.keyframe_times_after = optional_times(root, "keyframe_times_after");

  for (const char* stage : {"before", "after"}) {
    const std::string csv = (folder / (std::string("trajectory_") + stage + ".csv")).string();
    if (!fs::exists(csv))
      throw InputError(csv, "", "missing (not a `saltus optimize` output folder)");
    WrenchSeries series = root_wrench_series(read_csv_table(csv), csv);
    (std::string(stage) == "before" ? out.before : out.after) = std::move(series);
  }
  return out;
}

ChartSpec keyframe_times_chart(const ResultFolder& f) {
  ChartSpec chart;
  chart.title = title_prefix(f) + ": keyframe times before and after optimisation";
  chart.x_title = "keyframe";
  chart.y_title = "keyframe time (s)";
  auto line = [](const std::string& label, const std::vector<double>& times, Rgb colour,
                 bool dashed) {
    LineSpec l;
    l.label = label;
    for (std::size_t i = 0; i < times.size(); ++i) {
      l.x.push_back(static_cast<double>(i));
      l.y.push_back(times[i]);
    }
    l.colour = colour;
    l.dashed = dashed;
    l.kind = LineKind::kPoints;
    l.width = 2.0;
    return l;
  };
  chart.lines.push_back(
      line("given (before)", f.keyframe_times_before, given_keyframe_colour(), true));
  chart.lines.push_back(
      line("optimised (after)", f.keyframe_times_after, optimised_keyframe_colour(), false));
  const std::size_t n = std::max(f.keyframe_times_before.size(), f.keyframe_times_after.size());
  for (std::size_t i = 0; i < n; ++i)
    chart.x_labels.push_back("K" + std::to_string(i + 1));
  return chart;
}

ChartSpec average_force_chart(const std::vector<ResultFolder>& folders) {
  ChartSpec chart;
  chart.title = "Average force acting on the root, √(J/6), before and after optimisation";
  chart.x_title = "result";
  chart.y_title = "average root force (N)";
  LineSpec before, after;
  before.label = "before (interpolated)";
  after.label = "after (optimised)";
  before.kind = after.kind = LineKind::kBars;
  before.colour = {0.70, 0.70, 0.72};
  after.colour = optimised_keyframe_colour();
  for (std::size_t i = 0; i < folders.size(); ++i) {
    before.x.push_back(static_cast<double>(i));
    after.x.push_back(static_cast<double>(i));
    before.y.push_back(folders[i].avg_root_force_before);
    after.y.push_back(folders[i].avg_root_force_after);
    chart.x_labels.push_back(folders[i].name);
  }
  chart.lines = {before, after};
  return chart;
}

std::vector<Figure> paper_figures(const std::vector<ResultFolder>& folders) {
  std::vector<Figure> out;
  StemSet stems;
  for (const ResultFolder& f : folders) {
    const std::string stem = stems.make(f.name);
    for (bool moment : {false, true}) {
      ChartSpec chart = root_wrench_chart(moment, f.before, &f.after, all_components(),
                                          f.keyframe_times_before, f.keyframe_times_after);
      chart.title = title_prefix(f) + (moment ? ": root moment" : ": root force") +
                    " before (dashed) and after (solid) optimisation";
      out.push_back({stem + (moment ? "_root_moment.png" : "_root_force.png"), std::move(chart)});
    }
    out.push_back({stem + "_keyframe_times.png", keyframe_times_chart(f)});
  }
  if (!folders.empty()) out.push_back({"average_root_force.png", average_force_chart(folders)});
  return out;
}

bool is_mass_study_folder(const std::string& dir) {
  const std::filesystem::path result = std::filesystem::path(dir) / "result.json";
  if (!std::filesystem::is_regular_file(result)) return false;
  try {
    const nlohmann::json document = read_json_file(result.string());
    return document.is_object() && document.value("study", std::string()) == "mass";
  } catch (const std::exception&) {
    return false;
  }
}

MassLoadSeries mass_load_series(const CsvTable& table, const std::vector<std::string>& segments,
                                const std::string& file) {
  MassLoadSeries out;
  out.time = csv_column(table, "t", file);
  const char* runs[] = {"given", "scaled"};
  for (const std::string& segment : segments) {
    SegmentLoadSeries s;
    s.segment = segment;
    for (int r = 0; r < 2; ++r) {
      const std::string prefix = std::string(runs[r]) + "." + segment + ".";
      s.force[r] = csv_column(table, prefix + "force_N", file);
      s.moment[r] = csv_column(table, prefix + "moment_Nm", file);
    }
    out.segments.push_back(std::move(s));
  }
  return out;
}

MassStudyFolder read_mass_study_folder(const std::string& dir) {
  namespace fs = std::filesystem;
  const fs::path folder(dir);
  if (!fs::is_directory(folder))
    throw InputError(dir, "", "not a folder (expected a `saltus study mass` output folder)");
  MassStudyFolder out;
  out.path = dir;
  out.name = folder.filename().empty() ? folder.parent_path().filename().string()
                                       : folder.filename().string();
  const std::string result_path = (folder / "result.json").string();
  if (!fs::exists(result_path))
    throw InputError(result_path, "", "missing (not a `saltus study mass` output folder)");
  const nlohmann::json document = read_json_file(result_path);
  const JsonNode root(document, result_path);
  root.require_object();
  if (root.at("study").as_string() != "mass")
    throw InputError(result_path, "/study", "not \"mass\" (not a `saltus study mass` folder)");
  if (const auto motion = root.find("motion")) out.motion = motion->as_string();
  const JsonNode runs = root.at("runs");
  runs.require_array();
  if (runs.size() != 2)
    throw InputError(result_path, runs.path_or_root(),
                     "expected two runs (given and scaled), found " + std::to_string(runs.size()));
  for (std::size_t r = 0; r < 2; ++r)
    out.run_labels[r] = runs.at(r).at("label").as_string();
  const JsonNode load_segments = root.at("load_segments");
  load_segments.require_array();
  std::vector<std::string> segments;
  for (std::size_t i = 0; i < load_segments.size(); ++i)
    segments.push_back(load_segments.at(i).as_string());
  const std::string csv = (folder / "mass.csv").string();
  if (!fs::exists(csv))
    throw InputError(csv, "", "missing (not a `saltus study mass` output folder)");
  out.loads = mass_load_series(read_csv_table(csv), segments, csv);
  return out;
}

ChartSpec mass_load_chart(const MassStudyFolder& folder, std::size_t index, bool moment) {
  const SegmentLoadSeries& s = folder.loads.segments.at(index);
  ChartSpec chart;
  // Short enough for a 2×2 grid panel; the motion's name is in the folder and the legend names
  // the two models.
  chart.title = std::string(moment ? "Joint moment" : "Joint force") + " at " + s.segment +
                " (optimised motion)";
  chart.x_title = "time (s)";
  chart.y_title = moment ? "joint moment magnitude (N·m)" : "joint force magnitude (N)";
  for (int r = 0; r < 2; ++r) {
    LineSpec line;
    line.label = folder.run_labels[static_cast<std::size_t>(r)];
    line.x = folder.loads.time;
    line.y = moment ? s.moment[static_cast<std::size_t>(r)] : s.force[static_cast<std::size_t>(r)];
    line.colour = r == 0 ? given_run_colour() : scaled_run_colour();
    line.width = 2.5;
    chart.lines.push_back(std::move(line));
  }
  return chart;
}

std::vector<FigureGrid> mass_study_figures(const std::vector<MassStudyFolder>& folders) {
  std::vector<FigureGrid> out;
  StemSet stems;
  for (const MassStudyFolder& f : folders) {
    FigureGrid grid;
    grid.file_name = stems.make(f.name) + "_loads.png";
    grid.columns = 2;
    for (std::size_t i = 0; i < f.loads.segments.size(); ++i)
      for (bool moment : {false, true})
        grid.panels.push_back(mass_load_chart(f, i, moment));
    out.push_back(std::move(grid));
  }
  return out;
}

}  // namespace saltus::gui
