#include "saltus/evaluation/twist_sources.h"

#include <algorithm>
#include <cmath>
#include <future>
#include <stdexcept>
#include <thread>

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
  for (Movement& m : movements) {
    std::vector<std::string> present;
    for (const std::string& j : m.joints)
      if (model.joint_index(j) > 0) present.push_back(j);
    m.joints = present;
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

  // Each movement's share is its Shapley value: the tilt it adds, v(S) − v(S ∪ {it}), averaged
  // over every set S of the other movements made symmetric first, weighted |S|!(n−|S|−1)!/n!.
  // The shares then add up to v(none) − v(all) exactly, whatever the movements do together
  // (one arm adducting against the other overhead tilts the body only through both).
  std::vector<const Movement*> present;
  for (const Movement& m : movements)
    if (!m.joints.empty()) present.push_back(&m);
  const int n = static_cast<int>(present.size());
  const int subsets = 1 << n;
  // The 2^n − 1 counterfactual flights are independent: flown on a few threads, each filling
  // its own masks (the result does not depend on the thread count).
  std::vector<std::vector<double>> tilt_of_mask(subsets);
  const auto fly = [&](int mask) {
    std::vector<std::string> joints;
    for (int i = 0; i < n; ++i)
      if (mask & (1 << i))
        joints.insert(joints.end(), present[i]->joints.begin(), present[i]->joints.end());
    tilt_of_mask[mask] =
        tilt_of(simulate_motion(with_symmetric_joints(actual, model, joints), model, options));
  };
  const int threads = std::clamp(static_cast<int>(std::thread::hardware_concurrency()), 1,
                                 std::max(1, subsets - 1));
  std::vector<std::future<void>> flying;
  for (int t = 1; t < threads; ++t)
    flying.push_back(std::async(std::launch::async, [&, t] {
      for (int mask = 1 + t; mask < subsets; mask += threads)
        fly(mask);
    }));
  for (int mask = 1; mask < subsets; mask += threads)
    fly(mask);
  for (std::future<void>& f : flying)
    f.get();  // rethrows a flight's exception

  std::vector<double> tilt_with_symmetric(subsets, out.total_tilt_deg);  // [mask of movements]
  for (int mask = 1; mask < subsets; ++mask) {
    const std::vector<double>& tilt = tilt_of_mask[mask];
    tilt_with_symmetric[mask] = at_time(out.times, tilt, out.reference_time_s);
    // The curves kept: every movement symmetric (the take-off's), then each one alone.
    if (mask == subsets - 1) {
      out.flight_names.insert(out.flight_names.begin() + 1, "take-off only");
      out.tilt_deg.insert(out.tilt_deg.begin() + 1, tilt);
    }
    if ((mask & (mask - 1)) == 0) {
      int i = 0;
      while (!(mask & (1 << i)))
        ++i;
      out.flight_names.push_back(std::string("without ") + present[i]->name);
      out.tilt_deg.push_back(tilt);
    }
  }
  const auto factorial = [](int k) {
    double f = 1.0;
    for (int i = 2; i <= k; ++i)
      f *= i;
    return f;
  };
  const double takeoff = tilt_with_symmetric[subsets - 1];
  out.shares.push_back({"take-off", takeoff, 0.0});
  double sum = takeoff;
  for (int i = 0; i < n; ++i) {
    double value = 0.0;
    for (int mask = 0; mask < subsets; ++mask) {
      if (mask & (1 << i)) continue;
      int size = 0;
      for (int b = mask; b; b &= b - 1)
        ++size;
      value += factorial(size) * factorial(n - size - 1) / factorial(n) *
               (tilt_with_symmetric[mask] - tilt_with_symmetric[mask | (1 << i)]);
    }
    out.shares.push_back({present[i]->name, value, 0.0});
    sum += value;
  }
  out.interaction_deg = out.total_tilt_deg - sum;
  for (TwistShare& s : out.shares) {
    s.percent = std::abs(out.total_tilt_deg) > 1e-9 ? 100.0 * s.tilt_deg / out.total_tilt_deg : 0;
    if (std::abs(s.percent) < 0.05) s.percent = 0.0;  // no "−0 %"
  }

  // The sentence: the sources in order of their share, those of at least 5 %; then those that
  // worked against the tilt by at least 5 % (else "202 % came from the right arm" stands alone).
  std::vector<TwistShare> ordered = out.shares;
  std::sort(ordered.begin(), ordered.end(),
            [](const TwistShare& a, const TwistShare& b) { return a.percent > b.percent; });
  if (!has_tilt_to_share(out.total_tilt_deg)) {
    out.sentence =
        format_number("The body is tilted by %.1f° at mid-flight: nothing to twist with.",
                      std::abs(out.total_tilt_deg));
  } else {
    out.sentence =
        format_number("Of the %.1f° of tilt at mid-flight, ", std::abs(out.total_tilt_deg));
    bool first = true;
    for (const TwistShare& s : ordered) {
      if (s.percent < 5.0) continue;
      out.sentence += (first ? "" : ", ") +
                      format_number(first ? "%.0f %% came from " : "%.0f %% from ", s.percent) +
                      "the " + s.source;
      first = false;
    }
    // Largest first: "; the left arm (102 %) and the legs (6 %) worked against it".
    std::vector<const TwistShare*> against;
    for (auto s = ordered.rbegin(); s != ordered.rend() && s->percent <= -5.0; ++s)
      against.push_back(&*s);
    for (std::size_t i = 0; i < against.size(); ++i)
      out.sentence += std::string(i == 0                    ? "; the "
                                  : i + 1 == against.size() ? " and the "
                                                            : ", the ") +
                      against[i]->source + format_number(" (%.0f %%)", -against[i]->percent);
    if (!against.empty()) out.sentence += " worked against it";
    out.sentence += ".";
  }
  return out;
}

}  // namespace saltus
