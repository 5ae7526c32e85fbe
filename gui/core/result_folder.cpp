#include "core/result_folder.h"

#include <filesystem>
#include <set>

#include "saltus/base/input_error.h"

namespace saltus::gui {

namespace {

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
  return f.result.motion.empty() ? f.name : f.result.motion;
}

/// The keyframe times after optimisation, none for other results.
std::vector<double> times_after(const ResultFolder& f) {
  return f.result.optimization ? f.result.optimization->keyframe_times_after
                               : std::vector<double>();
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

Rgb given_run_colour() {
  return {0.16, 0.36, 0.74};
}
Rgb scaled_run_colour() {
  return {0.90, 0.45, 0.08};
}

}  // namespace

ResultFolder read_optimization_folder(const std::string& dir) {
  ResultFolder folder = read_result_folder(dir);
  if (folder.result.kind != ResultJson::Kind::kOptimization)
    throw InputError((std::filesystem::path(dir) / "result.json").string(), "/after",
                     "null: this is not an optimisation result (run `saltus optimize`)");
  return folder;
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
  const std::vector<double>& before = f.result.keyframe_times_before;
  const std::vector<double> after = times_after(f);
  chart.lines.push_back(line("given (before)", before, given_keyframe_colour(), true));
  chart.lines.push_back(line("optimised (after)", after, optimised_keyframe_colour(), false));
  const std::size_t n = std::max(before.size(), after.size());
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
    const ResultJson& r = folders[i].result;
    before.y.push_back(r.before.avg_root_force);
    after.y.push_back(r.optimization ? r.optimization->after.avg_root_force : 0.0);
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
    const WrenchSeries before = root_wrench_series(f.before.samples);
    const WrenchSeries after = root_wrench_series(f.after ? f.after->samples : f.before.samples);
    for (bool moment : {false, true}) {
      ChartSpec chart =
          root_wrench_chart(moment, before, f.after ? &after : nullptr, all_components(),
                            f.result.keyframe_times_before, times_after(f));
      chart.title = title_prefix(f) + (moment ? ": root moment" : ": root force") +
                    " before (dashed) and after (solid) optimisation";
      out.push_back({stem + (moment ? "_root_moment.png" : "_root_force.png"), std::move(chart)});
    }
    out.push_back({stem + "_keyframe_times.png", keyframe_times_chart(f)});
  }
  if (!folders.empty()) out.push_back({"average_root_force.png", average_force_chart(folders)});
  return out;
}

ChartSpec mass_load_chart(const MassStudyFolder& folder, std::size_t index, bool moment) {
  const std::string& segment = folder.loads.load_segments.at(index);
  const std::array<MassLoads, 2>& runs = folder.loads.loads.at(index);
  ChartSpec chart;
  // Short enough for a 2×2 grid panel; the motion's name is in the folder and the legend names
  // the two models.
  chart.title = std::string(moment ? "Joint moment" : "Joint force") + " at " + segment +
                " (optimised motion)";
  chart.x_title = "time (s)";
  chart.y_title = moment ? "joint moment magnitude (N·m)" : "joint force magnitude (N)";
  for (int r = 0; r < 2; ++r) {
    LineSpec line;
    const MassLoads& loads = runs[static_cast<std::size_t>(r)];
    line.label = folder.runs[static_cast<std::size_t>(r)].label;
    line.x = folder.loads.time;
    line.y = moment ? loads.moment_Nm : loads.force_N;
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
    for (std::size_t i = 0; i < f.loads.load_segments.size(); ++i)
      for (bool moment : {false, true})
        grid.panels.push_back(mass_load_chart(f, i, moment));
    out.push_back(std::move(grid));
  }
  return out;
}

}  // namespace saltus::gui
