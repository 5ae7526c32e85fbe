#include "saltus/evaluation/what_if.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

#include "saltus/base/constants.h"
#include "saltus/base/input_error.h"
#include "saltus/base/number_bound.h"
#include "saltus/base/text_format.h"
#include "saltus/motion/interpolate.h"

namespace saltus {

namespace {

/// The joints whose bend makes a tuck or pike, and whose turn the tightness scales.
constexpr const char* kLegJoints[] = {"hip_l", "hip_r", "knee_l", "knee_r"};
/// The bend curve is sampled at least this often, s.
constexpr double kBendStep = 0.0025;
/// A somersault or twist count below this (revolutions) has no direction to be short of.
constexpr double kNoTurn = 0.05;

std::vector<int> leg_segments(const BodyModel& model) {
  std::vector<int> out;
  for (const char* joint : kLegJoints) {
    const int k = model.joint_index(joint);
    if (k > 0) out.push_back(k);
  }
  return out;
}

/// The mean over `legs` of each joint's rotation angle from straight (identity), degrees.
double bend_at(const JointRotationAt& rotation_at, const std::vector<int>& legs, double t) {
  double sum = 0.0;
  for (int k : legs)
    sum += rotation_angle_between(Eigen::Quaterniond::Identity(), rotation_at(k, t));
  return degrees_from_radians(sum / static_cast<double>(legs.size()));
}

/// Where the straight line between samples i and j crosses `level`.
double crossing(const std::vector<double>& times, const std::vector<double>& values, std::size_t i,
                std::size_t j, double level) {
  const double dv = values[j] - values[i];
  if (dv == 0.0) return times[i];
  const double u = std::clamp((level - values[i]) / dv, 0.0, 1.0);
  return times[i] + u * (times[j] - times[i]);
}

/// The times a shift moves, with the group each belongs to: 0 fixed (take-off, landing), 1 the
/// tuck-in, 2 the opening. Strictly increasing, first 0, last T.
struct Anchor {
  double time;
  int group;
};

std::vector<Anchor> anchors_of(const TuckPhases& tuck, double duration) {
  std::vector<Anchor> out = {{0.0, 0}};
  if (!tuck.starts_at_takeoff) out.push_back({tuck.tuck_start_s, 1});
  out.push_back({tuck.tucked_s, 1});
  if (tuck.opens) {
    out.push_back({tuck.open_start_s, 2});
    if (!tuck.opened_at_landing) out.push_back({tuck.opened_s, 2});
  }
  out.push_back({duration, 0});
  return out;
}

/// The time warp w: the new clock → the motion's. The tuck-in and the opening (anchor pairs of
/// one group) are moved whole: w′ = 1 on them. Each other phase is stretched or compressed to
/// its new length: w′ = p on it, except next to a moved anchor, where w′ eases from 1 to p over δ
/// by a smoothstep, so that w′ is continuous and w C². p makes the phase's integral of w′ its
/// old length, so every anchor lands exactly at its new time.
class TimeWarp {
 public:
  struct Value {
    double time = 0.0;          ///< w(t), on the motion's clock
    double rate = 1.0;          ///< w′(t)
    double acceleration = 0.0;  ///< w″(t), 1/s
  };

  TimeWarp(const std::vector<Anchor>& anchors, const WhatIfChange& change) {
    const auto moved = [&](const Anchor& a) {
      return a.time + (a.group == 1 ? change.tuck_later_s : a.group == 2 ? change.open_later_s : 0);
    };
    for (std::size_t i = 0; i + 1 < anchors.size(); ++i) {
      Phase p;
      p.old_start = anchors[i].time;
      p.start = moved(anchors[i]);
      p.end = moved(anchors[i + 1]);
      const double old_length = anchors[i + 1].time - anchors[i].time;
      const double length = p.end - p.start;
      p.whole = anchors[i].group != 0 && anchors[i].group == anchors[i + 1].group;
      if (!p.whole) {
        // Ease in from an anchor that moves (not from take-off or landing, which do not).
        p.ease_start = anchors[i].group != 0;
        p.ease_end = anchors[i + 1].group != 0;
        p.ease = std::min(kWarpBlendS, 0.25 * std::min(old_length, length));
        const double eased = 0.5 * p.ease * ((p.ease_start ? 1 : 0) + (p.ease_end ? 1 : 0));
        p.rate = (old_length - eased) / (length - eased);
      }
      phases_.push_back(p);
    }
  }

  Value at(double t) const {
    std::size_t i = 0;
    while (i + 1 < phases_.size() && t > phases_[i].end)
      ++i;
    const Phase& p = phases_[i];
    const double since = t - p.start;
    Value v;
    if (p.whole) {
      v.time = p.old_start + since;
      return v;
    }
    // w′ = p + (1 − p)·(1 − smooth(u)) near an eased end, u the distance to it in units of δ,
    // smooth(u) = 3u² − 2u³; G(u) = ∫₀ᵘ (1 − smooth) = u − u³ + u⁴/2.
    const auto G = [](double u) { return u - u * u * u + 0.5 * u * u * u * u; };
    const auto smooth = [](double u) { return u * u * (3.0 - 2.0 * u); };
    const double extra = 1.0 - p.rate;
    v.time = p.old_start + p.rate * since;
    v.rate = p.rate;
    v.acceleration = 0.0;
    if (p.ease_start) {
      const double u = std::min(since / p.ease, 1.0);
      v.time += extra * p.ease * G(u);
      if (u < 1.0) {
        v.rate += extra * (1.0 - smooth(u));
        v.acceleration -= extra * 6.0 * u * (1.0 - u) / p.ease;
      }
    }
    if (p.ease_end) {
      const double u = (p.end - t) / p.ease;
      if (u < 1.0) {
        const double clamped = std::max(u, 0.0);
        v.time += extra * p.ease * (G(1.0) - G(clamped));
        v.rate += extra * (1.0 - smooth(clamped));
        v.acceleration += extra * 6.0 * clamped * (1.0 - clamped) / p.ease;
      }
    }
    return v;
  }

  /// The new time at which the motion's clock reads `time` (w is increasing).
  double inverse(double time) const {
    double lo = phases_.front().start, hi = phases_.back().end;
    for (int i = 0; i < 60 && hi - lo > 1e-13; ++i) {
      const double mid = 0.5 * (lo + hi);
      (at(mid).time < time ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
  }

  /// Where w″ is not smooth: the moved anchors and the ends of the easing.
  std::vector<double> kinks() const {
    std::vector<double> out;
    for (const Phase& p : phases_) {
      out.push_back(p.start);
      if (p.ease_start) out.push_back(p.start + p.ease);
      if (p.ease_end) out.push_back(p.end - p.ease);
    }
    return out;
  }

 private:
  struct Phase {
    double start = 0.0, end = 0.0;  ///< on the new clock
    double old_start = 0.0;         ///< w(start)
    bool whole = false;             ///< a moved movement: w′ = 1
    bool ease_start = false, ease_end = false;
    double ease = 0.0;  ///< δ, s
    double rate = 1.0;  ///< p
  };
  std::vector<Phase> phases_;
};

/// c0·exp(s·log(c0⁻¹·c)): c turned s times as far from c0 (signs kept: a spline's controls).
Eigen::Quaterniond scaled_from(const Eigen::Quaterniond& c0, const Eigen::Quaterniond& c,
                               double scale) {
  return c0 * quat_exp<double>(scale * quat_log<double>(c0.conjugate() * c));
}

std::string seconds_words(double s) {
  return format_number("%.3g s", std::abs(s));
}

/// Degrees past (> 0) or short of (< 0) `target` revolutions, in the target's direction (or
/// `fallback`'s when the target has no turn to speak of).
double over_deg(double value, double target, double fallback) {
  const double reference = std::abs(target) >= kNoTurn ? target : fallback;
  const double direction = reference < 0 ? -1.0 : 1.0;
  return 360.0 * (value - target) * direction;
}

std::string over_words(double deg) {
  const double rounded = std::round(std::abs(deg));
  if (rounded == 0.0) return "on target";
  return format_number("%.0f°", rounded) + (deg > 0 ? " over" : " short");
}

/// The joint movements of a what-if flight: the motion's curves, the legs' scaled, followed on
/// the warped clock.
class ChangedJoints {
 public:
  ChangedJoints(const Trajectory<double>& trajectory, const BodyModel& model,
                const TuckPhases& tuck, const WhatIfChange& change)
      : curves_(trajectory) {
    if (change.tuck_scale != 1.0) {
      for (int k : leg_segments(model)) {
        std::vector<Eigen::Quaterniond> control = trajectory.rotations[k].control();
        const Eigen::Quaterniond c0 = control.front();
        for (Eigen::Quaterniond& c : control)
          c = scaled_from(c0, c, change.tuck_scale);
        curves_.rotations[k] = QuaternionSpline<double>(trajectory.knots, std::move(control));
      }
    }
    if (change.tuck_later_s != 0.0 || change.open_later_s != 0.0)
      warp_.emplace(anchors_of(tuck, trajectory.duration()), change);
  }

  QuaternionSample<double> at(int segment, double t) const {
    if (!warp_) return curves_.rotations[segment].evaluate(t);
    const TimeWarp::Value w = warp_->at(t);
    QuaternionSample<double> s = curves_.rotations[segment].evaluate(w.time);
    s.alpha = s.alpha * (w.rate * w.rate) + s.omega * w.acceleration;
    s.omega *= w.rate;
    return s;
  }

  /// For the free flight; refers to this object.
  PrescribedJoints prescribed() const {
    if (!warp_) return trajectory_joints(curves_);
    PrescribedJoints out;
    out.motion = [this](double t, BodyState<double>& state) {
      for (int k = 1; k < curves_.segment_count(); ++k) {
        const QuaternionSample<double> s = at(k, t);
        state.joints[k].q = s.q;
        state.joints[k].omega = s.omega;
        state.joints[k].alpha = s.alpha;
      }
    };
    for (double knot : curves_.knots)
      out.breakpoints.push_back(warp_->inverse(knot));
    for (double kink : warp_->kinks())
      out.breakpoints.push_back(kink);
    out.takeoff_root = curves_.rotations[0].evaluate(0.0).q;
    out.own_landing_root = curves_.rotations[0].evaluate(curves_.duration()).q;
    return out;
  }

  double duration() const { return curves_.duration(); }

 private:
  Trajectory<double> curves_;
  std::optional<TimeWarp> warp_;
};

/// `value` s as the range it is beside prints its ends (%+.3f), with every digit it needs where
/// that would print an end it is not, and short (%g) when it is huge.
std::string seconds_beside(double value, double lo, double hi) {
  const std::string text =
      std::fabs(value) < 1e4 ? format_number("%+.3f", value) : format_number("%+g", value);
  if (text != format_number("%+.3f", lo) && text != format_number("%+.3f", hi)) return text;
  return (value > 0.0 ? "+" : "") + exact_number(value);
}

/// Throws InputError naming the flag (--tuck-later, --open-later, --tuck-scale) for a change
/// the motion does not allow (WhatIf::fly).
void check_change(const TuckPhases& tuck, const WhatIfChange& change) {
  const std::pair<const char*, double> values[] = {{"--tuck-later", change.tuck_later_s},
                                                   {"--open-later", change.open_later_s},
                                                   {"--tuck-scale", change.tuck_scale}};
  for (const auto& [flag, value] : values)
    if (!std::isfinite(value))
      throw InputError(flag, "",
                       "a what-if change must be a finite number, not " + message_number(value));
  check_bound("--tuck-scale", kTuckScaleBound, change.tuck_scale, kTuckScaleWhy);
  if (change.unchanged()) return;
  const char* changed = change.tuck_later_s != 0.0   ? "--tuck-later"
                        : change.open_later_s != 0.0 ? "--open-later"
                                                     : "--tuck-scale";
  if (!tuck.found) throw InputError(changed, "", tuck.reason);
  if (change.open_later_s != 0.0 && !tuck.opens)
    throw InputError("--open-later", "",
                     "The motion lands in its tuck: there is no opening to move.");
  constexpr double kSlack = 1e-9;
  const auto check = [](double value, double lo, double hi, const char* flag, const char* what) {
    if (value < lo - kSlack || value > hi + kSlack)
      throw InputError(flag, "",
                       std::string(what) + format_number(" can move from %+.3f s", lo) +
                           format_number(" to %+.3f s on this motion", hi) + ", not " +
                           seconds_beside(value, lo, hi) + " s.");
  };
  check(change.tuck_later_s, tuck.tuck_later_min_s, tuck.tuck_later_max_s, "--tuck-later",
        "The tuck");
  check(change.open_later_s, tuck.open_later_min_s, tuck.open_later_max_s, "--open-later",
        "The opening");
}

}  // namespace

TuckPhases find_tuck(const Trajectory<double>& trajectory, const BodyModel& model) {
  return find_tuck([&trajectory](int k, double t) { return trajectory.rotations[k].evaluate(t).q; },
                   trajectory.duration(), model);
}

TuckPhases find_tuck(const JointRotationAt& rotation_at, double duration, const BodyModel& model) {
  TuckPhases out;
  const std::vector<int> legs = leg_segments(model);
  if (legs.empty()) {
    out.reason = "The model has no hip or knee joints: there is no tuck to change.";
    return out;
  }
  const int count = std::max(201, static_cast<int>(std::ceil(duration / kBendStep)) + 1);
  out.times = uniform_times(duration, count);
  for (double t : out.times)
    out.bend_deg.push_back(bend_at(rotation_at, legs, t));
  const std::vector<double>& b = out.bend_deg;
  const std::size_t peak =
      static_cast<std::size_t>(std::max_element(b.begin(), b.end()) - b.begin());
  out.takeoff_bend_deg = b.front();
  out.peak_bend_deg = b[peak];
  out.peak_time_s = out.times[peak];
  out.landing_bend_deg = b.back();
  out.tuck_start_s = out.tucked_s = 0.0;
  out.open_start_s = out.opened_s = duration;
  const double rise = out.peak_bend_deg - out.takeoff_bend_deg;
  if (rise < kMinTuckBendDeg) {
    out.reason = format_number("The hips and knees bend at most %.0f°", rise) +
                 format_number(
                     " more than at take-off (a tuck or pike takes %.0f°): there is "
                     "no tuck to change.",
                     kMinTuckBendDeg);
    return out;
  }
  out.found = true;

  // Tucked: the first time the bend reaches 90 % of the rise; the tuck-in begins the last time
  // before that it is within 10 % of the rise above take-off (the first sample at least is).
  const double tucked_level = out.takeoff_bend_deg + (1.0 - kTuckPhaseLevel) * rise;
  const double start_level = out.takeoff_bend_deg + kTuckPhaseLevel * rise;
  std::size_t i = 0;
  while (b[i] < tucked_level)
    ++i;
  out.tucked_s = i == 0 ? out.times[0] : crossing(out.times, b, i - 1, i, tucked_level);
  std::size_t j = i;
  while (j > 0 && b[j] > start_level)
    --j;
  out.tuck_start_s =
      j + 1 < b.size() ? crossing(out.times, b, j, j + 1, start_level) : out.times[j];

  const double fall = out.peak_bend_deg - out.landing_bend_deg;
  out.opens = fall >= kMinTuckBendDeg;
  if (out.opens) {
    const double open_level = out.landing_bend_deg + (1.0 - kTuckPhaseLevel) * fall;
    const double opened_level = out.landing_bend_deg + kTuckPhaseLevel * fall;
    std::size_t k = b.size() - 1;
    while (b[k] < open_level)
      --k;
    out.open_start_s = k + 1 < b.size() ? crossing(out.times, b, k, k + 1, open_level) : duration;
    std::size_t m = k;
    while (m + 1 < b.size() && b[m] > opened_level)
      ++m;
    out.opened_s = m > 0 ? crossing(out.times, b, m - 1, m, opened_level) : out.times[m];
  }
  out.starts_at_takeoff = out.tuck_start_s < kMinPhaseS;
  out.opened_at_landing = !out.opens || duration - out.opened_s < kMinPhaseS;

  // How far each shift may go: the phases it stretches or compresses get at most
  // kMaxPhaseSpeedUp times faster; the hold between tuck and opening is shared by both shifts.
  const double squeeze = 1.0 - 1.0 / kMaxPhaseSpeedUp;
  const double before = out.starts_at_takeoff ? out.tucked_s : out.tuck_start_s;
  const double hold = (out.opens ? out.open_start_s : duration) - out.tucked_s;
  out.tuck_later_min_s = -squeeze * before;
  out.tuck_later_max_s = squeeze * hold * (out.opens ? 0.5 : 1.0);
  if (out.opens) {
    const double after = duration - (out.opened_at_landing ? out.open_start_s : out.opened_s);
    out.open_later_min_s = -squeeze * hold * 0.5;
    out.open_later_max_s = squeeze * after;
  }
  return out;
}

std::string what_if_change_words(const WhatIfChange& change) {
  if (change.unchanged()) return "as keyframed";
  std::vector<std::string> parts;
  if (change.tuck_later_s != 0.0)
    parts.push_back("tucking " + seconds_words(change.tuck_later_s) +
                    (change.tuck_later_s > 0 ? " later" : " earlier"));
  if (change.open_later_s != 0.0)
    parts.push_back("opening " + seconds_words(change.open_later_s) +
                    (change.open_later_s > 0 ? " later" : " earlier"));
  if (change.tuck_scale != 1.0) {
    const double percent = 100.0 * (change.tuck_scale - 1.0);
    parts.push_back(std::abs(percent) < 0.5
                        ? format_number("tuck %.1f %%", 100.0 * change.tuck_scale)
                        : format_number("tuck %.0f %%", std::abs(percent)) +
                              (percent > 0 ? " tighter" : " looser"));
  }
  std::string out;
  for (std::size_t i = 0; i < parts.size(); ++i)
    out += (i ? ", " : "") + parts[i];
  return out;
}

WhatIf::WhatIf(const Motion& motion, const BodyModel& model, const EvaluateOptions& options,
               double tolerance_deg)
    : motion_(motion), model_(model), options_(options), tolerance_deg_(tolerance_deg) {
  check_evaluate_options(options);
  if (!(tolerance_deg > 0.0 && std::isfinite(tolerance_deg)))
    throw std::invalid_argument("the landing tolerance must be a positive number of degrees");
  trajectory_ = motion_trajectory(motion, model, options.interpolation);
  takeoff_ = takeoff_angular_momentum(motion, model, trajectory_);
  tuck_ = find_tuck(trajectory_, model);
  unchanged_ =
      simulate_joint_motion(motion, model, trajectory_joints(trajectory_), takeoff_.value, options);
  unchanged_.angular_momentum_from_file = takeoff_.from_file;
  unchanged_.angular_momentum_spread = takeoff_.spread;
  std::vector<Eigen::Quaterniond> roots;
  for (const SampleRecord& s : unchanged_.samples)
    roots.push_back(s.segment_rotation.at(0));
  unchanged_landing_ = yeadon_summary(roots);
  target_ = yeadon_summary(trajectory_);
}

WhatIfResult WhatIf::fly(const WhatIfChange& change) const {
  check_change(tuck_, change);
  WhatIfResult out;
  out.change = change;
  out.change_words = what_if_change_words(change);
  if (change.unchanged()) {
    out.tuck = tuck_;
    out.flight = unchanged_;
    out.landing = unchanged_landing_;
  } else {
    const ChangedJoints joints(trajectory_, model_, tuck_, change);
    out.tuck = find_tuck([&joints](int k, double t) { return joints.at(k, t).q; },
                         joints.duration(), model_);
    out.flight =
        simulate_joint_motion(motion_, model_, joints.prescribed(), takeoff_.value, options_);
    out.flight.angular_momentum_from_file = takeoff_.from_file;
    out.flight.angular_momentum_spread = takeoff_.spread;
    std::vector<Eigen::Quaterniond> roots;
    for (const SampleRecord& s : out.flight.samples)
      roots.push_back(s.segment_rotation.at(0));
    out.landing = yeadon_summary(roots);
  }

  const double fallback_somersaults = unchanged_landing_.somersaults;
  out.somersault_over_deg =
      over_deg(out.landing.somersaults, target_.somersaults, fallback_somersaults);
  out.twist_over_deg = over_deg(out.landing.twists, target_.twists, unchanged_landing_.twists);
  out.somersault_vs_unchanged_deg =
      over_deg(out.landing.somersaults, unchanged_landing_.somersaults, target_.somersaults);
  out.twist_vs_unchanged_deg =
      over_deg(out.landing.twists, unchanged_landing_.twists, target_.twists);
  out.tolerance_deg = tolerance_deg_;
  out.within_tolerance = std::abs(out.somersault_over_deg) <= tolerance_deg_ &&
                         std::abs(out.twist_over_deg) <= tolerance_deg_;

  // The words: the twist only for a twisting motion, or when this flight twists after all.
  const bool twisting = std::abs(target_.twists) >= kNoTurn || std::abs(out.twist_over_deg) >= 1.0;
  const bool on_target = over_words(out.somersault_over_deg) == "on target" &&
                         (!twisting || over_words(out.twist_over_deg) == "on target");
  if (on_target)
    out.verdict = "you land on target";
  else if (twisting)
    out.verdict = "you land " + over_words(out.somersault_over_deg) + " in somersault, " +
                  over_words(out.twist_over_deg) + " in twist";
  else
    out.verdict = "you land " + over_words(out.somersault_over_deg);
  std::string counts = format_number("%.2f somersaults", std::abs(out.landing.somersaults));
  if (twisting) {
    counts += format_number(", %.2f twists", std::abs(out.landing.twists));
    // A twist the other way than the motion's is not "fewer twists".
    if (std::abs(target_.twists) >= kNoTurn && std::abs(out.landing.twists) >= 0.005 &&
        (out.landing.twists < 0) != (target_.twists < 0))
      counts += " the other way";
  }
  out.sentence = "Same take-off, " + out.change_words + ": " + counts + " — " + out.verdict +
                 (out.within_tolerance ? format_number(" (within %.0f°).", tolerance_deg_)
                                       : format_number(" (more than %.0f° off).", tolerance_deg_));
  return out;
}

WhatIfResult what_if(const Motion& motion, const BodyModel& model, const WhatIfChange& change,
                     const EvaluateOptions& options) {
  return WhatIf(motion, model, options).fly(change);
}

}  // namespace saltus
