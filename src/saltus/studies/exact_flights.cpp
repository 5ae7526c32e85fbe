#include "saltus/studies/exact_flights.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "saltus/base/constants.h"
#include "saltus/base/text_format.h"
#include "saltus/dynamics/free_flight.h"
#include "saltus/evaluation/yeadon_angles.h"
#include "saltus/math/quaternion.h"
#include "saltus/motion/interpolate.h"

namespace saltus {
namespace {

/// splitmix64: the same numbers from the same seed on every platform (the standard library's
/// distributions are implementation-defined).
class Random {
 public:
  explicit Random(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  double uniform(double a, double b) {
    return a + (b - a) * static_cast<double>(next() >> 11) * 0x1.0p-53;
  }
  int integer(int a, int b) { return a + static_cast<int>(next() % (b - a + 1)); }
  bool chance(double p) { return uniform(0.0, 1.0) < p; }

 private:
  std::uint64_t state_;
};

double two_decimals(double x) {
  return std::round(x * 100.0) / 100.0;
}

/// Joint angles in degrees (examples/README.md's signs: flexion of shoulders, elbows and hips is
/// negative about x, knee flexion positive; abduction about z, left +, right −).
struct Pose {
  double shoulder_l = 0, shoulder_r = 0, abduct_l = 0, abduct_r = 0, elbow_l = 0, elbow_r = 0;
  double hip = 0, knee = 0, thoracic = 0, lumbar = 0, ankle = 0;
};

/// Both arms drawn from the same ranges, each side on its own (real athletes are not symmetric).
void draw_arms(Random& r, Pose& p, double shoulder_lo, double shoulder_hi, double abduct_lo,
               double abduct_hi, double elbow_lo, double elbow_hi) {
  p.shoulder_l = r.uniform(shoulder_lo, shoulder_hi);
  p.shoulder_r = std::clamp(p.shoulder_l + r.uniform(-10, 10), -180.0, 0.0);
  p.abduct_l = r.uniform(abduct_lo, abduct_hi);
  p.abduct_r = r.uniform(abduct_lo, abduct_hi);
  p.elbow_l = r.uniform(elbow_lo, elbow_hi);
  p.elbow_r = r.uniform(elbow_lo, elbow_hi);
}

Pose takeoff_pose(Random& r) {
  Pose p;
  if (r.chance(0.7))
    draw_arms(r, p, -180, -140, 0, 15, -15, 0);  // arms up
  else
    draw_arms(r, p, -40, -10, 0, 20, -20, 0);  // arms low
  p.hip = r.uniform(-10, 5);
  p.knee = r.uniform(0, 10);
  p.thoracic = r.uniform(-5, 5);
  p.lumbar = r.uniform(-5, 5);
  p.ankle = r.uniform(-20, 5);
  return p;
}

Pose shape_pose(Random& r, FlightShape shape, bool twisting) {
  Pose p;
  switch (shape) {
    case FlightShape::kTucked:
      draw_arms(r, p, -70, -30, 5, 20, -100, -50);
      p.hip = r.uniform(-130, -105);
      p.knee = r.uniform(110, 140);
      p.thoracic = r.uniform(5, 20);
      p.lumbar = r.uniform(0, 10);
      break;
    case FlightShape::kPiked:
      draw_arms(r, p, -110, -40, 0, 15, -20, 0);
      p.hip = r.uniform(-130, -100);
      p.knee = r.uniform(0, 8);
      p.thoracic = r.uniform(10, 25);
      p.lumbar = r.uniform(0, 10);
      break;
    case FlightShape::kStraight:
      if (twisting)
        draw_arms(r, p, -30, -5, 0, 8, -40, 0);  // arms in, the twist goes faster
      else
        draw_arms(r, p, -180, -20, 5, 30, -30, 0);
      p.hip = r.uniform(-15, 5);
      p.knee = r.uniform(0, 10);
      p.thoracic = r.uniform(-10, 5);
      p.lumbar = r.uniform(-10, 0);
      break;
  }
  p.ankle = r.uniform(-30, 0);
  return p;
}

Pose landing_pose(Random& r) {
  Pose p;
  draw_arms(r, p, -180, -20, 0, 30, -30, 0);
  p.hip = r.uniform(-40, -5);
  p.knee = r.uniform(5, 30);
  p.thoracic = r.uniform(0, 15);
  p.lumbar = r.uniform(-5, 5);
  p.ankle = r.uniform(-10, 10);
  return p;
}

Keyframe pose_keyframe(const BodyModel& model, double time, const Pose& p) {
  Keyframe k;
  k.time = time;
  k.rotations.assign(model.size(), Eigen::Quaterniond::Identity());
  auto set = [&](const std::string& joint, double x, double z) {
    const int index = model.joint_index(joint);
    if (index < 0)
      throw std::invalid_argument("exact flights need a '" + joint + "' joint; model '" +
                                  model.name + "' has none");
    k.rotations[index] = quat_from_euler_deg({x, 0.0, z}, "XYZ");
  };
  set("thoracic", p.thoracic, 0);
  set("lumbar", p.lumbar, 0);
  set("shoulder_l", p.shoulder_l, p.abduct_l);
  set("shoulder_r", p.shoulder_r, -p.abduct_r);
  set("elbow_l", p.elbow_l, 0);
  set("elbow_r", p.elbow_r, 0);
  for (const char* side : {"_l", "_r"}) {
    set(std::string("hip") + side, p.hip, 0);
    set(std::string("knee") + side, p.knee, 0);
    set(std::string("ankle") + side, p.ankle, 0);
  }
  return k;
}

/// The motion the joints are splined through: the take-off pose at 0, `early` and `late` at
/// their times, the landing pose at `duration` (the root left at identity: only joints count).
Motion four_pose_source(const BodyModel& model, double duration, const Pose& takeoff,
                        double early_time, const Pose& early, double late_time, const Pose& late,
                        const Pose& landing) {
  Motion source;
  source.model = model.name;
  source.keyframes = {pose_keyframe(model, 0.0, takeoff), pose_keyframe(model, early_time, early),
                      pose_keyframe(model, late_time, late),
                      pose_keyframe(model, duration, landing)};
  return source;
}

const char* shape_name(FlightShape shape) {
  switch (shape) {
    case FlightShape::kTucked:
      return "tucked";
    case FlightShape::kPiked:
      return "piked";
    case FlightShape::kStraight:
      return "straight";
  }
  return "";
}

/// The root's accumulated turn (rad) between consecutive states.
std::vector<double> accumulated_turn(const std::vector<BodyState<double>>& states) {
  std::vector<double> out{0.0};
  for (std::size_t i = 1; i < states.size(); ++i)
    out.push_back(out.back() + states[i - 1].joints[0].q.angularDistance(states[i].joints[0].q));
  return out;
}

/// The joints of a C² spline through the poses of `source`, as the free flight moves them, and
/// the flight's breakpoints at the poses' times.
struct PosedJoints {
  Trajectory<double> joints;
  FreeFlightOptions flight_options;
  PosedJoints(const Motion& source, const BodyModel& model)
      : joints(interpolate_keyframes(source, model)) {
    for (const Keyframe& k : source.keyframes)
      flight_options.breakpoints.push_back(k.time);
  }
  JointMotion motion() const {
    return [this](double t, BodyState<double>& s) {
      for (int k = 1; k < joints.segment_count(); ++k) {
        const auto q = joints.rotations[k].evaluate(t);
        s.joints[k] = {q.q, q.omega, q.alpha};
      }
    };
  }
};

/// The flight's fine grid: 5 ms apart, both ends included.
std::vector<double> fine_times(double duration) {
  std::vector<double> fine;
  const int count = static_cast<int>(std::ceil(duration / 0.005));
  for (int i = 0; i <= count; ++i)
    fine.push_back(duration * i / count);
  return fine;
}

/// Yeadon's twists of a flown flight (revolutions).
double flown_twists(const std::vector<BodyState<double>>& flown) {
  std::vector<Eigen::Quaterniond> roots;
  for (const BodyState<double>& state : flown)
    roots.push_back(state.joints[0].q);
  return yeadon_summary(roots).twists;
}

/// Flies the joints from `initial`, records the root's turn in `f`, keyframes the flight at
/// times a user would type (two decimals, roughly even) and stores the exact motion. With
/// `key_count` 0 the count follows the flight: no more than 150° of root turn between neighbours
/// and at least 0.06 s apart where the time allows; otherwise exactly `key_count` keyframes,
/// however far the body turns between them.
void keyframe_flight(const BodyModel& model, Random& r, const JointMotion& joint_motion,
                     const FreeFlightOptions& flight_options, const FreeFlightInitialState& initial,
                     double duration, const std::vector<double>& fine, ExactFlight& f,
                     int key_count = 0) {
  const int fine_count = static_cast<int>(fine.size()) - 1;
  const std::vector<BodyState<double>> flown =
      simulate_free_flight(model, joint_motion, initial, fine, flight_options);
  const std::vector<double> turn = accumulated_turn(flown);
  f.root_turn_deg = turn.back() * kDegreesPerRadian;

  // Keyframe times as a user types them (two decimals, roughly even), with no more than 150° of
  // root turn between neighbours and at least 0.06 s apart where the time allows.
  const auto turn_at = [&](double t) {
    const double s = t / duration * fine_count;
    const int i = std::clamp(static_cast<int>(s), 0, fine_count - 1);
    return turn[i] + (s - i) * (turn[i + 1] - turn[i]);
  };
  const int fewest = std::max(5, static_cast<int>(std::ceil(f.root_turn_deg / 110.0)) + 1);
  const int most_keys = std::max(fewest, std::min(25, static_cast<int>(duration / 0.06) + 1));
  int count = key_count > 0 ? key_count : r.integer(fewest, most_keys);
  std::vector<double> times;
  for (;; ++count) {
    times.assign(1, 0.0);
    const double h = duration / (count - 1);
    for (int i = 1; i + 1 < count; ++i) {
      double t = two_decimals(i * h + r.uniform(-0.25, 0.25) * h);
      if (t <= times.back() + 0.015) t = two_decimals(i * h);
      times.push_back(t);
    }
    times.push_back(duration);
    bool fine_enough = true;
    for (std::size_t i = 0; i + 1 < times.size(); ++i)
      fine_enough = fine_enough && times[i + 1] > times[i] + 0.005 &&
                    (turn_at(times[i + 1]) - turn_at(times[i])) * kDegreesPerRadian <= 150.0;
    if (key_count > 0 || fine_enough || count >= 40) break;
  }

  const std::vector<BodyState<double>> at_keys =
      simulate_free_flight(model, joint_motion, initial, times, flight_options);
  f.motion.name = "exact flight " + std::to_string(f.seed);
  f.motion.model = model.name;
  f.motion.takeoff.com_position = initial.com_position;
  f.motion.takeoff.com_velocity = initial.com_velocity;
  f.motion.takeoff.angular_momentum = initial.angular_momentum;
  for (std::size_t i = 0; i < times.size(); ++i) {
    Keyframe k;
    k.time = times[i];
    for (const auto& joint : at_keys[i].joints)
      k.rotations.push_back(joint.q);
    f.motion.keyframes.push_back(std::move(k));
  }
}

/// Tilts `initial`'s angular momentum, about the somersault axis x, from x towards the upright
/// body's long axis y (a contact twist) by the angle that flies `wanted` twists: three passes of
/// twists ∝ sin(tilt), held within 5° and `most_deg`. Records the tilt in `f`.
void tilt_for_twists(const BodyModel& model, const JointMotion& joint_motion,
                     const FreeFlightOptions& flight_options, const std::vector<double>& fine,
                     double wanted, bool positive, double most_deg, FreeFlightInitialState& initial,
                     ExactFlight& f) {
  const double sign = positive ? 1.0 : -1.0;
  const double L = initial.angular_momentum.x();
  const auto tilted = [&](double deg) {
    const double a = deg / kDegreesPerRadian;
    return Eigen::Vector3d(L * std::cos(a), sign * std::abs(L) * std::sin(a), 0.0);
  };
  double deg = 15.0;
  for (int pass = 0; pass < 3; ++pass) {
    initial.angular_momentum = tilted(deg);
    const double got = std::abs(
        flown_twists(simulate_free_flight(model, joint_motion, initial, fine, flight_options)));
    const double scaled =
        std::asin(std::min(1.0, std::sin(deg / kDegreesPerRadian) * wanted / std::max(got, 1e-3)));
    deg = std::clamp(scaled * kDegreesPerRadian, 5.0, most_deg);
  }
  f.takeoff_tilt_deg = sign * deg;
  initial.angular_momentum = tilted(deg);
}

/// Scales the somersault momentum L = (±30, 0, 0) twice by the turn it gives, so the flight
/// turns `somersaults` (the turn is nearly proportional to L; the joints' movement adds a
/// little).
void size_somersault(const BodyModel& model, const JointMotion& joint_motion,
                     const FreeFlightOptions& flight_options, const std::vector<double>& fine,
                     double somersaults, FreeFlightInitialState& initial) {
  initial.angular_momentum = Eigen::Vector3d(somersaults < 0 ? -30.0 : 30.0, 0.0, 0.0);
  for (int pass = 0; pass < 2; ++pass) {
    const double turned =
        accumulated_turn(simulate_free_flight(model, joint_motion, initial, fine, flight_options))
            .back();
    initial.angular_momentum.x() *= std::abs(somersaults) * 2.0 * kPi / turned;
  }
}

}  // namespace

std::string ExactFlight::description() const {
  std::string out = "seed " + std::to_string(seed) + ": " + shape_name(shape);
  out += format_number(", %.2f somersaults ", std::abs(somersaults)) +
         (somersaults < 0 ? "backwards" : "forwards");
  if (twists > 0) out += format_number(", %.1f twists", twists);
  if (twist_source == "take-off")
    out += format_number(", twist from the take-off (momentum tilted %.0f deg)", takeoff_tilt_deg);
  else if (twist_source == "arm")
    out += ", twist from one arm";
  out += platform ? format_number(", platform %.0f m", drop_m) : std::string(", trampoline");
  out += format_number(", %.2f s", motion.flight_time());
  out += ", " + std::to_string(motion.keyframes.size()) + " keyframes";
  out += format_number(", root turns %.0f deg", root_turn_deg);
  return out;
}

ExactFlight make_exact_flight(const BodyModel& model, std::uint64_t seed) {
  Random r(seed);
  ExactFlight f;
  f.seed = seed;
  const double duration = two_decimals(r.uniform(0.4, 2.5));
  const int shape_draw = r.integer(0, 2);
  f.shape = static_cast<FlightShape>(shape_draw);
  // Somersaults in quarter turns up to what the shape can turn in this time.
  const double turns_per_second[] = {1.75, 1.3, 0.85};
  const double most = std::min(4.0, turns_per_second[shape_draw] * duration);
  const double direction = r.chance(0.5) ? -1.0 : 1.0;
  f.somersaults = direction * r.integer(0, static_cast<int>(std::floor(most * 4.0))) / 4.0;
  if (f.shape == FlightShape::kStraight && r.chance(0.6))
    f.twists =
        r.integer(1, static_cast<int>(std::floor(std::min(3.0, 2.0 * duration) * 2.0))) / 2.0;

  // Take-off: a trampoline (lands where it took off) or a platform (lands lower).
  const double g = kStandardGravity;
  Eigen::Vector3d velocity(r.uniform(-0.1, 0.1), g * duration / 2.0, r.uniform(-0.3, 0.3));
  Eigen::Vector3d position(0.0, r.uniform(1.0, 1.3), 0.0);
  if (duration >= 0.9 && r.chance(0.4)) {
    for (const double drop : {10.0, 5.0, 3.0, 1.0}) {
      const double up = (g * duration * duration / 2.0 - drop) / duration;
      if (up >= 0.5 && up <= 5.5) {
        f.platform = true;
        f.drop_m = drop;
        velocity.y() = up;
        velocity.z() = r.uniform(0.5, 1.5);
        position.y() = drop + 1.1;
        break;
      }
    }
  }

  // The joints move take-off -> shape -> shape -> landing on a C² spline through four poses.
  Motion source;
  source.model = model.name;
  source.keyframes = {
      pose_keyframe(model, 0.0, takeoff_pose(r)),
      pose_keyframe(model, duration * r.uniform(0.12, 0.3), shape_pose(r, f.shape, f.twists > 0)),
      pose_keyframe(model, duration * r.uniform(0.6, 0.8), shape_pose(r, f.shape, f.twists > 0)),
      pose_keyframe(model, duration, landing_pose(r))};
  const PosedJoints posed(source, model);
  const JointMotion joint_motion = posed.motion();
  const FreeFlightOptions& flight_options = posed.flight_options;

  FreeFlightInitialState initial;
  initial.com_position = position;
  initial.com_velocity = velocity;
  initial.root_orientation = Eigen::Quaterniond(
      Eigen::AngleAxisd(r.uniform(-15.0, 15.0) / kDegreesPerRadian, Eigen::Vector3d::UnitX()));
  const std::vector<double> fine = fine_times(duration);
  // Somersault: L about x scaled twice by the turn it gives (the turn is nearly proportional
  // to L; the joints' own movement adds a little).
  if (f.somersaults != 0.0) {
    initial.angular_momentum = Eigen::Vector3d(30.0 * direction, 0.0, 0.0);
    for (int pass = 0; pass < 2; ++pass) {
      const double turned =
          accumulated_turn(simulate_free_flight(model, joint_motion, initial, fine, flight_options))
              .back();
      initial.angular_momentum.x() *= std::abs(f.somersaults) * 2.0 * kPi / turned;
    }
  }
  // Twist: L along the upright body's long axis (y at take-off), sized for a straight body
  // with its arms in (about 1.2 kg·m² for 66 kg).
  if (f.twists > 0)
    initial.angular_momentum.y() = (r.chance(0.5) ? 1.0 : -1.0) * 2.0 * kPi * f.twists * 1.2 *
                                   model.total_mass() / 66.0 / duration;
  keyframe_flight(model, r, joint_motion, flight_options, initial, duration, fine, f);
  return f;
}

ExactFlight make_twisting_flight(const BodyModel& model, std::uint64_t seed) {
  Random r(seed ^ 0x7457495354ull);  // "tWIST": a stream apart from make_exact_flight's
  ExactFlight f;
  f.seed = seed;
  const double duration = two_decimals(r.uniform(1.0, 2.0));
  const bool from_takeoff = r.chance(0.5);
  // A piked body hardly twists, and a contact twist run through a pike can untwist: the twists
  // from the take-off are layouts, those from an arm layouts or pikes that open.
  f.shape = !from_takeoff && r.chance(0.5) ? FlightShape::kPiked : FlightShape::kStraight;
  f.twist_source = from_takeoff ? "take-off" : "arm";
  const double turns_per_second = f.shape == FlightShape::kStraight ? 0.85 : 1.3;
  const int quarters = std::max(4, static_cast<int>(std::floor(turns_per_second * duration * 4)));
  const double direction = r.chance(0.5) ? -1.0 : 1.0;
  f.somersaults = direction * r.integer(4, std::min(quarters, 8)) / 4.0;

  const double g = kStandardGravity;
  const Eigen::Vector3d velocity(r.uniform(-0.1, 0.1), g * duration / 2.0, r.uniform(-0.3, 0.3));
  const Eigen::Vector3d position(0.0, r.uniform(1.0, 1.3), 0.0);

  // Arms overhead at take-off; then the shape, with both arms in (twisting from the take-off)
  // or one arm brought to the side early while the other stays up (twisting from the air).
  Pose takeoff = takeoff_pose(r);
  draw_arms(r, takeoff, -180, -160, 0, 10, -10, 0);
  // A pike opens to a layout for the twist (a piked body hardly twists: its long-axis inertia).
  Pose early = shape_pose(r, f.shape, from_takeoff);
  Pose late = shape_pose(r, FlightShape::kStraight, from_takeoff);
  if (!from_takeoff) {
    const bool left_down = r.chance(0.5);
    for (Pose* p : {&early, &late}) {
      const double up = r.uniform(-178, -165), down = r.uniform(-25, -5);
      (left_down ? p->shoulder_l : p->shoulder_r) = down;
      (left_down ? p->shoulder_r : p->shoulder_l) = up;
      p->abduct_l = p->abduct_r = r.uniform(0, 6);
    }
  }
  // Drawn in this order (the stream is the family's).
  const double early_time = duration * r.uniform(0.12, 0.22);
  const double late_time = duration * r.uniform(0.6, 0.75);
  const Pose landing = landing_pose(r);
  const PosedJoints posed(
      four_pose_source(model, duration, takeoff, early_time, early, late_time, late, landing),
      model);
  const JointMotion joint_motion = posed.motion();
  const FreeFlightOptions& flight_options = posed.flight_options;
  FreeFlightInitialState initial;
  initial.com_position = position;
  initial.com_velocity = velocity;
  const std::vector<double> fine = fine_times(duration);
  // Somersault: L about x scaled twice by the turn it gives; then, twisting from the take-off,
  // tilted from the somersault axis towards the body's long axis (upright at take-off: y), so
  // that the long axis leans out of the plane the body somersaults in (a contact twist).
  size_somersault(model, joint_motion, flight_options, fine, f.somersaults, initial);
  if (from_takeoff) {
    // A twist count in halves, 1 to 3 as the time allows.
    const double wanted =
        r.integer(2, std::max(2, std::min(6, static_cast<int>(4 * duration) - 2))) / 2.0;
    tilt_for_twists(model, joint_motion, flight_options, fine, wanted, r.chance(0.5), 30.0, initial,
                    f);
  }
  keyframe_flight(model, r, joint_motion, flight_options, initial, duration, fine, f);
  f.flown_twists =
      flown_twists(simulate_free_flight(model, joint_motion, initial, fine, flight_options));
  f.twists = std::abs(f.flown_twists);
  f.motion.name = "twisting exact flight " + std::to_string(seed);
  return f;
}

ExactFlight make_hard_twisting_flight(const BodyModel& model, std::uint64_t seed) {
  Random r(seed ^ 0x4841524454ull);  // "HARDT": a stream apart from the other families'
  ExactFlight f;
  f.seed = seed;
  f.shape = FlightShape::kStraight;
  f.twist_source = "take-off";
  const double duration = two_decimals(r.uniform(1.5, 2.0));
  f.somersaults = r.chance(0.7) ? -1.0 : 1.0;   // mostly backwards, as the held-out flight
  const double wanted = r.integer(4, 6) / 2.0;  // 2, 2.5 or 3 twists
  const int key_count = r.integer(7, 11);

  const double g = kStandardGravity;
  const Eigen::Vector3d velocity(r.uniform(-0.1, 0.1), g * duration / 2.0, r.uniform(-0.3, 0.3));
  const Eigen::Vector3d position(0.0, r.uniform(1.0, 1.3), 0.0);

  // Both arms overhead at take-off, in by the first shape (the twist speeds up as they come
  // in), still in before the landing's opening.
  Pose takeoff = takeoff_pose(r);
  draw_arms(r, takeoff, -180, -160, 0, 10, -10, 0);
  const Pose early = shape_pose(r, FlightShape::kStraight, true);
  const Pose late = shape_pose(r, FlightShape::kStraight, true);
  const double early_time = duration * r.uniform(0.12, 0.2);
  const double late_time = duration * r.uniform(0.65, 0.8);
  const Pose landing = landing_pose(r);
  const PosedJoints posed(
      four_pose_source(model, duration, takeoff, early_time, early, late_time, late, landing),
      model);
  const JointMotion joint_motion = posed.motion();
  const FreeFlightOptions& flight_options = posed.flight_options;
  FreeFlightInitialState initial;
  initial.com_position = position;
  initial.com_velocity = velocity;
  const std::vector<double> fine = fine_times(duration);
  size_somersault(model, joint_motion, flight_options, fine, f.somersaults, initial);
  tilt_for_twists(model, joint_motion, flight_options, fine, wanted, r.chance(0.5), 40.0, initial,
                  f);
  keyframe_flight(model, r, joint_motion, flight_options, initial, duration, fine, f, key_count);
  f.flown_twists =
      flown_twists(simulate_free_flight(model, joint_motion, initial, fine, flight_options));
  f.twists = std::abs(f.flown_twists);
  f.motion.name = "hard twisting flight " + std::to_string(seed);
  return f;
}

Motion disturb_interior_times(const Motion& motion, double max_shift, std::uint64_t seed) {
  Random r(seed ^ 0x5DEECE66Dull);
  Motion out = motion;
  for (std::size_t i = 1; i + 1 < motion.keyframes.size(); ++i) {
    const double before = motion.keyframes[i].time - motion.keyframes[i - 1].time;
    const double after = motion.keyframes[i + 1].time - motion.keyframes[i].time;
    const double shift = std::clamp(r.uniform(-max_shift, max_shift), -0.4 * before, 0.4 * after);
    const double t = two_decimals(motion.keyframes[i].time + shift);
    // Rounding must not close a gap: then the time stays as it was.
    if (t > out.keyframes[i - 1].time + 0.005 && t < motion.keyframes[i + 1].time - 0.005)
      out.keyframes[i].time = t;
  }
  return out;
}

}  // namespace saltus
