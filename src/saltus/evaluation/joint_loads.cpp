#include "saltus/evaluation/joint_loads.h"

#include <algorithm>

#include "saltus/base/constants.h"
#include "saltus/base/text_format.h"

namespace saltus {

std::vector<JointLoadRise> joint_load_rises(const BodyModel& model, const DenseCheck& before,
                                            const DenseCheck& after) {
  std::vector<JointLoadRise> rises;
  const int n = std::min({model.size(), static_cast<int>(before.joint_peaks.size()),
                          static_cast<int>(after.joint_peaks.size())});
  for (int k = 1; k < n; ++k) {
    JointLoadRise r;
    r.joint = model.segments[k].joint;
    r.before = before.joint_peaks[k];
    r.after = after.joint_peaks[k];
    r.force_ratio = std::max(r.after.force_N, kJointForceFloorN) /
                    std::max(r.before.force_N, kJointForceFloorN);
    r.moment_ratio = std::max(r.after.moment_Nm, kJointMomentFloorNm) /
                     std::max(r.before.moment_Nm, kJointMomentFloorNm);
    rises.push_back(r);
  }
  return rises;
}

JointLoadRise largest_joint_load_rise(const BodyModel& model, const DenseCheck& before,
                                      const DenseCheck& after) {
  JointLoadRise largest;
  bool found = false;
  for (const JointLoadRise& r : joint_load_rises(model, before, after))
    if (!found || r.ratio() > largest.ratio()) largest = r, found = true;
  return largest;
}

double body_weight_N(const BodyModel& model) {
  return model.total_mass() * kStandardGravity;
}

std::string joint_load_rise_words(const JointLoadRise& rise, double body_weight) {
  if (rise.moment_ratio >= rise.force_ratio)
    return rise.joint + format_number(", moment %.3g N·m", rise.after.moment_Nm) +
           format_number(" at t = %.3f s after, ", rise.after.moment_time_s) +
           format_number("%.3g N·m before", rise.before.moment_Nm) +
           format_number(" (%.2fx)", rise.moment_ratio);
  return rise.joint + format_number(", force %.3g N", rise.after.force_N) +
         format_number(" (%.0f %% of body weight)", 100.0 * rise.after.force_N / body_weight) +
         format_number(" at t = %.3f s after, ", rise.after.force_time_s) +
         format_number("%.3g N before", rise.before.force_N) +
         format_number(" (%.2fx)", rise.force_ratio);
}

std::string joint_load_verdict_words(const JointLoadRise& rise) {
  if (rise.ratio() <= kJointLoadRiseLimit)
    return format_number("every joint within %.2fx of its peak load before", rise.ratio());
  return rise.joint + format_number(" carries %.2fx its peak load before", rise.ratio()) +
         format_number(
             " (more than %.2gx): the optimiser made it pay for the root force; do not "
             "read it as the athlete's",
             kJointLoadRiseLimit);
}

}  // namespace saltus
