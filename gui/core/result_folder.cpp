#include "core/result_folder.h"

#include <filesystem>
#include <set>

#include "saltus/io/input_error.h"
#include "saltus/io/json_reader.h"

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
  std::set<std::string> used;
  for (const ResultFolder& f : folders) {
    std::string stem = file_safe(f.name);
    for (int k = 2; used.count(stem); ++k)
      stem = file_safe(f.name) + "-" + std::to_string(k);
    used.insert(stem);
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

}  // namespace saltus::gui
