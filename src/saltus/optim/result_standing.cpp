#include "saltus/optim/result_standing.h"

#include "saltus/base/text_format.h"

namespace saltus {

ResultStanding result_standing(const OptimizationResult& result, const BodyModel& model) {
  ResultStanding out;
  out.solved = result.solve.solved;
  out.avg_root_force = result.after.metrics.avg_root_force;
  out.largest_rise = largest_joint_load_rise(model, result.before.check, result.after.check);
  out.joints_within_policy = out.largest_rise.ratio() <= kJointLoadRiseLimit;
  return out;
}

bool ranks_above(const ResultStanding& a, const ResultStanding& b) {
  if (a.solved != b.solved) return a.solved;
  if (a.joints_within_policy != b.joints_within_policy) return a.joints_within_policy;
  return a.avg_root_force < b.avg_root_force;
}

std::string human_joints_warning(const OptimizationResult& result, const JointLoadRise& rise) {
  const auto& polish = result.joint_load_polish;
  if (!(polish && polish->bounded_alternative && rise.ratio() > kJointLoadRiseLimit &&
        polish->bounded_alternative->landing_drift_deg >
            AutomaticResolution{}.max_landing_drift_deg))
    return "";
  const JointLoadPolish::BoundedAlternative& alternative = *polish->bounded_alternative;
  return format_number(
             "with human joints instead: the polish's bounded try closest to flying as shown "
             "(every joint within %.2fx its input peak, ",
             alternative.joint_rise) +
         format_number("%.3g N) has a free flight that lands ", alternative.avg_root_force) +
         format_number(
             "%.0f deg from it: with the joints its input needs, this body does not "
             "fly these keyframes",
             alternative.landing_drift_deg);
}

}  // namespace saltus
