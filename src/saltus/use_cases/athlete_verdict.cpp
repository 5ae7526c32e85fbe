#include "saltus/use_cases/athlete_verdict.h"

#include <cmath>

#include "saltus/base/text_format.h"
#include "saltus/evaluation/joint_loads.h"
#include "saltus/evaluation/strength_demand.h"
#include "saltus/evaluation/what_if.h"
#include "saltus/optim/result_standing.h"

namespace saltus {

namespace {

/// The verdict on `flown` (the motion whose free flight is judged) with the strength peaks of
/// the motion judged; `run` adds its joints' warnings.
AthleteVerdict verdict_of(const Motion& flown, const BodyModel& model,
                          const EvaluateOptions& options,
                          const std::vector<JointStrengthPeak>& peaks,
                          const OptimizationResult* run) {
  AthleteVerdict out;
  // The motion as keyframed, flown from its take-off: WhatIf's unchanged flight is
  // simulate_motion's, judged against the keyframed landing with the library's tolerance.
  const WhatIf prepared(flown, model, options);
  const WhatIfResult landing = prepared.fly(WhatIfChange{});
  out.flight = landing.flight;
  out.lands = landing.within_tolerance;
  out.tolerance_deg = landing.tolerance_deg;
  out.somersault_over_deg = landing.somersault_over_deg;
  out.twist_over_deg = landing.twist_over_deg;
  out.landing_error_deg = landing.flight.landing_root_error_deg;
  out.flight_words =
      "Flies " + landing.landing.description + "; keyframed: " + prepared.target().description;

  out.strength_peaks = peaks;
  out.strength_words = strength_verdict_words(model, peaks);
  out.reasons = over_strength_lines(model, peaks);
  const int largest = largest_strength_share(peaks);
  const bool strength_known = largest > 0;
  const bool within_strength =
      strength_known && peaks[static_cast<std::size_t>(largest)].share <= 1.0;

  std::string pays, human;
  if (run) {
    const JointLoadRise rise = largest_joint_load_rise(model, run->before.check, run->after.check);
    if (!rise.joint.empty() && rise.ratio() > kJointLoadRiseLimit) {
      pays = joint_load_verdict_words(rise);
      out.reasons.push_back(pays);
    }
    human = human_joints_warning(*run, rise);
    if (!human.empty()) out.reasons.push_back(human);
  }

  if (!out.lands) {
    out.light = VerdictLight::kRed;
    out.headline = "Does not land it: " + landing.verdict +
                   format_number(" (more than %.0f° off)", out.tolerance_deg);
    out.summary = "Does not land it";
  } else if (!human.empty()) {
    // It lands only because a joint pays: with the joints its input needs, it does not.
    out.light = VerdictLight::kRed;
    out.headline =
        "Does not land it with human joints: the optimised motion lands only because a joint "
        "carries many times its load";
    out.summary = "Does not land it with human joints";
  } else {
    const std::string landed =
        "Lands it" +
        format_number(" (%.0f° from the keyframed landing, within ",
                      std::max(std::abs(out.somersault_over_deg), std::abs(out.twist_over_deg))) +
        format_number("%.0f°)", out.tolerance_deg);
    if (!strength_known) {
      out.light = VerdictLight::kAmber;
      out.headline = landed + ", but its joints cannot be checked: " + out.strength_words;
      out.summary = "Lands it; its joints cannot be checked";
    } else if (!within_strength) {
      out.light = VerdictLight::kAmber;
      out.headline = landed + ", but " + out.strength_words;
      out.summary = "Lands it, but " + out.strength_words.substr(0, out.strength_words.find(" ("));
    } else if (!pays.empty()) {
      out.light = VerdictLight::kAmber;
      out.headline = landed + ", but the optimiser made a joint pay for the root force";
      out.summary = "Lands it, but a joint pays for the root force";
    } else {
      out.light = VerdictLight::kGreen;
      out.headline = landed + ", " + out.strength_words;
      out.summary = "Lands it within the athlete's strength";
    }
  }
  return out;
}

}  // namespace

std::string verdict_light_name(VerdictLight light) {
  switch (light) {
    case VerdictLight::kGreen:
      return "green";
    case VerdictLight::kAmber:
      return "amber";
    case VerdictLight::kRed:
      break;
  }
  return "red";
}

AthleteVerdict athlete_verdict(const MotionFile& file, const EvaluateOptions& options,
                               const MotionEvaluation& evaluation) {
  return verdict_of(file.motion, file.model, options, evaluation.check.strength_peaks, nullptr);
}

AthleteVerdict athlete_verdict(const MotionFile& file, const EvaluateOptions& options) {
  return athlete_verdict(file, options, evaluate_motion(file.motion, file.model, options));
}

AthleteVerdict athlete_verdict(const MotionFile& file, const EvaluateOptions& options,
                               const OptimizationResult& run) {
  return verdict_of(run.optimized_motion, file.model, options, run.after.check.strength_peaks,
                    &run);
}

}  // namespace saltus
