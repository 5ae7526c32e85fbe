#include "core/result_folder.h"

#include <algorithm>
#include <filesystem>

#include "core/plot_series.h"
#include "saltus/base/input_error.h"

namespace saltus::gui {

namespace {

std::string title_prefix(const ResultFolder& f) {
  return f.result.motion.empty() ? f.name : f.result.motion;
}

/// The keyframe times after optimisation, none for other results.
std::vector<double> times_after(const ResultFolder& f) {
  return f.result.optimization ? f.result.optimization->keyframe_times_after
                               : std::vector<double>();
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

}  // namespace saltus::gui
