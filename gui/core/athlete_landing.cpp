#include "core/athlete_landing.h"

#include <cmath>

#include "core/athletes.h"
#include "saltus/base/text_format.h"
#include "saltus/body/segment_names.h"
#include "saltus/evaluation/joint_loads.h"
#include "saltus/evaluation/joint_strength.h"
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

  // The joints against this athlete's strength: the run's optimised motion, else the keyframes.
  const DenseCheck check =
      run ? run->after.check : evaluate_motion(on_athlete.motion, on_athlete.model, options).check;
  const std::vector<JointMomentShare> shares = joint_moment_shares(on_athlete.model, check);
  for (const JointMomentShare& share : shares)
    out.joints.push_back(
        {capitalised(joint_label(share.joint)), share.share, strength_light(share.share)});
  out.strength_words = joint_moment_share_words(shares);
  const std::optional<JointMomentShare> largest = largest_joint_moment_share(shares);
  out.strength_light = strength_light(largest ? largest->share : std::nullopt);

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
