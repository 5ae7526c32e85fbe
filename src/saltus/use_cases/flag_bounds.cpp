#include "saltus/use_cases/flag_bounds.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "saltus/base/input_error.h"
#include "saltus/evaluation/what_if.h"
#include "saltus/formats/bvh_file.h"
#include "saltus/formats/plausible_ranges.h"
#include "saltus/optim/option_table.h"
#include "saltus/use_cases/motion_exports.h"

namespace saltus {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

/// The verbs of the runs an option is for (src/cli/main.cpp, study_verbs.cpp and saltus-gui's
/// command line add them so; the CLI test of this table checks every verb's --help against it).
std::vector<std::string> option_verbs(const OptionSpec& spec) {
  std::vector<std::string> verbs{"optimize", "study athletes", "saltus-gui"};
  if (spec.use == OptionUse::kEvaluation)
    verbs.insert(verbs.begin(), {"evaluate", "simulate", "analyse twist", "analyse what-if"});
  // The studies' and the report's own runs take the grid and the iteration limit only.
  if (spec.name == "samples" || spec.name == "max_iterations")
    verbs.insert(verbs.end() - 1, {"study convergence", "study mass", "paper"});
  return verbs;
}

NumberBound interval(double lower, double upper, const char* unit = "", bool whole = false) {
  NumberBound b;
  b.lower = lower;
  b.upper = upper;
  b.unit = unit;
  b.whole = whole;
  return b;
}

NumberBound positive(const char* unit = "") {
  NumberBound b = interval(0.0, kInfinity, unit);
  b.lower_open = true;
  return b;
}

FlagBound row(const char* flag, std::vector<std::string> verbs, NumberBound bound,
              const char* meaning, const char* why = "", const char* further = "") {
  FlagBound r;
  r.flag = flag;
  r.verbs = std::move(verbs);
  r.bound = bound;
  r.meaning = meaning;
  r.why = why;
  r.further = further;
  return r;
}

std::vector<FlagBound> make_flag_bounds() {
  std::vector<FlagBound> t;
  for (const OptionSpec& spec : option_table()) {
    if (spec.kind != OptionKind::kInteger && spec.kind != OptionKind::kReal) continue;
    FlagBound r =
        row(spec.flag.c_str(), option_verbs(spec), option_bound(spec), spec.label.c_str());
    if (!spec.word.empty())
      r.further = "or " + spec.word +
                  (spec.word_use == OptionUse::kOptimization ? " (optimisations only)" : "");
    r.option_table = true;
    t.push_back(r);
  }

  const std::vector<std::string> runs{"study convergence", "study athletes", "paper"};
  t.push_back(row("--jobs", runs, interval(1, 4096, "", true),
                  "cases run at once, each in a process of its own"));
  t.push_back(row("--case-time-limit", runs, interval(0, kInfinity, "s"),
                  "seconds before a case's process is killed (0: none)"));
  t.push_back(row("--shards", runs, interval(1, 100000, "", true), "array tasks of --emit-slurm"));
  const std::vector<std::string> convergence{"study convergence"};
  t.push_back(row("--epsilons", convergence, positive("N or N·m"),
                  "each of the strict model's bounds to try"));
  t.push_back(row("--mass-errors", convergence, interval(-90, 1000, "%"),
                  "each mass and inertia error to try"));
  t.push_back(
      row("--timing-errors", convergence, interval(0, 1, "s"), "each keyframe-time error to try"));
  t.push_back(row("--seed", convergence, interval(0, 4294967295.0, "", true),
                  "seed of the timing errors' signs"));
  t.push_back(row("--factor", {"study mass"}, positive(), "mass and inertia multiplier"));

  const char* bmi = "with --height, a body mass index of 8-80 kg/m²";
  t.push_back(row("--height", {"model new", "model scale"}, plausible::kStatureBound,
                  "standing height", "the human range; the height is in metres",
                  "with --mass, a body mass index of 8-80 kg/m²"));
  t.push_back(row("--mass", {"model new", "model scale"}, plausible::kBodyMassBound, "body mass",
                  "the human range", bmi));
  t.push_back(row("--mass", {"model yeadon"}, plausible::kBodyMassBound,
                  "body mass the densities are scaled to", "the human range"));
  t.push_back(
      row("--age", {"model new", "model yeadon"}, plausible::kAgeBound, "age, for the strength"));

  const std::vector<std::string> what_if{"analyse what-if"};
  const char* motion_range = "the range the motion allows, printed by the verb";
  t.push_back(row("--tuck-later", what_if, interval(-kInfinity, kInfinity, "s"),
                  "the tuck-in this much later", "", motion_range));
  t.push_back(row("--open-later", what_if, interval(-kInfinity, kInfinity, "s"),
                  "the opening this much later", "", motion_range));
  t.push_back(row("--tuck-scale", what_if, kTuckScaleBound, "the hips' and knees' turn times this",
                  kTuckScaleWhy));

  t.push_back(row("--frame-time", {"import"}, plausible::kCaptureFrameTimeBound,
                  "seconds per frame, instead of the file's",
                  "captures run at 1 to 1000 frames per second"));
  t.push_back(row("--keyframes", {"import"},
                  interval(2, plausible::kMaxCaptureFlightFrames, "", true), "keyframes to pick",
                  "", "or all; at most the flight's frames"));
  static const std::string fps_further =
      "BVH: frames " + message_number(plausible::kMinCaptureFrameTime) + "-" +
      message_number(plausible::kMaxCaptureFrameTime) + " s apart and at most " +
      std::to_string(kMaxBvhFrames) + " frames, as `import` reads them; the other formats: at " +
      "most " + format_number("%.0f", kMaxExportSegmentPoses) +
      " segment poses (frames × segments); `--format html` takes none";
  t.push_back(row("--fps", {"export"}, positive("fps"), "frames per second of the export", "",
                  fps_further.c_str()));

  const std::vector<std::string> app{"saltus-gui"};
  t.push_back(row("--time", app, interval(0, kInfinity, "s"), "the time of the flight shown"));
  NumberBound video_fps = positive("fps");
  video_fps.upper = 120;
  t.push_back(row("--fps", app, video_fps, "frames per second of the video"));
  t.push_back(row("--speed", app, interval(0.05, 10), "motion seconds per video second"));
  t.push_back(row("--poses", app, interval(2, 40, "", true), "poses in the lecture figure"));
  t.push_back(row("--seconds", app, positive("s"), "length of the playback benchmark"));
  return t;
}

std::string joined(const std::vector<std::string>& verbs) {
  std::string out;
  for (const std::string& v : verbs)
    out += (out.empty() ? "" : ", ") + ("`" + v + "`");
  return out;
}

}  // namespace

const std::vector<FlagBound>& flag_bounds() {
  static const std::vector<FlagBound> table = make_flag_bounds();
  return table;
}

const FlagBound& flag_bound(std::string_view flag, std::string_view verb) {
  for (const FlagBound& r : flag_bounds())
    if (r.flag == flag &&
        (verb.empty() || std::find(r.verbs.begin(), r.verbs.end(), verb) != r.verbs.end()))
      return r;
  throw std::logic_error("no bound for " + std::string(flag) + " of " + std::string(verb) +
                         " in flag_bounds()");
}

void check_flag(std::string_view flag, double value, std::string_view verb,
                const std::string& named) {
  const FlagBound& r = flag_bound(flag, verb);
  check_bound(named.empty() ? r.flag : named, r.bound, value, r.why);
}

std::string flag_bounds_markdown() {
  std::string out =
      "| flag | verbs | accepted | what it is | also bounded by |\n|---|---|---|---|---|\n";
  for (const FlagBound& r : flag_bounds())
    out += "| `" + r.flag + "` | " + joined(r.verbs) + " | " + bound_text(r.bound) +
           (r.bound.whole ? ", whole" : "") + " | " + r.meaning + " | " + r.further + " |\n";
  return out;
}

}  // namespace saltus
