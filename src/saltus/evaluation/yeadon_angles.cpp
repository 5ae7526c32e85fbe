#include "saltus/evaluation/yeadon_angles.h"

#include <algorithm>
#include <cmath>

#include "saltus/base/constants.h"

namespace saltus {

namespace {

constexpr double kTwoPi = 2.0 * 3.14159265358979323846;
constexpr double kMaxSpacing = 0.0025;  ///< s, the dense check's

/// `angle` moved by whole turns to lie within half a turn of `near`.
double nearest_turn(double angle, double near) {
  return angle + kTwoPi * std::round((near - angle) / kTwoPi);
}

/// "", "¼", "½", "¾" for a count rounded to quarters, or e.g. "1½".
std::string quarters(double count) {
  const long q = std::lround(std::abs(count) * 4.0);
  const long whole = q / 4;
  static const char* const kFraction[4] = {"", "¼", "½", "¾"};
  if (q % 4 == 0) return std::to_string(whole);
  return (whole > 0 ? std::to_string(whole) : std::string()) + kFraction[q % 4];
}

}  // namespace

double forward_somersault_sign(const Eigen::Quaterniond& world_from_root_at_takeoff) {
  const Eigen::Vector3d left = world_from_root_at_takeoff * Eigen::Vector3d::UnitX();
  return left.x() >= 0.0 ? 1.0 : -1.0;
}

Eigen::Vector3d somersault_tilt_twist(const Eigen::Quaterniond& world_from_root) {
  const Eigen::Matrix3d r = world_from_root.normalized().toRotationMatrix();
  // Rx(φ)·Rz(θ)·Ry(ψ) = [cθcψ, −sθ, cθsψ; ·, cφcθ, ·; ·, sφcθ, ·].
  const double theta = std::asin(std::clamp(-r(0, 1), -1.0, 1.0));
  const double phi = std::atan2(r(2, 1), r(1, 1));
  const double psi = std::atan2(r(0, 2), r(0, 0));
  return {phi, theta, psi};
}

Eigen::Vector3d somersault_tilt_twist_rates(const Eigen::Vector3d& angles,
                                            const Eigen::Vector3d& omega_body) {
  const double theta = angles[1], psi = angles[2];
  const double ct = std::cos(theta), st = std::sin(theta);
  const double cp = std::cos(psi), sp = std::sin(psi);
  Eigen::Matrix3d a;
  a.col(0) << cp * ct, -st, sp * ct;  // Ryᵀ·Rzᵀ·x̂
  a.col(1) << -sp, 0.0, cp;           // Ryᵀ·ẑ
  a.col(2) << 0.0, 1.0, 0.0;          // ŷ
  return a.partialPivLu().solve(omega_body);
}

std::vector<Eigen::Vector3d> unwrapped_angles(const std::vector<Eigen::Quaterniond>& rotations) {
  std::vector<Eigen::Vector3d> out;
  out.reserve(rotations.size());
  for (const Eigen::Quaterniond& q : rotations) {
    Eigen::Vector3d a = somersault_tilt_twist(q);
    if (!out.empty()) {
      a[0] = nearest_turn(a[0], out.back()[0]);
      a[2] = nearest_turn(a[2], out.back()[2]);
    }
    out.push_back(a);
  }
  return out;
}

YeadonSummary yeadon_summary(const Trajectory<double>& trajectory, int min_points) {
  YeadonSummary s;
  const double duration = trajectory.duration();
  if (trajectory.rotations.empty() || !(duration > 0)) {
    s.description = somersault_twist_words(0, 0);
    return s;
  }
  const int intervals =
      std::max({min_points - 1, static_cast<int>(std::ceil(duration / kMaxSpacing)), 1});
  std::vector<Eigen::Quaterniond> rotations;
  std::vector<Eigen::Vector3d> omegas;
  std::vector<double> times;
  for (int i = 0; i <= intervals; ++i) {
    const double t = duration * i / intervals;
    const auto sample = trajectory.rotations[0].evaluate(t);
    rotations.push_back(sample.q);
    omegas.push_back(sample.omega);
    times.push_back(t);
  }
  const std::vector<Eigen::Vector3d> angles = unwrapped_angles(rotations);
  for (std::size_t i = 0; i < angles.size(); ++i) {
    s.max_tilt_deg = std::max(s.max_tilt_deg, std::abs(angles[i][1]) * kDegreesPerRadian);
    const double twist_rate =
        std::abs(somersault_tilt_twist_rates(angles[i], omegas[i])[2]) / kTwoPi;
    if (twist_rate > s.peak_twist_rate_rev_s)
      s.peak_twist_rate_rev_s = twist_rate, s.peak_twist_rate_time_s = times[i];
  }
  s.somersaults =
      forward_somersault_sign(rotations.front()) * (angles.back()[0] - angles.front()[0]) / kTwoPi;
  s.twists = (angles.back()[2] - angles.front()[2]) / kTwoPi;
  s.description = somersault_twist_words(s.somersaults, s.twists);
  return s;
}

YeadonSummary yeadon_summary(const std::vector<Eigen::Quaterniond>& root_rotations) {
  YeadonSummary s;
  const std::vector<Eigen::Vector3d> angles = unwrapped_angles(root_rotations);
  for (const Eigen::Vector3d& a : angles)
    s.max_tilt_deg = std::max(s.max_tilt_deg, std::abs(a[1]) * kDegreesPerRadian);
  if (!angles.empty()) {
    s.somersaults = forward_somersault_sign(root_rotations.front()) *
                    (angles.back()[0] - angles.front()[0]) / kTwoPi;
    s.twists = (angles.back()[2] - angles.front()[2]) / kTwoPi;
  }
  s.description = somersault_twist_words(s.somersaults, s.twists);
  return s;
}

std::string somersault_twist_words(double somersaults, double twists) {
  const std::string s = quarters(somersaults);
  const bool many_somersaults = std::lround(std::abs(somersaults) * 4.0) > 4;
  std::string out;
  if (s == "0")
    out = "no somersault";
  else
    out = (std::lround(std::abs(somersaults) * 4.0) < 4 ? "a " : "") + s +
          (somersaults < 0 ? " back" : " front") +
          (many_somersaults ? " somersaults" : " somersault");
  const long halves = std::lround(std::abs(twists) * 2.0);
  if (halves == 0) return out;
  const std::string t = halves % 2 == 0 ? std::to_string(halves / 2)
                                        : (halves > 1 ? std::to_string(halves / 2) : "") + "½";
  return out + " with " + t + (halves > 2 ? " twists" : " twist") +
         (twists > 0 ? " to the left" : " to the right");
}

}  // namespace saltus
