#include "saltus/evaluation/twist_sources.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "saltus/base/constants.h"
#include "saltus/base/text_format.h"
#include "saltus/evaluation/simulate.h"
#include "saltus/evaluation/yeadon_angles.h"

namespace saltus {

namespace {

/// The rotation reflected in the sagittal plane (x → −x): the same turn about the mirrored axis.
Eigen::Quaterniond mirror(const Eigen::Quaterniond& q) {
  return Eigen::Quaterniond(q.w(), q.x(), -q.y(), -q.z());
}

/// The other side's name ("shoulder_l" ↔ "shoulder_r"), or "" for a joint without a side.
std::string counterpart(const std::string& joint) {
  const std::size_t n = joint.size();
  if (n > 2 && joint.compare(n - 2, 2, "_l") == 0) return joint.substr(0, n - 2) + "_r";
  if (n > 2 && joint.compare(n - 2, 2, "_r") == 0) return joint.substr(0, n - 2) + "_l";
  return "";
}

/// The midpoint of two rotations (sign-aligned normalised sum).
Eigen::Quaterniond midpoint(const Eigen::Quaterniond& a, Eigen::Quaterniond b) {
  if (a.coeffs().dot(b.coeffs()) < 0) b.coeffs() = -b.coeffs();
  return Eigen::Quaterniond((a.coeffs() + b.coeffs()).normalized());
}

/// Tilt (deg) of a free flight at every sample.
std::vector<double> tilt_of(const SimulationResult& flight) {
  std::vector<Eigen::Quaterniond> roots;
  for (const SampleRecord& s : flight.samples)
    roots.push_back(s.segment_rotation.at(0));
  std::vector<double> out;
  for (const Eigen::Vector3d& a : unwrapped_angles(roots))
    out.push_back(a[1] * kDegreesPerRadian);
  return out;
}

/// Linear interpolation of `values` at `time`.
double at_time(const std::vector<double>& times, const std::vector<double>& values, double time) {
  for (std::size_t i = 0; i + 1 < times.size(); ++i)
    if (time <= times[i + 1]) {
      const double u = (time - times[i]) / (times[i + 1] - times[i]);
      return values[i] + u * (values[i + 1] - values[i]);
    }
  return values.back();
}

struct Movement {
  const char* name;
  std::vector<std::string> joints;
};

}  // namespace

Motion with_symmetric_joints(const Motion& motion, const BodyModel& model,
                             const std::vector<std::string>& joints) {
  Motion out = motion;
  out.spline.reset();  // the keyframes are changed: their interpolation is the motion now
  for (std::size_t i = 0; i < motion.keyframes.size(); ++i)
    for (const std::string& joint : joints) {
      const int k = model.joint_index(joint);
      if (k <= 0) throw std::invalid_argument("no joint named '" + joint + "' (or the root)");
      const std::string other = counterpart(joint);
      const int c = other.empty() ? k : model.joint_index(other);
      if (c < 0) throw std::invalid_argument("no joint named '" + other + "'");
      // The mean of the joint and its counterpart's mirror image (of itself, unpaired): what is
      // left when the asymmetry between the sides is taken away.
      out.keyframes[i].rotations[k] =
          midpoint(motion.keyframes[i].rotations[k], mirror(motion.keyframes[i].rotations[c]));
    }
  return out;
}

TwistSources twist_sources(const Motion& motion, const BodyModel& model,
                           const EvaluateOptions& options) {
  Motion actual = motion;
  actual.spline.reset();
  const SimulationResult own = simulate_motion(actual, model, options);
  // Every counterfactual starts from the same take-off state.
  actual.takeoff.angular_momentum = own.angular_momentum;

  std::vector<Movement> movements = {
      {"left arm", {"shoulder_l", "elbow_l"}},
      {"right arm", {"shoulder_r", "elbow_r"}},
      {"legs", {"hip_l", "hip_r", "knee_l", "knee_r", "ankle_l", "ankle_r"}},
      {"trunk", {"lumbar", "thoracic"}}};
  std::vector<std::string> every_joint;
  for (Movement& m : movements) {
    std::vector<std::string> present;
    for (const std::string& j : m.joints)
      if (model.joint_index(j) > 0) present.push_back(j);
    m.joints = present;
    every_joint.insert(every_joint.end(), present.begin(), present.end());
  }

  TwistSources out;
  for (const SampleRecord& s : own.samples)
    out.times.push_back(s.time);
  out.reference_time_s = 0.5 * actual.flight_time();
  out.flight_names.push_back("actual");
  out.tilt_deg.push_back(tilt_of(own));
  std::vector<Eigen::Quaterniond> roots;
  for (const SampleRecord& s : own.samples)
    roots.push_back(s.segment_rotation.at(0));
  out.twists = yeadon_summary(roots).twists;
  out.total_tilt_deg = at_time(out.times, out.tilt_deg[0], out.reference_time_s);

  const auto fly = [&](const std::string& name, const std::vector<std::string>& joints) {
    const SimulationResult flight =
        simulate_motion(with_symmetric_joints(actual, model, joints), model, options);
    out.flight_names.push_back(name);
    out.tilt_deg.push_back(tilt_of(flight));
    return at_time(out.times, out.tilt_deg.back(), out.reference_time_s);
  };
  const double takeoff = fly("take-off only", every_joint);
  out.shares.push_back({"take-off", takeoff, 0.0});
  double sum = takeoff;
  for (const Movement& m : movements) {
    if (m.joints.empty()) continue;
    const double without = fly(std::string("without ") + m.name, m.joints);
    out.shares.push_back({m.name, out.total_tilt_deg - without, 0.0});
    sum += out.total_tilt_deg - without;
  }
  out.interaction_deg = out.total_tilt_deg - sum;
  for (TwistShare& s : out.shares) {
    s.percent = std::abs(out.total_tilt_deg) > 1e-9 ? 100.0 * s.tilt_deg / out.total_tilt_deg : 0;
    if (std::abs(s.percent) < 0.05) s.percent = 0.0;  // no "−0 %"
  }

  // The sentence: the sources in order of their share, those of at least 5 %.
  std::vector<TwistShare> ordered = out.shares;
  std::sort(ordered.begin(), ordered.end(),
            [](const TwistShare& a, const TwistShare& b) { return a.percent > b.percent; });
  if (!has_tilt_to_share(out.total_tilt_deg)) {
    out.sentence =
        format_number("The body is tilted by %.1f° at mid-flight: nothing to twist with.",
                      std::abs(out.total_tilt_deg));
  } else {
    out.sentence =
        format_number("Of the %.0f° of tilt at mid-flight, ", std::abs(out.total_tilt_deg));
    bool first = true;
    for (const TwistShare& s : ordered) {
      if (s.percent < 5.0) continue;
      out.sentence += (first ? "" : ", ") +
                      format_number(first ? "%.0f %% came from " : "%.0f %% from ", s.percent) +
                      "the " + s.source;
      first = false;
    }
    out.sentence += ".";
  }
  return out;
}

}  // namespace saltus
