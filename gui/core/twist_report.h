#pragma once
/// @file
/// What the Twist panel shows of the library's `twist_sources`: which motion it analyses (the one
/// the 3D view shows), the rows of its table (each source's tilt and share, the interaction, the
/// total) and the chart of tilt over time of the actual flight and of each counterfactual. The
/// numbers are the library's; this file only picks, labels and formats them.

#include <optional>
#include <string>
#include <vector>

#include "core/chart_spec.h"
#include "core/workspace.h"
#include "saltus/evaluation/twist_sources.h"

namespace saltus::gui {

/// The motion the Twist panel analyses: the interpolated keyframes, or with the "after" stage
/// shown, the optimised motion of the run shown.
struct TwistSubject {
  Motion motion;
  BodyModel model;
  EvaluateOptions options;
  /// "the interpolated keyframes" or "the optimised motion of run 2".
  std::string description;
  /// Which result this is: the workspace's generation (a new motion, model, edit or undo) and
  /// the run analysed (-1: the interpolated keyframes). Equal keys, same motion and model.
  struct Key {
    int generation = -1;
    int run = -1;
    bool operator==(const Key& other) const {
      return generation == other.generation && run == other.run;
    }
    bool operator!=(const Key& other) const { return !(*this == other); }
  };
  Key key;
};

/// The subject for the workspace as it is; nullopt without a motion.
std::optional<TwistSubject> twist_subject(const Workspace& workspace);

/// One row of the table.
struct TwistRow {
  enum class Kind { kSource, kInteraction, kTotal };
  Kind kind = Kind::kSource;
  std::string label;  ///< "Right arm", "Together (interaction)", "Total"
  /// The library's tilt counted in the direction of the total tilt (its sign, Yeadon's θ,
  /// says which side the body leans; here a share < 0 works against the total, as its percent).
  double tilt_deg = 0.0;
  double percent = 0.0;      ///< of the total tilt, the library's
  std::string tilt_text;     ///< "17.2°"
  std::string percent_text;  ///< "70 %"
};

struct TwistReport {
  std::string sentence;  ///< the library's, as it wrote it
  /// False when the flight is not tilted enough to share out (has_tilt_to_share): the panel
  /// shows the sentence alone, no table of zeros and no percentages of nearly nothing.
  bool tilted = false;
  /// Sources in the library's order, then the interaction, then the total; empty if !tilted.
  std::vector<TwistRow> rows;
  /// "Tilt 23.1° at mid-flight (t = 1.02 s; θ = −23.1° in the chart); 1.50 twists to the left."
  std::string summary;
  ChartSpec chart;
};

TwistReport twist_report(const TwistSources& sources);

/// The chart alone: tilt θ (°) against time (s) of every flight the library flew, labelled for
/// a coach ("actual flight", "take-off only", "left arm made symmetric", ...), the reference
/// time as a marker. The actual flight is a wide pale band under the others: a movement that
/// changes nothing draws its curve inside the band instead of hiding it.
ChartSpec twist_chart(const TwistSources& sources);

/// "17.2°", "−3.0°" (no "−0.0°").
std::string tilt_text(double degrees);
/// "70 %", "−12 %" (no "−0 %").
std::string percent_text(double percent);

}  // namespace saltus::gui
