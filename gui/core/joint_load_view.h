#pragma once
/// @file
/// The Joint loads and Strength tabs as a coach reads them: for one joint, its force against time
/// with a second axis in % of body weight, its moment with its share of the athlete's strength
/// over time (evaluation/strength_demand.h: the moment in each anatomical direction against the
/// athlete's capacity there, at that angle and speed; red above 100 %), a line that says the
/// peaks in those terms with a traffic light, and, with a run shown, the moment the optimiser
/// raised the joint's load marked on the chart (its peak after against before,
/// evaluation/joint_loads.h), in the words of `saltus optimize`. And every joint's share as a
/// strip over time.

#include <optional>
#include <string>
#include <vector>

#include "core/chart_spec.h"
#include "saltus/body/body_model.h"
#include "saltus/evaluation/force_metrics.h"
#include "saltus/evaluation/joint_loads.h"
#include "saltus/evaluation/sampling.h"

namespace saltus::gui {

/// A joint's share of the athlete's strength, as a traffic light.
enum class StrengthLight { kUnknown, kGreen, kAmber, kRed };

/// Green below kAmberShare of the athlete's strength, amber from it up to all of it, red beyond
/// it (more than the athlete's muscles can give there); unknown without a strength curve.
inline constexpr double kAmberShare = 0.8;
StrengthLight strength_light(const std::optional<double>& share);
/// "within the athlete's strength", "near the athlete's maximum", "beyond the athlete's
/// strength", "no strength curve".
std::string strength_light_words(StrengthLight light);
Rgb strength_light_colour(StrengthLight light);
/// The colour of a share of strength (the strips): the light's colour, a share near 0 paler.
Rgb strength_share_colour(double share);

/// A rise of a joint's peak load past this is marked on its chart (smaller ones are the
/// optimiser's noise, not a load it asked of the joint).
inline constexpr double kMarkedJointRise = 1.1;

/// What the Joint loads tab shows of one joint.
struct JointLoadView {
  ChartSpec force;   ///< |F| (N), before and after; right axis % of body weight
  ChartSpec moment;  ///< |M| (N·m), before and after; right axis its share of strength (%)
  /// The stage shown (after with a run): "Peak force 254 N (40 % of body weight) at 0.000 s ·
  /// peak moment 51.4 N·m at 0.698 s · largest share of the athlete's strength 64 % (left knee
  /// extension at t = 0.31 s)".
  std::string summary;
  std::optional<double> share;  ///< the largest share of strength, none without a curve
  StrengthLight light = StrengthLight::kUnknown;
  /// With a run whose optimisation raised this joint's peak past kMarkedJointRise: "Raised by
  /// the optimiser: knee_l, moment 7.17 N·m at t = 0.224 s after, 2.6 N·m before (2.76x)",
  /// then joint_load_verdict_words' warning when past kJointLoadRiseLimit; else "".
  std::string raised;
  bool raised_past_limit = false;
};

/// The view of `segment`'s joint (segment 0: the root, the load the world must supply): its
/// loads over the dense plot samples `before` and, with a run, `after` (null without), and its
/// peaks from the dense checks of the same stages.
JointLoadView joint_load_view(const BodyModel& model, int segment,
                              const std::vector<SampleRecord>& before,
                              const DenseCheck& before_check,
                              const std::vector<SampleRecord>* after,
                              const DenseCheck* after_check);

/// The joint list's entry: "Left knee (left lower leg)", and for a joint the run made pay (its
/// rise past kJointLoadRiseLimit) " — 4.71x its peak before".
std::string joint_choice_label(const BodyModel& model, int segment, const JointLoadRise* rise);

/// One joint's share of the athlete's strength over the flight, for the Strength tab's strips.
struct StrengthStrip {
  int segment = 0;
  std::string joint;  ///< "Left knee"
  std::vector<double> times;
  std::vector<double> shares;  ///< at `times`, 1 = all of the athlete's strength there
  double peak = 0.0;           ///< the dense check's largest share
  double peak_time_s = 0.0;
  /// "left knee extension 64 % of the athlete's strength at t = 0.31 s"; beyond it, the line
  /// `saltus evaluate` prints ("left knee flexion would need 708 % of his strength at t = 0.04 s
  /// (29 of 4 N·m at 30°, shortening at 13.7 rad/s)").
  std::string peak_words;
};

/// A strip for every joint with a strength curve, in model order, from the stage's dense plot
/// samples and its dense check.
std::vector<StrengthStrip> strength_strips(const BodyModel& model,
                                           const std::vector<SampleRecord>& samples,
                                           const DenseCheck& check);

}  // namespace saltus::gui
