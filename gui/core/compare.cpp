#include "core/compare.h"

#include <algorithm>
#include <filesystem>
#include <stdexcept>

#include "saltus/base/input_error.h"
#include "saltus/body/segment_names.h"
#include "saltus/evaluation/residual_measures.h"
#include "saltus/formats/result_json.h"

namespace saltus::gui {

FolderRun folder_run(const std::string& dir) {
  namespace fs = std::filesystem;
  const fs::path folder(dir);
  if (!fs::is_directory(folder))
    throw InputError(dir, "", "not a folder (expected a `saltus optimize` or `evaluate` folder)");
  const std::string name = folder.filename().empty() ? folder.parent_path().filename().string()
                                                     : folder.filename().string();
  FolderRun run;
  const fs::path optimized = folder / "optimized.motion.json";
  if (fs::exists(optimized)) {
    run.motion_path = optimized.string();
    run.label = name + " (optimised)";
    run.description = "optimised motion (saltus optimize folder)";
    return run;
  }
  const std::string result_path = (folder / "result.json").string();
  if (!fs::exists(result_path))
    throw InputError(result_path, "",
                     "missing (expected a `saltus optimize` or `saltus evaluate` output folder)");
  run.motion_path = read_result_json(result_path).motion_file;
  const fs::path model = folder / "model.json";
  if (!fs::exists(model))
    throw InputError(model.string(), "", "missing (the folder's copy of the body model)");
  run.model_path = model.string();
  run.label = name;
  run.description = "interpolated keyframes (saltus evaluate folder)";
  return run;
}

double compare_duration(double duration_a, double duration_b) {
  return std::max(duration_a, duration_b);
}

double run_time(double t, double duration) {
  return std::clamp(t, 0.0, duration);
}

Rgb compare_colour(int run, int component) {
  // Per axis (x, y, z): dark, medium, pale of one hue; blue for run 0, orange for run 1.
  static const Rgb kBlue[3] = {{0.05, 0.20, 0.55}, {0.20, 0.45, 0.85}, {0.50, 0.70, 0.95}};
  static const Rgb kOrange[3] = {{0.60, 0.25, 0.00}, {0.92, 0.45, 0.05}, {0.98, 0.70, 0.35}};
  const int axis = ((component % 3) + 3) % 3;
  return run == 0 ? kBlue[axis] : kOrange[axis];
}

ChartSpec compare_root_chart(const RootChartStyle& style,
                             const std::array<const WrenchSeries*, 2>& runs,
                             const std::array<std::string, 2>& labels) {
  ChartSpec chart = root_chart_frame(style);
  const int first = style.moment ? 3 : 0;
  const char* const axes[3] = {"x", "y", "z"};
  for (int r = 0; r < 2; ++r) {
    const WrenchSeries* series = runs[static_cast<std::size_t>(r)];
    if (!series) continue;
    const std::string& label = labels[static_cast<std::size_t>(r)];
    if (style.components) {
      for (int a = 0; a < 3; ++a) {
        if (!style.axes[static_cast<std::size_t>(a)]) continue;
        LineSpec line;
        line.label = std::string(axes[a]) + " " + label;
        line.x = series->time;
        line.y = series->component[static_cast<std::size_t>(first + a)];
        line.colour = compare_colour(r, a);
        style_compared_line(line, r == 1, true);
        line.colour = compare_colour(r, a);  // the run's own shade, not a paler one
        chart.lines.push_back(std::move(line));
      }
    } else {
      LineSpec line;
      line.label = label;
      line.x = series->time;
      line.y = style.moment ? series->moment_magnitude : series->force_magnitude;
      line.colour = compare_colour(r, 1);
      style_compared_line(line, r == 1, true);
      line.colour = compare_colour(r, 1);
      chart.lines.push_back(std::move(line));
    }
  }
  return chart;
}

ChartSpec compare_joint_chart(const BodyModel& model, int segment, bool moment,
                              const std::array<const std::vector<SampleRecord>*, 2>& runs,
                              const std::array<std::string, 2>& labels) {
  if (segment < 0 || segment >= model.size()) throw std::out_of_range("joint segment");
  const Segment& s = model.segments[static_cast<std::size_t>(segment)];
  ChartSpec chart;
  chart.title = std::string(moment ? "Joint moment" : "Joint force") + " at the " +
                joint_label(s.joint) + " (on the " + segment_label(s.name) + ")";
  chart.x_title = "time (s)";
  chart.y_title = moment ? "|M| (N·m)" : "|F| (N)";
  for (int r = 0; r < 2; ++r) {
    const std::vector<SampleRecord>* samples = runs[static_cast<std::size_t>(r)];
    if (!samples) continue;
    LineSpec line;
    line.label = labels[static_cast<std::size_t>(r)];
    for (const SampleRecord& record : *samples) {
      const Vector6d& w = record.joint_wrench.at(static_cast<std::size_t>(segment));
      line.x.push_back(record.time);
      line.y.push_back(moment ? moment_magnitude(w) : force_magnitude(w));
    }
    style_compared_line(line, r == 1, true);
    line.colour = compare_colour(r, 1);
    chart.lines.push_back(std::move(line));
  }
  return chart;
}

}  // namespace saltus::gui
