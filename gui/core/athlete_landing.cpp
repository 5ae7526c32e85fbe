#include "core/athlete_landing.h"

#include <cmath>

#include "core/athletes.h"
#include "saltus/base/text_format.h"
#include "saltus/body/segment_names.h"
#include "saltus/evaluation/joint_loads.h"
#include "saltus/evaluation/strength_demand.h"
#include "saltus/evaluation/what_if.h"
#include "saltus/optim/result_standing.h"

namespace saltus::gui {

AthleteLanding athlete_landing(const MotionFile& on_athlete, const EvaluateOptions& options,
                               const OptimizationResult* run) {
  AthleteLanding out;
  out.athlete = athlete_label(on_athlete);
  // The motion as keyframed, flown from its take-off: WhatIf's unchanged flight is
  // simulate_motion's, judged against the keyframed landing with the library's tolerance.
  const WhatIf prepared(on_athlete.motion, on_athlete.model, options);
  const WhatIfResult flown = prepared.fly(WhatIfChange{});
  out.flight = flown.flight;
  out.lands = flown.within_tolerance;
  out.tolerance_deg = flown.tolerance_deg;
  out.landing_error_deg = flown.flight.landing_root_error_deg;
  out.sentence = flown.sentence;
  out.flight_words =
      "Flies " + flown.landing.description + "; keyframed: " + prepared.target().description;
  const double worst =
      std::max(std::abs(flown.somersault_over_deg), std::abs(flown.twist_over_deg));
  out.headline =
      out.lands
          ? format_number("Lands it: %.0f° from the keyframed landing", worst) +
                format_number(" (within %.0f°)", out.tolerance_deg)
          : format_number("Does not land it: the body is %.0f° off the last keyframe at landing",
                          out.landing_error_deg) +
                format_number(" (more than %.0f° off)", out.tolerance_deg);

  // The joints against this athlete's strength: the run's optimised motion, else the keyframes;
  // in the words `saltus evaluate` and `optimize` print.
  const DenseCheck check =
      run ? run->after.check : evaluate_motion(on_athlete.motion, on_athlete.model, options).check;
  const BodyModel& model = on_athlete.model;
  for (int k = 1; k < model.size() && k < static_cast<int>(check.strength_peaks.size()); ++k) {
    const JointStrengthPeak& peak = check.strength_peaks[static_cast<std::size_t>(k)];
    const std::optional<double> share =
        peak.coordinate >= 0 ? std::optional<double>(peak.share) : std::nullopt;
    out.joints.push_back(
        {capitalised(joint_label(model.segments[static_cast<std::size_t>(k)].joint)), share,
         strength_light(share)});
  }
  out.strength_words = strength_verdict_words(model, check.strength_peaks);
  out.over_strength = over_strength_lines(model, check.strength_peaks);
  const int largest = largest_strength_share(check.strength_peaks);
  out.strength_light = strength_light(
      largest > 0
          ? std::optional<double>(check.strength_peaks[static_cast<std::size_t>(largest)].share)
          : std::nullopt);

  if (run) {
    const JointLoadRise rise =
        largest_joint_load_rise(on_athlete.model, run->before.check, run->after.check);
    if (!rise.joint.empty() && rise.ratio() > kJointLoadRiseLimit)
      out.warnings.push_back(joint_load_verdict_words(rise));
    const std::string human = human_joints_warning(*run, rise);
    if (!human.empty()) out.warnings.push_back(human);
  }
  return out;
}

}  // namespace saltus::gui
