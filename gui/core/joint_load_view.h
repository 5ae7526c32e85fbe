#pragma once
/// @file
/// The Joint loads tab as a coach reads it: for one joint, its force against time with a second
/// axis in % of body weight, its moment with a second axis in % of the published maximal moment
/// of that joint for this athlete (evaluation/joint_strength.h: per kg of body mass, times the
/// athlete's mass), a line that says the peaks in those terms with a traffic light, and, with a
/// run shown, the moment the optimiser raised the joint's load marked on the chart (its peak
/// after against before, evaluation/joint_loads.h), in the words of `saltus optimize`.

#include <optional>
#include <string>
#include <vector>

#include "core/chart_spec.h"
#include "saltus/body/body_model.h"
#include "saltus/evaluation/force_metrics.h"
#include "saltus/evaluation/joint_loads.h"

namespace saltus::gui {

/// A joint's moment against the athlete's strength, as a traffic light.
enum class StrengthLight { kUnknown, kGreen, kAmber, kRed };

/// Green below kAmberShare of the maximum, amber from it up to the maximum, red beyond it
/// (more than the strongest healthy adults' published maximum, per kg); unknown without one.
inline constexpr double kAmberShare = 0.8;
StrengthLight strength_light(const std::optional<double>& share);
/// "within its strength", "near its maximum", "beyond its maximum", "no published maximum".
std::string strength_light_words(StrengthLight light);
Rgb strength_light_colour(StrengthLight light);

/// A rise of a joint's peak load past this is marked on its chart (smaller ones are the
/// optimiser's noise, not a load it asked of the joint).
inline constexpr double kMarkedJointRise = 1.1;

/// What the tab shows of one joint.
struct JointLoadView {
  ChartSpec force;   ///< |F| (N), before and after; right axis % of body weight
  ChartSpec moment;  ///< |M| (N·m), before and after; right axis % of the published maximum
  /// The stage shown (after with a run): "Peak force 840 N (131 % of body weight) at 0.420 s ·
  /// peak moment 45.0 N·m at 0.380 s: 24 % of the published maximum for this athlete (2.92
  /// N·m/kg × 65.5 kg = 191 N·m, knee extension)".
  std::string summary;
  std::optional<double> share;  ///< peak moment over the published maximum, none without one
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

}  // namespace saltus::gui
