#include "saltus/evaluation/flight_checks.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "saltus/base/constants.h"
#include "saltus/evaluation/yeadon_angles.h"
#include "saltus/motion/interpolate.h"

namespace saltus {

double ballistic_flight_time(const Takeoff& takeoff, double landing_height) {
  const double g = gravity().norm();
  const double v = takeoff.com_velocity.y();
  const double drop = takeoff.com_position.y() - landing_height;
  const double discriminant = v * v + 2.0 * g * drop;
  if (discriminant < 0.0) return std::numeric_limits<double>::quiet_NaN();
  return (v + std::sqrt(discriminant)) / g;
}

FlightChecks flight_checks(const Takeoff& takeoff, const std::vector<SampleRecord>& samples) {
  if (samples.empty()) throw std::invalid_argument("flight_checks: no samples");
  FlightChecks out;
  const Eigen::Vector3d l0 = samples.front().angular_momentum;
  const double l0_norm = l0.norm();
  out.samples.reserve(samples.size());
  for (const SampleRecord& s : samples) {
    FlightCheckSample c;
    c.time = s.time;
    c.com_off_parabola_m = (s.com - ballistic_com(takeoff, s.time)).norm();
    c.angular_momentum_drift_percent =
        l0_norm > 0.0 ? 100.0 * (s.angular_momentum - l0).norm() / l0_norm : 0.0;
    out.max_com_off_parabola_m = std::max(out.max_com_off_parabola_m, c.com_off_parabola_m);
    out.max_angular_momentum_drift_percent =
        std::max(out.max_angular_momentum_drift_percent, c.angular_momentum_drift_percent);
    out.samples.push_back(c);
  }
  out.flight_time = samples.back().time;
  out.ballistic_flight_time = ballistic_flight_time(takeoff, samples.back().com.y());
  out.height_change_m = samples.back().com.y() - takeoff.com_position.y();
  return out;
}

double forward_somersault_sign(const SampleRecord& takeoff) {
  if (takeoff.segment_rotation.empty()) throw std::invalid_argument("sample without a pose");
  return forward_somersault_sign(takeoff.segment_rotation.front());
}

FlightCheckVerdict judge_flight(const FlightChecks& checks) {
  FlightCheckVerdict v;
  v.on_parabola = checks.max_com_off_parabola_m <= kFreeFlightComToleranceM;
  v.angular_momentum_kept =
      checks.max_angular_momentum_drift_percent <= kFreeFlightAngularMomentumTolerancePercent;
  // NaN (thrown too low to come down to where the motion ends) fails.
  v.flight_time_matches =
      std::abs(checks.ballistic_flight_time - checks.flight_time) <= kFreeFlightTimeToleranceS;
  return v;
}

}  // namespace saltus
