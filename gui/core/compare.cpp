#include "core/compare.h"

#include <algorithm>
#include <filesystem>

#include "saltus/base/input_error.h"
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

ChartSpec compare_root_chart(bool moment, const std::array<const WrenchSeries*, 2>& runs,
                             const std::array<std::string, 2>& labels, const ComponentMask& shown) {
  // The legend names the runs (first solid, second dashed); the title fits half a window.
  ChartSpec chart = root_wrench_chart_frame(moment);
  const int first = moment ? 3 : 0;
  for (int r = 0; r < 2; ++r) {
    const WrenchSeries* series = runs[static_cast<std::size_t>(r)];
    if (!series) continue;
    for (int i = first; i < first + 3; ++i) {
      if (!shown[static_cast<std::size_t>(i)]) continue;
      LineSpec line;
      line.label = wrench_component_name(i) + ", " + labels[static_cast<std::size_t>(r)];
      line.x = series->time;
      line.y = series->component[static_cast<std::size_t>(i)];
      line.colour = compare_colour(r, i);
      line.dashed = r == 1;
      line.width = 2.0;
      chart.lines.push_back(std::move(line));
    }
  }
  return chart;
}

}  // namespace saltus::gui
