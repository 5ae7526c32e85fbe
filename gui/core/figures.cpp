#include "core/figures.h"

#include <cstdio>
#include <filesystem>
#include <set>
#include <variant>

#include "core/plot_series.h"
#include "core/run_list.h"
#include "core/twist_report.h"
#include "saltus/base/text_format.h"
#include "saltus/body/segment_names.h"
#include "saltus/evaluation/evaluate.h"
#include "saltus/evaluation/residual_measures.h"
#include "saltus/formats/model_file.h"
#include "saltus/formats/motion_file.h"

namespace saltus::gui {

namespace {

/// Unique stems, so two folders with the same name write different figures.
class StemSet {
 public:
  std::string make(const std::string& name) {
    std::string stem = figure_stem(name);
    for (int k = 2; used_.count(stem); ++k)
      stem = figure_stem(name) + "-" + std::to_string(k);
    used_.insert(stem);
    return stem;
  }

 private:
  std::set<std::string> used_;
};

std::string display_name(const ResultFolder& f) {
  return f.result.motion.empty() ? f.name : f.result.motion;
}

/// The figures' numbers of an optimisation folder (result.json as the library reads it).
double avg_force_after(const ResultFolder& f) {
  return f.result.optimization ? f.result.optimization->after.avg_root_force
                               : f.result.before.avg_root_force;
}
const std::vector<double>& keyframe_times_after(const ResultFolder& f) {
  return f.result.optimization ? f.result.optimization->keyframe_times_after
                               : f.result.keyframe_times_before;
}

/// Root force and moment before and after: from the folder's trajectory CSVs, or denser.
struct Curves {
  WrenchSeries before, after;
};

/// The body weight of the folder's model.json, 0 when it cannot be read (the % axis is left
/// out then).
double folder_body_weight(const ResultFolder& f) {
  try {
    return body_weight(load_body_model((std::filesystem::path(f.path) / "model.json").string()));
  } catch (const std::exception&) {
    return 0.0;
  }
}

/// The series of a motion file evaluated on the dense plot grid with the folder's model.
WrenchSeries dense_series(const std::string& motion, const std::string& model, int knots) {
  const MotionFile file = load_motion_file(motion, model);
  EvaluateOptions options;
  options.samples = plot_samples_for(file.motion.flight_time());
  options.interpolation.knots_per_interval = knots;
  return root_wrench_series(evaluate_motion(file.motion, file.model, options).samples);
}

/// Smooth curves where the motions can be evaluated again exactly: "after" from
/// optimized.motion.json (its stored spline is the optimised motion), "before" from the motion
/// file result.json names (as `saltus optimize` interpolated it, with its knots). Where a file
/// cannot be read, the CSV's samples stay (true values, only coarser).
Curves dense_curves(const ResultFolder& f) {
  namespace fs = std::filesystem;
  Curves c{root_wrench_series(f.before.samples),
           root_wrench_series(f.after ? f.after->samples : f.before.samples)};
  const fs::path folder(f.path);
  const std::string model = (folder / "model.json").string();
  try {
    c.after = dense_series((folder / "optimized.motion.json").string(), model, 1);
  } catch (const std::exception&) {
  }
  try {
    const fs::path motion = f.result.motion_file;
    // With the automatic resolution "before" is the paper's interpolation, knots at the
    // keyframes (optimize_motion); otherwise the knots `saltus optimize` used.
    const auto& o = f.result.optimization;
    const bool automatic = o && o->resolution && o->resolution->automatic;
    const int knots = automatic ? 1 : f.result.knots_per_interval;
    // Relative to where `saltus optimize` ran: try the current folder, then the folder's parent.
    for (const fs::path& candidate : {motion, folder.parent_path() / motion}) {
      if (!fs::exists(candidate)) continue;
      c.before = dense_series(candidate.string(), model, knots);
      break;
    }
  } catch (const std::exception&) {
  }
  return c;
}

/// "M1" from "M1-straight-back-somersault" or "M1 straight back somersault".
std::string first_word(const std::string& name) {
  const std::size_t end = name.find_first_of(" -_");
  return name.substr(0, end);
}

/// What a mass study scaled, as people say it ("left and right thighs × 1.5"); the run's own
/// label when the folder does not say which segments.
std::string scaled_label(const MassStudyFolder& f) {
  if (f.scaled_segments.empty()) return f.runs[1].label;
  return "model with " + mass_scaling_label(f.scaled_segments, f.factor);
}

}  // namespace

std::string figure_stem(const std::string& name) {
  std::string out;
  for (char c : name) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                    c == '-' || c == '_' || c == '.';
    out += ok ? c : '_';
  }
  return out.empty() ? std::string("figure") : out;
}

ChartSpec titled_figure(ChartSpec chart, const std::string& motion, const std::string& settings) {
  // One line for the motion and the settings when it fits a figure's width, else two.
  constexpr std::size_t kLineLength = 90;
  const bool one_line = motion.size() + settings.size() + 3 <= kLineLength;
  chart.title += "\n" + motion;
  if (!settings.empty()) chart.title += (one_line ? " · " : "\n") + settings;
  return chart;
}

std::string folder_settings(const ResultFolder& f) {
  const auto formulation = f.result.option("formulation");
  std::string out = formulation && std::holds_alternative<std::string>(*formulation)
                        ? std::get<std::string>(*formulation)
                        : std::string("optimised");
  out += " · " + status_text(f.result.status.empty() ? "solved" : f.result.status);
  const int iterations = f.result.optimization ? f.result.optimization->iterations : 0;
  if (iterations > 0) out += " in " + std::to_string(iterations) + " iterations";
  out += " · average root force " + format_number("%.3g", f.result.before.avg_root_force) + " → " +
         format_number("%.3g", avg_force_after(f)) + " N";
  return out;
}

std::vector<Figure> result_figures(const std::vector<ResultFolder>& folders) {
  std::vector<Figure> out;
  StemSet stems;
  for (const ResultFolder& f : folders) {
    const Curves curves = dense_curves(f);
    const std::string stem = stems.make(f.name);
    const std::string settings = folder_settings(f);
    RootChartStyle style;
    style.log_scale = true;
    style.body_weight_N = folder_body_weight(f);
    for (bool moment : {false, true}) {
      style.moment = moment;
      style.components = false;
      out.push_back(
          {stem + (moment ? "_root_moment.png" : "_root_force.png"),
           titled_figure(root_chart(style, curves.before, &curves.after,
                                    f.result.keyframe_times_before, keyframe_times_after(f)),
                         display_name(f), settings)});
      style.components = true;
      out.push_back(
          {stem + (moment ? "_root_moment_components.png" : "_root_force_components.png"),
           titled_figure(root_chart(style, curves.before, &curves.after,
                                    f.result.keyframe_times_before, keyframe_times_after(f)),
                         display_name(f), settings)});
    }
    ChartSpec times = keyframe_times_chart(f);
    times.title = "Keyframe times before and after optimisation";
    out.push_back({stem + "_keyframe_times.png", titled_figure(times, display_name(f), settings)});
  }
  if (!folders.empty())
    out.push_back({"average_root_force.png", average_root_force_figure(folders)});
  return out;
}

ChartSpec average_root_force_figure(const std::vector<ResultFolder>& folders) {
  ChartSpec chart;
  chart.title = "Average force acting on the root √(J/6), before and after optimisation";
  chart.x_title = "result";
  chart.y_title = "average root force (N, log scale)";
  // Points on a log axis: after optimisation the force is hundreds of times smaller than before;
  // on a linear axis its bars were too short to see, and bars on a log axis start at 1 N.
  chart.log_y = true;
  LineSpec before, after;
  before.label = "before (interpolated)";
  after.label = "after (optimised)";
  before.kind = after.kind = LineKind::kPoints;
  before.colour = {0.70, 0.70, 0.72};
  after.colour = optimised_keyframe_colour();
  std::set<std::string> short_names;
  for (const ResultFolder& f : folders)
    short_names.insert(first_word(f.name));
  const bool short_ok = short_names.size() == folders.size();
  std::string listed;
  for (std::size_t i = 0; i < folders.size(); ++i) {
    before.x.push_back(static_cast<double>(i) - 0.15);
    after.x.push_back(static_cast<double>(i) + 0.15);
    before.y.push_back(folders[i].result.before.avg_root_force);
    after.y.push_back(avg_force_after(folders[i]));
    const std::string label = short_ok ? first_word(folders[i].name) : std::to_string(i + 1);
    chart.x_labels.push_back(label);
    if (!short_ok) listed += (i ? ", " : "") + label + " " + folders[i].name;
  }
  if (!short_ok) chart.title += "\n" + listed;
  chart.lines = {before, after};
  return chart;
}

std::vector<FigureGrid> mass_study_load_figures(const std::vector<MassStudyFolder>& folders) {
  std::vector<FigureGrid> out;
  StemSet stems;
  for (const MassStudyFolder& f : folders) {
    FigureGrid grid;
    grid.file_name = stems.make(f.name) + "_loads.png";
    grid.columns = 2;
    const std::array<std::string, 2> labels{"model as given", scaled_label(f)};
    for (std::size_t i = 0; i < f.loads.load_segments.size(); ++i) {
      const std::string& segment = f.loads.load_segments[i];
      for (bool moment : {false, true}) {
        ChartSpec chart;
        chart.title = std::string(moment ? "Joint moment" : "Joint force") + " on the " +
                      segment_label(segment) + (f.motion.empty() ? "" : "\n" + f.motion) +
                      " (optimised)";
        chart.x_title = "time (s)";
        chart.y_title = moment ? "|M| (N·m)" : "|F| (N)";
        for (std::size_t r = 0; r < 2; ++r) {
          LineSpec line;
          line.label = labels[r];
          line.x = f.loads.time;
          line.y = moment ? f.loads.loads[i][r].moment_Nm : f.loads.loads[i][r].force_N;
          line.colour = magnitude_curve_colour(moment);
          style_compared_line(line, r == 1, true);
          chart.lines.push_back(std::move(line));
        }
        grid.panels.push_back(std::move(chart));
      }
    }
    out.push_back(std::move(grid));
  }
  return out;
}

std::vector<Figure> twist_figures(const std::vector<TwistFolder>& folders) {
  std::vector<Figure> out;
  StemSet stems;
  for (const TwistFolder& f : folders) {
    const TwistReport report = twist_report(f.sources);
    ChartSpec chart = report.chart;
    chart.title = report.sentence;
    out.push_back({stems.make(f.name) + "_twist.png",
                   titled_figure(chart, f.motion.empty() ? f.name : f.motion, report.summary)});
  }
  return out;
}

}  // namespace saltus::gui
