#include "saltus/evaluation/strength_demand.h"

#include <algorithm>
#include <cmath>

#include "saltus/base/text_format.h"
#include "saltus/body/segment_names.h"

namespace saltus {

namespace {

constexpr double kDegPerRad = 57.29577951308232;

std::string percent(double share) {
  return format_number("%.0f %%", 100.0 * share);
}

}  // namespace

StrengthDemand strength_demand(const AthleteStrength& strength, int segment,
                               const JointState<double>& joint,
                               const Eigen::Vector3d& moment_child) {
  StrengthDemand best;
  const std::array<CoordinateStrength, 3>& curves = strength.joints[segment];
  if (!curves[0].positive && !curves[0].negative && !curves[1].positive && !curves[1].negative &&
      !curves[2].positive && !curves[2].negative)
    return best;
  const JointCoordinateState state =
      joint_coordinate_state(strength.coordinates[segment], joint.q, joint.omega, moment_child);
  for (int i = 0; i < 3; ++i) {
    // The moment drives the coordinate one way: that direction's muscles carry it, shortening
    // when the coordinate moves the same way.
    const bool positive = state.moment[i] >= 0.0;
    const std::optional<StrengthCurve>& curve = positive ? curves[i].positive : curves[i].negative;
    if (!curve) continue;
    const double direction = positive ? 1.0 : -1.0;
    StrengthDemand d;
    d.coordinate = i;
    d.positive = positive;
    d.moment_Nm = std::abs(state.moment[i]);
    d.angle_rad = state.value[i];
    d.shortening_speed = direction * state.rate[i];
    d.capacity_Nm = strength_capacity(*curve, d.angle_rad, d.shortening_speed, &d.extrapolated);
    d.share = d.moment_Nm / d.capacity_Nm;
    if (best.coordinate < 0 || d.share > best.share) best = d;
  }
  return best;
}

std::string strength_direction_words(const BodyModel& model, int segment,
                                     const StrengthDemand& demand) {
  if (demand.coordinate < 0) return "";
  const JointCoordinates coordinates = joint_coordinates(model, segment);
  const JointCoordinate& c = coordinates.coordinates[demand.coordinate];
  return joint_label(model.segments[segment].joint) + " " +
         (demand.positive ? c.positive : c.negative);
}

int largest_strength_share(const std::vector<JointStrengthPeak>& peaks) {
  int best = 0;
  for (std::size_t k = 1; k < peaks.size(); ++k)
    if (peaks[k].coordinate >= 0 && (best == 0 || peaks[k].share > peaks[best].share))
      best = static_cast<int>(k);
  return best;
}

std::vector<std::string> over_strength_lines(const BodyModel& model,
                                             const std::vector<JointStrengthPeak>& peaks) {
  std::vector<int> over;
  for (std::size_t k = 1; k < peaks.size() && k < model.segments.size(); ++k)
    if (peaks[k].coordinate >= 0 && peaks[k].share > 1.0) over.push_back(static_cast<int>(k));
  std::sort(over.begin(), over.end(),
            [&](int a, int b) { return peaks[a].share > peaks[b].share; });
  const std::string whose = model.strength.female ? "her" : "his";
  std::vector<std::string> lines;
  for (const int k : over) {
    const JointStrengthPeak& p = peaks[k];
    const std::string speed =
        std::abs(p.shortening_speed) < 0.05
            ? "held still"
            : format_number(
                  p.shortening_speed > 0 ? "shortening at %.1f rad/s" : "lengthening at %.1f rad/s",
                  std::abs(p.shortening_speed));
    lines.push_back(strength_direction_words(model, k, p) + " would need " + percent(p.share) +
                    " of " + whose + " strength at t = " + format_number("%.2f", p.time_s) +
                    " s (" + format_number("%.0f", p.moment_Nm) + " of " +
                    format_number("%.0f", p.capacity_Nm) + " N·m at " +
                    format_number("%.0f°", kDegPerRad * p.angle_rad) + ", " + speed +
                    (p.extrapolated ? "; beyond the measured range" : "") + ")");
  }
  return lines;
}

std::string strength_verdict_words(const BodyModel& model,
                                   const std::vector<JointStrengthPeak>& peaks) {
  const int k = largest_strength_share(peaks);
  if (k == 0) return "no joint has a strength curve";
  int over = 0;
  for (std::size_t j = 1; j < peaks.size(); ++j)
    if (peaks[j].coordinate >= 0 && peaks[j].share > 1.0) ++over;
  const std::string largest = "(largest: " + strength_direction_words(model, k, peaks[k]) + ", " +
                              percent(peaks[k].share) +
                              " at t = " + format_number("%.2f", peaks[k].time_s) + " s)";
  if (over == 0) return "every joint within the athlete's strength " + largest;
  return std::to_string(over) + (over == 1 ? " joint" : " joints") +
         " beyond the athlete's strength " + largest;
}

}  // namespace saltus
