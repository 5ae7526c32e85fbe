// saltus_make_example_motions: writes the bundled example motions M2-M7 of the paper (§3.4) and
// its 5 m dive (§6.2) as physically consistent keyframe files, the way M1 was made.
//
// The joint keyframes (every joint but the root) are chosen by hand to look like the real skill.
// The root keyframes are not: a free flight with those joint movements is simulated from an
// upright take-off, the take-off angular momentum (its somersault component and, for twisting
// skills, its vertical one: a take-off twist) is tuned by Newton's method until the flight ends
// with exactly the skill's somersaults and twists (upright on the bed, head down for the dive),
// and the root orientation is read off the flight at the keyframe times. Like motion capture,
// the keyframes then describe a flight that obeys Newton's laws; `saltus simulate` of a written
// file lands on its last keyframe.
//
// Usage: saltus_make_example_motions OUT_DIR [--verbose] [--only NAME]
//   OUT_DIR      folder for the *.motion.json files (examples/motions to regenerate the bundle)
//   --verbose    also print the root angles at every keyframe and the pose checks
//   --only NAME  write only the motions whose file name contains NAME (e.g. M5, dive)
//
// Angles: somersault, tilt and twist are Yeadon's (J. Biomech. 23, 1990): the athlete's
// orientation is Rx(somersault) Rz(tilt) Ry(twist) in the frame of the take-off heading, i.e.
// intrinsic Euler angles in the order "XZY" (x: left, y: up, z: facing; examples/README.md).
// Positive somersault = forward, positive twist = to the athlete's left.

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "saltus/base/constants.h"
#include "saltus/base/resources.h"
#include "saltus/body/body_model.h"
#include "saltus/dynamics/free_flight.h"
#include "saltus/dynamics/inverse_dynamics.h"
#include "saltus/evaluation/evaluate.h"
#include "saltus/evaluation/sampling.h"
#include "saltus/evaluation/simulate.h"
#include "saltus/formats/model_file.h"
#include "saltus/formats/motion_file.h"
#include "saltus/math/quaternion.h"
#include "saltus/motion/interpolate.h"
#include "saltus/motion/motion.h"

namespace {

namespace fs = std::filesystem;
using saltus::BodyModel;
using saltus::BodyState;
using saltus::Keyframe;
using saltus::Motion;
using saltus::SampleRecord;
using saltus::Segment;
using saltus::Trajectory;

constexpr double kRadToDeg = 180.0 / M_PI;
constexpr const char* kModelName = "zatsiorsky-66kg";
/// Output grid of the design flights: fine enough to unwrap the somersault and twist angles
/// (the fastest rotation, a tucked somersault, turns ~0.05 rad per step).
constexpr double kFlightGridStep = 0.005;
/// The Newton iteration on the take-off angular momentum stops when the landing angles are this
/// close to the skill's (degrees), well below what the files' 0.01° rounding can show.
constexpr double kLandingToleranceDeg = 1e-4;
/// examples/README.md "Keyframe spacing": the spline takes the shorter way between consecutive
/// keyframes, so no joint may turn by 180° or more between two of them. Keep a margin.
constexpr double kMaxKeyframeStepDeg = 170.0;

/// `value` rounded to a multiple of `unit` (0.01, 0.001, ...), computed as an integer divided by
/// 1/unit so that the file shows 1.35, not 1.3499999999999999.
double round_to(double value, double unit) {
  const double per_unit = std::round(1.0 / unit);
  const double r = std::round(value * per_unit) / per_unit;
  return r == 0.0 ? 0.0 : r;  // no "-0" in files
}

// ---------------------------------------------------------------------------------------------
// Poses: what a coach would write down. Sign conventions as in examples/README.md.

/// One arm: shoulder flexion (negative = forward and up, −180 = overhead), abduction (positive =
/// away from the body's midline, for either arm), elbow flexion (negative = bent).
struct Arm {
  double flexion = 0.0;
  double abduction = 0.0;
  double elbow = 0.0;
};

/// One leg: hip flexion (negative = pike or tuck), hip abduction (positive = apart), knee flexion
/// (positive = bent), ankle (positive = toes pointed).
struct Leg {
  double hip = 0.0;
  double hip_abduction = 0.0;
  double knee = 0.0;
  double ankle = 0.0;
};

/// All joint angles of one keyframe except the root's. Trunk: thoracic flexion (positive =
/// bending forward); lumbar as written to the file, negative = flexion (the pelvis hangs below the
/// abdomen like the thighs below the pelvis, so it flexes with the hips' sign).
struct Pose {
  double thoracic = 0.0;
  double lumbar = 0.0;
  Arm left_arm;
  Arm right_arm;
  Leg left_leg;
  Leg right_leg;
};

Arm arm(double flexion, double abduction, double elbow) {
  return {flexion, abduction, elbow};
}

Leg leg(double hip, double knee, double ankle, double hip_abduction = 0.0) {
  return {hip, hip_abduction, knee, ankle};
}

Pose symmetric(double thoracic, const Arm& arms, const Leg& legs, double lumbar = 0.0) {
  return {thoracic, lumbar, arms, arms, legs, legs};
}

Pose with_arms(Pose pose, const Arm& left, const Arm& right) {
  pose.left_arm = left;
  pose.right_arm = right;
  return pose;
}

// The building blocks of all skills. The tuck's arm angles put the hands on the shins (the pose
// report: hand to knee 0.18 m); its thighs then lie ~0.2 m in front of the thorax's axis, i.e.
// the knees touch the chest.
const Arm kArmsOverhead = arm(-170, 0, -5);
const Arm kArmsForward = arm(-60, 10, -15);       // landing: arms forward to balance
const Arm kArmsHugging = arm(-35, -15, -125);     // twisting: hands on the chest
const Arm kArmsGrabbingShins = arm(-5, 5, -110);  // tuck: elbows at the sides, hands on shins
const Leg kTuckedLegs = leg(-130, 140, 30);
const Leg kLandingLegs = leg(-12, 15, 5);

const Pose kTakeoff = symmetric(0, kArmsOverhead, leg(0, 0, 10));
const Pose kLanding = symmetric(5, kArmsForward, kLandingLegs);
const Pose kTuck = symmetric(35, kArmsGrabbingShins, kTuckedLegs, -10);
const Pose kTwistingLayout = symmetric(0, kArmsHugging, leg(0, 0, 15));

/// Keyframe rotation of one joint as the intrinsic XYZ Euler angles written to the file. The
/// right side mirrors the left: flexion is the same, abduction (about z) changes sign.
struct JointAngles {
  const char* joint;
  Eigen::Vector3d euler_deg;
};

std::vector<JointAngles> joint_angles(const Pose& p) {
  const auto side = [](double sign, const Arm& a) {
    return Eigen::Vector3d(a.flexion, 0.0, sign * a.abduction);
  };
  const auto hip = [](double sign, const Leg& l) {
    return Eigen::Vector3d(l.hip, 0.0, sign * l.hip_abduction);
  };
  const auto x = [](double angle) { return Eigen::Vector3d(angle, 0.0, 0.0); };
  return {{"lumbar", x(p.lumbar)},
          {"thoracic", x(p.thoracic)},
          {"shoulder_l", side(1, p.left_arm)},
          {"elbow_l", x(p.left_arm.elbow)},
          {"shoulder_r", side(-1, p.right_arm)},
          {"elbow_r", x(p.right_arm.elbow)},
          {"hip_l", hip(1, p.left_leg)},
          {"knee_l", x(p.left_leg.knee)},
          {"ankle_l", x(p.left_leg.ankle)},
          {"hip_r", hip(-1, p.right_leg)},
          {"knee_r", x(p.right_leg.knee)},
          {"ankle_r", x(p.right_leg.ankle)}};
}

// ---------------------------------------------------------------------------------------------
// Skills.

struct KeyframeDesign {
  double time;  ///< s
  Pose pose;
};

struct MotionDesign {
  std::string file;
  std::string name;
  std::string summary;       ///< what a coach sees (first sentences of the description)
  std::string twist_source;  ///< where the twist comes from ("" for untwisted skills)
  Eigen::Vector3d com_position = Eigen::Vector3d(0, 1, 0);         ///< m (paper §3.4)
  Eigen::Vector3d com_velocity = Eigen::Vector3d(0.15, 10, 0.15);  ///< m/s
  /// Rotation of the athlete about the vertical at take-off, degrees (0: facing +z).
  double heading_deg = 0.0;
  std::vector<KeyframeDesign> keyframes;
  double somersaults = 0.0;  ///< at landing, revolutions (+ forward)
  double twists = 0.0;       ///< at landing, revolutions (+ to the left)
  /// Take-off angular momentum in the athlete's take-off frame (x left, y up, z facing),
  /// kg·m²/s: the starting guess, and the final value of the components that are not tuned.
  Eigen::Vector3d angular_momentum_guess = Eigen::Vector3d::Zero();
  /// Untwisted skills tune the somersault component x of the take-off angular momentum alone
  /// (their flights neither tilt nor twist); twisting skills tune x and the twist component y
  /// so that the landing has exactly the skill's somersaults and twists. The tilt left at
  /// landing is reported: the tilt of a take-off twist dies out as the body comes round to
  /// upright again (0.6-2.3° left after whole somersaults here), but not after the dive's one and
  /// a half (examples/README.md).
  bool twisting() const { return twists != 0.0 || aerial_twist; }
  /// The twist comes from the joint movements alone (an aerial twist): the take-off angular
  /// momentum is tuned about the somersault axis only, and `twists` is not a target but the
  /// nearest half twist of what the flight gives (the file states the flown value).
  bool aerial_twist = false;
  /// The last keyframe's root orientation is designed, not read off the flight: the flight's
  /// somersault and twist with its tilt removed, i.e. exactly vertical, head down (the dive's
  /// entry, paper §6.2). The free flight then misses it by that tilt; closing the gap is the
  /// optimiser's job, as in the paper's design study.
  bool designed_vertical_entry = false;
};

// ---------------------------------------------------------------------------------------------
// Flights.

Eigen::Quaterniond heading_rotation(double heading_deg) {
  return Eigen::Quaterniond(Eigen::AngleAxisd(heading_deg / kRadToDeg, Eigen::Vector3d::UnitY()));
}

/// Yeadon's angles (somersault, tilt, twist) in degrees of a rotation R = Rx(a) Rz(b) Ry(c),
/// each of a and c taken within 180° of the previous value so that a sequence unwraps.
Eigen::Vector3d xzy_angles_deg(const Eigen::Quaterniond& q, const Eigen::Vector3d& previous) {
  const Eigen::Matrix3d m = q.toRotationMatrix();
  const double a = std::atan2(m(2, 1), m(1, 1)) * kRadToDeg;
  const double b = std::asin(std::clamp(-m(0, 1), -1.0, 1.0)) * kRadToDeg;
  const double c = std::atan2(m(0, 2), m(0, 0)) * kRadToDeg;
  const auto near = [](double angle, double reference) {
    return angle + 360.0 * std::round((reference - angle) / 360.0);
  };
  return {near(a, previous.x()), b, near(c, previous.z())};
}

/// A free flight of a design: its joint movements and a take-off angular momentum.
struct Flight {
  std::vector<double> times;
  std::vector<BodyState<double>> states;
  std::vector<Eigen::Vector3d> athlete_angles;  ///< somersault, tilt, twist, take-off frame
  std::vector<Eigen::Vector3d> world_angles;    ///< the same decomposition of world_from_root
  std::vector<int> keyframe_samples;            ///< index of each keyframe time in `times`
};

/// The motion with the design's joint keyframes; root keyframes are placeholders (the heading)
/// until the flight provides them.
Motion design_motion(const MotionDesign& design, const BodyModel& model) {
  Motion motion;
  motion.name = design.name;
  motion.model = kModelName;
  motion.takeoff.com_position = design.com_position;
  motion.takeoff.com_velocity = design.com_velocity;
  for (const KeyframeDesign& k : design.keyframes) {
    Keyframe keyframe;
    keyframe.time = k.time;
    keyframe.rotations.assign(model.size(), heading_rotation(design.heading_deg));
    for (const JointAngles& j : joint_angles(k.pose))
      keyframe.rotations[model.joint_index(j.joint)] =
          saltus::quat_from_euler_deg(j.euler_deg, "XYZ");
    motion.keyframes.push_back(keyframe);
  }
  return motion;
}

/// Simulates the free flight exactly as `saltus simulate` does (joint splines fitted through the
/// keyframes, root left to the dynamics) on a fine grid that contains every keyframe time.
/// @param angular_momentum_athlete  take-off angular momentum in the athlete's take-off frame
Flight simulate(const MotionDesign& design, const BodyModel& model,
                const Eigen::Vector3d& angular_momentum_athlete) {
  const Motion motion = design_motion(design, model);
  const Trajectory<double> trajectory = saltus::interpolate_keyframes(motion, model);
  const double flight_time = design.keyframes.back().time;
  Flight flight;
  const int steps = static_cast<int>(std::ceil(flight_time / kFlightGridStep));
  for (int i = 0; i <= steps; ++i)
    flight.times.push_back(flight_time * i / steps);
  for (const KeyframeDesign& k : design.keyframes)
    flight.times.push_back(k.time);
  std::sort(flight.times.begin(), flight.times.end());
  flight.times.erase(std::unique(flight.times.begin(), flight.times.end(),
                                 [](double a, double b) { return std::abs(a - b) < 1e-9; }),
                     flight.times.end());
  for (const KeyframeDesign& k : design.keyframes) {
    const auto at = std::min_element(
        flight.times.begin(), flight.times.end(),
        [&](double a, double b) { return std::abs(a - k.time) < std::abs(b - k.time); });
    *at = k.time;
    flight.keyframe_samples.push_back(static_cast<int>(at - flight.times.begin()));
  }

  const Eigen::Quaterniond heading = heading_rotation(design.heading_deg);
  saltus::FreeFlightInitialState initial;
  initial.com_position = design.com_position;
  initial.com_velocity = design.com_velocity;
  initial.root_orientation = heading;
  initial.angular_momentum = heading * angular_momentum_athlete;
  const saltus::JointMotion joints = [&trajectory](double t, BodyState<double>& state) {
    for (int k = 1; k < trajectory.segment_count(); ++k) {
      const saltus::QuaternionSample<double> s = trajectory.rotations[k].evaluate(t);
      state.joints[k].q = s.q;
      state.joints[k].omega = s.omega;
      state.joints[k].alpha = s.alpha;
    }
  };
  flight.states = saltus::simulate_free_flight(model, joints, initial, flight.times);

  Eigen::Vector3d athlete = Eigen::Vector3d::Zero();
  Eigen::Vector3d world(0.0, 0.0, design.heading_deg);
  for (const BodyState<double>& s : flight.states) {
    athlete = xzy_angles_deg(heading.conjugate() * s.joints[0].q, athlete);
    world = xzy_angles_deg(s.joints[0].q, world);
    flight.athlete_angles.push_back(athlete);
    flight.world_angles.push_back(world);
  }
  return flight;
}

/// Landing angles minus the skill's: somersault, tilt and twist errors in degrees.
Eigen::Vector3d landing_error(const MotionDesign& design, const Flight& flight) {
  return flight.athlete_angles.back() -
         Eigen::Vector3d(360.0 * design.somersaults, 0.0, 360.0 * design.twists);
}

/// Newton's method (finite-difference Jacobian) on the take-off angular momentum, athlete frame:
/// untwisted skills solve for the somersault with x, twisting skills for the somersault and the
/// twist with x and y. The guess fixes which solution is found (how many twists).
Eigen::Vector3d tune_angular_momentum(const MotionDesign& design, const BodyModel& model) {
  constexpr double kStep = 0.01;  // kg·m²/s, finite-difference step
  // Steps are capped: a long one can jump to a flight with a different number of twists.
  constexpr double kMaxStep = 2.0;
  constexpr int kMaxIterations = 40;
  const int unknowns = design.twisting() && !design.aerial_twist ? 2 : 1;
  const auto residual = [&](const Eigen::Vector3d& h) {
    const Eigen::Vector3d e = landing_error(design, simulate(design, model, h));
    return unknowns == 1 ? Eigen::VectorXd(e.head<1>())
                         : Eigen::VectorXd(Eigen::Vector2d(e.x(), e.z()));
  };
  Eigen::Vector3d h = design.angular_momentum_guess;
  for (int iteration = 0; iteration < kMaxIterations; ++iteration) {
    const Eigen::VectorXd error = residual(h);
    if (error.norm() < kLandingToleranceDeg) return h;
    Eigen::MatrixXd jacobian(unknowns, unknowns);
    for (int u = 0; u < unknowns; ++u) {
      Eigen::Vector3d probe = h;
      probe[u] += kStep;
      jacobian.col(u) = (residual(probe) - error) / kStep;
    }
    Eigen::VectorXd step = jacobian.fullPivLu().solve(-error);
    step /= std::max(1.0, step.cwiseAbs().maxCoeff() / kMaxStep);
    h.head(unknowns) += step;
  }
  throw std::runtime_error(design.name + ": the take-off angular momentum did not converge");
}

// ---------------------------------------------------------------------------------------------
// Checks and output.

/// The largest rotation of any joint (root included) between consecutive keyframes, degrees.
double max_keyframe_step_deg(const Motion& motion, const BodyModel& model, std::string& where) {
  double worst = 0.0;
  for (std::size_t k = 1; k < motion.keyframes.size(); ++k) {
    for (int j = 0; j < model.size(); ++j) {
      const double angle = saltus::rotation_angle_between(motion.keyframes[k - 1].rotations[j],
                                                          motion.keyframes[k].rotations[j]) *
                           kRadToDeg;
      if (angle > worst) {
        worst = angle;
        where = model.segments[j].joint + " between keyframes " + std::to_string(k - 1) + " and " +
                std::to_string(k);
      }
    }
  }
  return worst;
}

/// A point at the far end of a segment's drawn shape, world frame.
Eigen::Vector3d segment_end(const BodyModel& model, const SampleRecord& record,
                            const std::string& segment) {
  const int i = model.segment_index(segment);
  return record.segment_position[i] +
         record.segment_rotation[i] * Eigen::Vector3d(0.0, model.segments[i].shape.length, 0.0);
}

/// Whole-body inertia about the CoM in the root (abdomen) frame, kg·m²: the somersault (x) and
/// twist (y) moments show how a pose speeds or slows the rotations.
Eigen::Matrix3d inertia_in_root_frame(const BodyModel& model, const SampleRecord& r) {
  Eigen::Matrix3d total = Eigen::Matrix3d::Zero();
  const Eigen::Matrix3d root_from_world = r.segment_rotation[0].conjugate().toRotationMatrix();
  for (int i = 0; i < model.size(); ++i) {
    const Segment& s = model.segments[i];
    const Eigen::Matrix3d rot = root_from_world * r.segment_rotation[i].toRotationMatrix();
    const Eigen::Vector3d c =
        root_from_world * (r.segment_position[i] + r.segment_rotation[i] * s.com - r.com);
    total += rot * s.inertia * rot.transpose() +
             s.mass * (c.squaredNorm() * Eigen::Matrix3d::Identity() - c * c.transpose());
  }
  return total;
}

/// Pose checks that a picture would show, in the body's own terms: the head (top of the thorax)
/// above the feet at take-off and landing, the hands near the shins in a tuck, etc.
std::string pose_report(const BodyModel& model, const SampleRecord& r) {
  const Eigen::Vector3d head = segment_end(model, r, "thorax");
  const Eigen::Vector3d feet =
      0.5 * (segment_end(model, r, "foot_l") + segment_end(model, r, "foot_r"));
  const Eigen::Vector3d hand_l = segment_end(model, r, "forearm_l");
  const Eigen::Vector3d knee_l = r.segment_position[model.segment_index("shank_l")];
  const Eigen::Vector3d chest =
      r.segment_position[model.segment_index("thorax")] +
      r.segment_rotation[model.segment_index("thorax")] * Eigen::Vector3d(0.0, 0.25, 0.0);
  const Eigen::Vector3d axis = (head - feet).normalized();
  const Eigen::Matrix3d inertia = inertia_in_root_frame(model, r);
  std::ostringstream out;
  out.precision(2);
  out << std::fixed << "head-feet axis (" << axis.x() << ", " << axis.y() << ", " << axis.z()
      << "), head-feet " << (head - feet).norm() << " m, hand_l-knee " << (hand_l - knee_l).norm()
      << " m, knee-chest " << (knee_l - chest).norm() << " m, I_x " << inertia(0, 0) << " I_y "
      << inertia(1, 1) << " kg m^2";
  return out.str();
}

nlohmann::ordered_json vector_json(const Eigen::Vector3d& v) {
  return nlohmann::ordered_json::array({v.x(), v.y(), v.z()});
}

nlohmann::ordered_json euler_json(const Eigen::Vector3d& angles, const char* order) {
  nlohmann::ordered_json out;
  out["euler_deg"] = vector_json(angles);
  out["order"] = order;
  return out;
}

std::string format(double value, int decimals) {
  std::ostringstream out;
  out.precision(decimals);
  out << std::fixed << value;
  std::string s = out.str();
  return s == "-0" || s.find_first_not_of("-0.") == std::string::npos ? std::string("0") : s;
}

/// What one motion came out as (printed, and used in the file's description).
struct Outcome {
  Eigen::Vector3d angular_momentum_world = Eigen::Vector3d::Zero();
  Eigen::Vector3d landing_angles = Eigen::Vector3d::Zero();  ///< somersault, tilt, twist, deg
  double max_tilt_deg = 0.0;
  /// Twisting skills: the angle between the take-off angular momentum and the somersault axis
  /// (the take-off twist), and the twists that the joint movements alone give when the same
  /// somersault momentum has no twist component (the aerial twist).
  double momentum_tilt_deg = 0.0;
  double aerial_twists = 0.0;
};

Outcome analyse(const MotionDesign& design, const BodyModel& model, const Eigen::Vector3d& h,
                const Flight& flight) {
  Outcome o;
  o.angular_momentum_world = heading_rotation(design.heading_deg) * h;
  o.landing_angles = flight.athlete_angles.back();
  for (const Eigen::Vector3d& a : flight.athlete_angles)
    o.max_tilt_deg = std::max(o.max_tilt_deg, std::abs(a.y()));
  if (design.aerial_twist) {
    o.aerial_twists = o.landing_angles.z() / 360.0;
  } else if (design.twisting()) {
    o.momentum_tilt_deg = std::atan2(h.y(), std::abs(h.x())) * kRadToDeg;
    o.aerial_twists =
        simulate(design, model, Eigen::Vector3d(h.x(), 0.0, 0.0)).athlete_angles.back().z() / 360.0;
  } else if (o.max_tilt_deg > 1e-6 || std::abs(o.landing_angles.z()) > 1e-6) {
    throw std::logic_error(design.name + ": an untwisted skill must not tilt or twist");
  }
  return o;
}

/// The file's description: the summary, how the root keyframes were made, and the numbers.
std::string describe(const MotionDesign& design, const std::vector<Eigen::Vector3d>& root,
                     const Outcome& outcome) {
  const bool twisting = design.twisting();
  const Eigen::Vector3d& h = outcome.angular_momentum_world;
  std::ostringstream out;
  out << design.summary << " " << design.keyframes.size()
      << " keyframes. The root keyframes are not guessed: they were read off a free-flight "
         "simulation of these joint movements (tools/make_example_motions.cpp) with take-off "
         "angular momentum ("
      << format(h.x(), 2) << ", " << format(h.y(), 2) << ", " << format(h.z(), 2)
      << ") kg m^2/s (takeoff.angular_momentum), tuned so that the flight lands with exactly "
      << format(std::abs(design.somersaults), 1) << (design.somersaults < 0 ? " backward" : "")
      << " somersaults";
  if (design.aerial_twist) {
    out << "; the twist, " << format(outcome.aerial_twists, 2)
        << " twists, comes from the joint movements alone (tilt left at the end of the flight "
        << format(outcome.landing_angles.y(), 1) << " deg)";
  } else if (twisting) {
    out << " and " << format(design.twists, 1) << " twists (tilt left at the end of the flight "
        << format(outcome.landing_angles.y(), 1) << " deg)";
  }
  out << ". Root "
      << (twisting ? "orientation as XZY Euler angles (somersault about x, tilt, "
                     "twist about the body's long axis)"
                   : "somersault angles")
      << " at the keyframes:";
  for (std::size_t k = 0; k < root.size(); ++k) {
    out << (k == 0 ? " " : "; ");
    if (twisting) {
      out << "(" << format(root[k].x(), 1) << ", " << format(root[k].y(), 1) << ", "
          << format(root[k].z(), 1) << ")";
    } else {
      out << format(root[k].x(), 1);
    }
  }
  out << " deg.";
  if (design.designed_vertical_entry) {
    out << " Except the last: the entry is designed exactly vertical (the flight's tilt of "
        << format(outcome.landing_angles.y(), 1)
        << " deg removed), so the free flight misses it by that much and the optimiser has to "
           "reach it (paper section 6.2).";
  }
  if (design.aerial_twist) {
    out << " " << design.twist_source
        << " The take-off angular momentum lies along the somersault axis (no take-off twist).";
  } else if (twisting) {
    out << " " << design.twist_source << " The take-off angular momentum is tilted "
        << format(outcome.momentum_tilt_deg, 1)
        << " deg from the somersault axis towards the vertical (the take-off twist); with it "
           "horizontal the same joint movements give "
        << format(outcome.aerial_twists, 2) << " twists (the aerial share).";
  }
  return out.str();
}

/// Writes the motion file: joint keyframes as designed (XYZ Euler, degrees), root keyframes from
/// the flight (XYZ somersault angle for untwisted skills, XZY somersault-tilt-twist otherwise),
/// rounded to 0.01°.
void write_motion(const MotionDesign& design, const Flight& flight, const Outcome& outcome,
                  const fs::path& path) {
  const Eigen::Vector3d& h_world = outcome.angular_momentum_world;
  const bool twisting = design.twisting();
  const std::vector<KeyframeDesign>& keyframes = design.keyframes;
  std::vector<Eigen::Vector3d> root;
  for (const int sample : flight.keyframe_samples) {
    const Eigen::Vector3d& a = flight.world_angles[sample];
    root.emplace_back(round_to(a.x(), 0.01), round_to(a.y(), 0.01), round_to(a.z(), 0.01));
  }
  // XZY angles (somersault, tilt, twist): with the tilt at 0 the long axis lies in the
  // somersault plane, and at the dive's 1.5 somersaults it points straight down.
  if (design.designed_vertical_entry) root.back().y() = 0.0;
  nlohmann::ordered_json out;
  out["format"] = "saltus-motion/1";
  out["name"] = design.name;
  out["description"] = describe(design, root, outcome);
  out["model"] = kModelName;
  out["takeoff"]["com_position"] = vector_json(design.com_position);
  out["takeoff"]["com_velocity"] = vector_json(design.com_velocity);
  out["takeoff"]["angular_momentum"] = vector_json(Eigen::Vector3d(
      round_to(h_world.x(), 1e-4), round_to(h_world.y(), 1e-4), round_to(h_world.z(), 1e-4)));
  out["tolerances"]["translation_m"] = 0.25;
  out["tolerances"]["quaternion"] = 0.05;
  out["keyframes"] = nlohmann::ordered_json::array();
  for (std::size_t k = 0; k < keyframes.size(); ++k) {
    nlohmann::ordered_json keyframe;
    keyframe["time"] = round_to(keyframes[k].time, 1e-6);
    nlohmann::ordered_json rotations;
    if (twisting) {
      rotations["root"] = euler_json(root[k], "XZY");
    } else {
      rotations["root"] = euler_json(Eigen::Vector3d(root[k].x(), 0.0, 0.0), "XYZ");
    }
    for (const JointAngles& j : joint_angles(keyframes[k].pose)) {
      const Eigen::Vector3d& e = j.euler_deg;
      rotations[j.joint] = euler_json(
          Eigen::Vector3d(round_to(e.x(), 1e-3), round_to(e.y(), 1e-3), round_to(e.z(), 1e-3)),
          "XYZ");
    }
    keyframe["rotations"] = rotations;
    out["keyframes"].push_back(keyframe);
  }
  std::ofstream file(path);
  if (!file) throw std::runtime_error("cannot write " + path.string());
  file << out.dump(2) << "\n";
}

// ---------------------------------------------------------------------------------------------
// The skills.

/// Distance (m) from the whole-body CoM to the ends of the forearms (the model has no hands) in a
/// pose held with the arms overhead: how high the CoM is when the hands touch the water in a
/// vertical, head-first entry.
double hands_below_com(const BodyModel& model, const Pose& pose) {
  BodyState<double> state(model.size());
  for (const JointAngles& j : joint_angles(pose))
    state.joints[model.joint_index(j.joint)].q = saltus::quat_from_euler_deg(j.euler_deg, "XYZ");
  const SampleRecord r = saltus::evaluate_states(model, {0.0}, {state}).front();
  const Eigen::Vector3d hands =
      0.5 * (segment_end(model, r, "forearm_l") + segment_end(model, r, "forearm_r"));
  return hands.y() - r.com.y();
}

std::vector<MotionDesign> designs(const BodyModel& model) {
  std::vector<MotionDesign> out;
  {
    MotionDesign m;
    m.file = "M2-tucked-back-somersault.motion.json";
    m.name = "M2 tucked back somersault";
    m.summary =
        "Tucked back somersault on the trampoline: the athlete leaves the bed straight with the "
        "arms overhead and rises while the backward rotation starts, brings the arms forward and "
        "down and pulls the knees to the chest, holds a tight tuck with the hands on the shins "
        "(hips -130 deg, knees 140 deg, trunk flexed) through the top of the flight, opens with "
        "the body still turning and lands upright with the arms forward. One backward turn, "
        "most of it in the tuck.";
    m.keyframes = {{0.0, kTakeoff},
                   {0.30, symmetric(3, arm(-155, 3, -8), leg(-20, 20, 15))},
                   {0.65, symmetric(25, arm(-70, 5, -70), leg(-105, 115, 30), -5)},
                   {1.00, kTuck},
                   {1.35, kTuck},
                   {1.75, symmetric(8, arm(-70, 10, -20), leg(-30, 30, 15))},
                   {2.04, kLanding}};
    m.somersaults = -1.0;
    m.angular_momentum_guess = Eigen::Vector3d(-15, 0, 0);
    out.push_back(m);
  }
  {
    MotionDesign m;
    m.file = "M3-tucked-double-back.motion.json";
    m.name = "M3 tucked double back somersault";
    m.summary =
        "Tucked double back somersault on the trampoline: take-off with the arms overhead, a "
        "tight tuck formed within a quarter of a second and held through two fast backward "
        "turns (up to ~9 rad/s), opened in the last 0.3 s to land upright with the arms "
        "forward. Keyframes every 0.25-0.3 s in the tuck keep the root's turn between "
        "consecutive keyframes below 150 deg.";
    m.keyframes = {{0.0, kTakeoff},
                   {0.25, symmetric(20, arm(-60, 5, -90), leg(-95, 100, 25), -5)},
                   {0.50, kTuck},
                   {0.78, kTuck},
                   {1.06, kTuck},
                   {1.34, kTuck},
                   {1.75, symmetric(10, arm(-25, 10, -70), leg(-50, 55, 20))},
                   {2.04, kLanding}};
    m.somersaults = -2.0;
    m.angular_momentum_guess = Eigen::Vector3d(-30, 0, 0);
    out.push_back(m);
  }
  {
    MotionDesign m;
    m.file = "M4-front-somersault-half-twist.motion.json";
    m.name = "M4 front somersault with half twist (barani)";
    m.summary =
        "Barani (front somersault with a half twist) on the trampoline, straight: take-off with "
        "the arms overhead, the arms spread wide to the sides (a T) while the body rotates "
        "forwards with a slight pike, so that hardly any twist shows in the first half; the "
        "arms are drawn in to the chest from 0.7 s and the half twist happens in the second "
        "half of the somersault, as a coach expects of a barani; the arms open to slow it and "
        "the athlete lands upright facing the other way with the arms forward.";
    m.twist_source =
        "Twist source: a small take-off twist. Spreading the arms raises the moment of inertia "
        "about the long axis from 0.85 to 2.35 kg m^2 and keeps the twist slow; pulling them in "
        "(0.89 kg m^2) makes it fast.";
    m.keyframes = {{0.0, kTakeoff},
                   {0.20, symmetric(5, arm(-90, 50, -10), leg(-15, 0, 15))},
                   {0.45, symmetric(10, arm(-10, 90, -5), leg(-20, 0, 15))},
                   {0.70, symmetric(10, arm(-10, 90, -5), leg(-20, 0, 15))},
                   {0.95, symmetric(5, arm(-25, 45, -80), leg(-10, 0, 15))},
                   {1.20, kTwistingLayout},
                   {1.45, kTwistingLayout},
                   {1.70, symmetric(5, arm(-50, 60, -20), leg(-15, 5, 10))},
                   {2.04, kLanding}};
    m.somersaults = 1.0;
    m.twists = 0.5;
    m.angular_momentum_guess = Eigen::Vector3d(32, 2, 0);
    out.push_back(m);
  }
  {
    MotionDesign m;
    m.file = "M5-front-somersault-one-and-a-half-twists.motion.json";
    m.name = "M5 front somersault with one and a half twists (rudi)";
    m.summary =
        "Rudolph (rudi: front somersault with one and a half twists) on the trampoline, "
        "straight: take-off with the arms overhead and a slight pike to start the forward "
        "rotation, the right arm dropped sideways while the left comes down in front, both arms "
        "wrapped to the chest for the twist (0.55-1.15 s), then opened wide with a slight pike "
        "to slow the twist; landing upright facing backwards with the arms forward.";
    m.twist_source =
        "Twist source: mainly a take-off twist; the early sideways drop of the right arm adds a "
        "little aerial twist.";
    m.keyframes = {{0.0, kTakeoff},
                   {0.20, symmetric(5, kArmsOverhead, leg(-15, 0, 15))},
                   {0.40, with_arms(symmetric(0, kArmsOverhead, leg(-5, 0, 15)), arm(-120, 0, -10),
                                    arm(-90, 90, -10))},
                   {0.55, kTwistingLayout},
                   {0.70, kTwistingLayout},
                   {0.85, kTwistingLayout},
                   {1.00, kTwistingLayout},
                   {1.15, kTwistingLayout},
                   {1.32, symmetric(0, arm(-40, 60, -20), leg(-10, 0, 15))},
                   {1.62, symmetric(5, arm(-60, 40, -15), leg(-25, 5, 15))},
                   {2.04, kLanding}};
    m.somersaults = 1.0;
    m.twists = 1.5;
    m.angular_momentum_guess = Eigen::Vector3d(31.8, 7.6, 0);
    out.push_back(m);
  }
  {
    MotionDesign m;
    m.file = "M6-half-twist-into-one-and-a-half-front.motion.json";
    m.name = "M6 half twist into one and a half front somersaults (Arabian double)";
    m.summary =
        "Arabian double on the trampoline: a half twist into one and a half front somersaults, "
        "tucked. The athlete leaves the bed rotating backwards with the arms overhead, pulls "
        "the arms to the chest and twists while still straight, so that the rest of the "
        "rotation is a front somersault as the athlete sees it; tucks tightly (0.6-1.2 s) for "
        "one and a half turns, opens and lands upright facing the other way. Upright landing "
        "after a half twist needs a whole number of turns relative to the bed: the world "
        "rotation is two backward turns (the half turn of the twist phase plus the one and a "
        "half front somersaults), so the root angle grows negative about x.";
    m.twist_source =
        "Twist source: a take-off twist, fast while the body is straight with the arms in; the "
        "tuck hides the rest of it (the tucked body turns about the slightly tilted angular "
        "momentum), which finishes as the athlete opens.";
    m.keyframes = {{0.0, kTakeoff},
                   {0.15, symmetric(0, arm(-80, -5, -110), leg(0, 0, 15))},
                   {0.30, kTwistingLayout},
                   {0.45, symmetric(20, arm(-40, 5, -90), leg(-90, 100, 25), -5)},
                   {0.60, kTuck},
                   {0.80, kTuck},
                   {1.00, kTuck},
                   {1.20, kTuck},
                   {1.47, symmetric(10, arm(-70, 10, -30), leg(-60, 70, 20))},
                   {1.77, symmetric(5, arm(-60, 20, -20), leg(-25, 25, 15))},
                   {2.04, kLanding}};
    m.somersaults = -2.0;
    m.twists = 0.5;
    m.angular_momentum_guess = Eigen::Vector3d(-30, 3, 0);
    out.push_back(m);
  }
  {
    MotionDesign m;
    m.file = "M7-double-front-one-and-a-half-twists.motion.json";
    m.name = "M7 double front somersault with one and a half twists";
    m.summary =
        "Double front somersault with one and a half twists on the trampoline: take-off with "
        "the arms overhead, a tight tuck held for the first one and a half turns (~10 rad/s), a "
        "kick-out to a straight body at 1.0 s with the arms kept in and wrapped to the chest for "
        "the twisting rest of the second somersault, opened with a slight pike to stop the "
        "twist, landing upright facing backwards.";
    m.twist_source =
        "Twist source: a take-off twist. During the tuck it shows only as a tilted somersault "
        "axis and half a twist; after the kick-out the straight body with the arms in twists "
        "fast, one more full twist.";
    m.keyframes = {{0.0, kTakeoff},
                   {0.15, symmetric(20, arm(-100, 5, -50), leg(-90, 100, 25), -5)},
                   {0.32, kTuck},
                   {0.49, kTuck},
                   {0.66, kTuck},
                   {0.83, kTuck},
                   {1.00, symmetric(10, arm(-40, 10, -100), leg(-40, 30, 20))},
                   {1.14, kTwistingLayout},
                   {1.28, kTwistingLayout},
                   {1.42, kTwistingLayout},
                   {1.62, symmetric(5, arm(-40, 60, -20), leg(-20, 0, 15))},
                   {1.84, symmetric(5, arm(-60, 40, -15), leg(-20, 10, 15))},
                   {2.04, kLanding}};
    m.somersaults = 2.0;
    m.twists = 1.5;
    m.angular_momentum_guess = Eigen::Vector3d(30, 7, 0);
    out.push_back(m);
  }
  {
    // Paper §6.2: the first eight keyframes of the M5 skill (take-off, arm drop, twisting with
    // the arms in), faster, then two new ones for a head-first entry.
    const MotionDesign& rudi = out[3];
    MotionDesign m;
    m.file = "dive-5m-front-one-and-a-half-twists.motion.json";
    m.name = "5 m platform dive: forward 1 1/2 somersaults with 1 1/2 twists";
    m.com_position = Eigen::Vector3d(0, 6, 0);
    m.com_velocity = Eigen::Vector3d(0, 4, -0.5);
    // The diver faces -z so that the paper's take-off velocity carries him forwards, away from
    // the platform; a forward somersault is then negative about the world x axis.
    m.heading_deg = 180.0;
    const Pose entry = symmetric(0, arm(-178, 0, 0), leg(0, 0, 30));
    const double hands = hands_below_com(model, entry);
    const double g = -saltus::gravity().y();
    const double v = m.com_velocity.y();
    const double entry_time =
        round_to((v + std::sqrt(v * v + 2.0 * g * (m.com_position.y() - hands))) / g, 0.01);
    const std::vector<double> times = {0.0, 0.15, 0.30, 0.42, 0.54, 0.66, 0.78, 0.90};
    for (std::size_t k = 0; k < times.size(); ++k)
      m.keyframes.push_back({times[k], rudi.keyframes[k].pose});
    m.keyframes.push_back({entry_time - 0.35, symmetric(5, arm(-150, 10, -15), leg(-15, 0, 25))});
    m.keyframes.push_back({entry_time, entry});
    std::ostringstream summary;
    summary
        << "Design study of the paper's section 6.2 for a 5 m platform: the first eight keyframes "
           "are the M5 rudi's (take-off with the arms overhead, the right arm dropped sideways, "
           "the arms wrapped to the chest for the twist), faster (M5's first 1.15 s in 0.9 s); "
           "the last two are new: coming out of the twist some 20 deg short of horizontal with "
           "the arms reaching overhead, and the entry, head down with the arms overhead. Take-off "
           "CoM (0, 6, 0) m, "
           "velocity (0, 4, -0.5) m/s; the diver faces -z, so the take-off velocity carries him "
           "away from the platform and the forward somersault is negative about world x. The "
           "flight ends at water entry, defined as the moment the hands (the ends of the "
           "forearms; the model has no hands) of the vertical, arms-overhead body reach the "
           "water at y = 0: the CoM is then "
        << format(hands, 2) << " m above the water, at t = " << format(entry_time, 2) << " s.";
    m.summary = summary.str();
    m.twist_source =
        "Twist source: a take-off twist, as in M5. A take-off twist cannot give an exactly "
        "vertical entry after an odd number of half somersaults: the body's long axis circles "
        "the angular momentum and is farthest from the take-off side after one and a half "
        "turns, so the entry is tilted sideways by about twice the angle between the angular "
        "momentum and the somersault axis. The arm and hip movements that divers use to take "
        "the tilt out are too weak in this model (one arm swept through 180 deg tilts the body "
        "~4 deg) to do it in free flight.";
    m.designed_vertical_entry = true;
    m.somersaults = 1.5;
    m.twists = 1.5;
    m.angular_momentum_guess = Eigen::Vector3d(50, 10, 0);
    out.push_back(m);
  }
  {
    MotionDesign m;
    m.file = "full-twisting-back-somersault-from-the-arms.motion.json";
    m.name = "Back somersault with a full twist from the arms (aerial twist)";
    m.summary =
        "Straight back somersault with a full twist on the trampoline, the twist made in the air: "
        "the athlete leaves the bed with the arms overhead and no twist at all (the angular "
        "momentum lies along the somersault axis); the left arm is brought down sideways to the "
        "hip in the first 0.4 s while the right stays overhead, which tilts the body about 9 deg; "
        "then both arms wrap to the chest (0.6-1.55 s) and the tilted body twists fast; the right "
        "arm opens sideways to slow the twist and the athlete lands upright, facing the way they "
        "took off, with the arms forward.";
    m.twist_source =
        "Twist source: the arms alone, moving differently (an aerial twist in Yeadon's sense; "
        "`saltus analyse twist` shares it between them).";
    const Pose up = symmetric(0, kArmsOverhead, leg(0, 0, 10));
    m.keyframes = {{0.0, kTakeoff},
                   {0.20, with_arms(up, arm(-90, 90, -10), kArmsOverhead)},
                   {0.40, with_arms(up, arm(-10, 15, -10), kArmsOverhead)},
                   {0.60, kTwistingLayout},
                   {0.80, kTwistingLayout},
                   {1.00, kTwistingLayout},
                   {1.20, kTwistingLayout},
                   {1.40, kTwistingLayout},
                   {1.55, kTwistingLayout},
                   {1.75, with_arms(symmetric(0, kArmsHugging, leg(-10, 0, 15)), arm(-60, 20, -20),
                                    arm(-90, 90, -10))},
                   {2.04, kLanding}};
    m.somersaults = -1.0;
    m.aerial_twist = true;
    m.angular_momentum_guess = Eigen::Vector3d(-31, 0, 0);
    out.push_back(m);
  }
  return out;
}

/// Designs, tunes, writes and checks one motion; prints what a reviewer needs.
void make_motion(const MotionDesign& design, const BodyModel& model, const fs::path& out_dir,
                 bool verbose) {
  const Eigen::Vector3d h = tune_angular_momentum(design, model);
  const Flight flight = simulate(design, model, h);
  const Outcome outcome = analyse(design, model, h, flight);
  const fs::path path = out_dir / design.file;
  write_motion(design, flight, outcome, path);

  // Independent check through the library's own loaders and jobs (what `saltus simulate` and
  // `saltus evaluate` report for the written file).
  const saltus::MotionFile written = saltus::load_motion_file(path.string());
  const saltus::SimulationResult simulated = saltus::simulate_motion(written.motion, written.model);
  const saltus::MotionEvaluation evaluated = saltus::evaluate_motion(written.motion, written.model);
  std::string where;
  const double step = max_keyframe_step_deg(written.motion, written.model, where);

  const Eigen::Vector3d& h_world = outcome.angular_momentum_world;
  const Eigen::Vector3d& landing = outcome.landing_angles;
  std::printf("%s  (%zu keyframes, %s)\n", design.name.c_str(), design.keyframes.size(),
              path.filename().c_str());
  std::printf("  take-off angular momentum (%.2f, %.2f, %.2f) kg m^2/s world, |L| %.2f\n",
              h_world.x(), h_world.y(), h_world.z(), h_world.norm());
  std::printf("  somersaults %.3f, twists %.3f, landing tilt %.2f deg, max tilt %.1f deg\n",
              landing.x() / 360.0, landing.z() / 360.0, landing.y(), outcome.max_tilt_deg);
  if (design.twisting()) {
    std::printf(
        "  take-off twist: L tilted %.1f deg from the somersault axis; aerial share "
        "(L horizontal) %.2f twists\n",
        outcome.momentum_tilt_deg, outcome.aerial_twists);
  }
  std::printf("  simulate: landing root error %.3f deg; evaluate: average root force %.2f N\n",
              simulated.landing_root_error_deg, evaluated.metrics.avg_root_force);
  std::printf("  largest keyframe step %.1f deg (%s)\n", step, where.c_str());
  if (verbose) {
    for (std::size_t k = 0; k < design.keyframes.size(); ++k) {
      const int s = flight.keyframe_samples[k];
      const SampleRecord record =
          saltus::evaluate_states(model, {flight.times[s]}, {flight.states[s]}).front();
      const Eigen::Vector3d& a = flight.athlete_angles[s];
      std::printf("    t=%.3f  somersault %8.2f  tilt %7.2f  twist %8.2f   %s\n", flight.times[s],
                  a.x(), a.y(), a.z(), pose_report(model, record).c_str());
    }
  }
  if (step >= kMaxKeyframeStepDeg)
    throw std::runtime_error(design.name + ": keyframes too far apart (" + where + ")");
}

}  // namespace

int main(int argc, char** argv) {
  const std::string usage =
      "usage: saltus_make_example_motions OUT_DIR [--verbose] [--only NAME]\n";
  const std::vector<std::string> args(argv + 1, argv + argc);
  bool verbose = false;
  std::string out_dir;
  std::string only;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a == "--help" || a == "-h") {
      std::cout << usage;
      return 0;
    }
    if (a == "--verbose") {
      verbose = true;
    } else if (a == "--only" && i + 1 < args.size()) {
      only = args[++i];
    } else if (out_dir.empty() && !a.empty() && a[0] != '-') {
      out_dir = a;
    } else {
      std::cerr << usage;
      return 2;
    }
  }
  if (out_dir.empty()) {
    std::cerr << usage;
    return 2;
  }
  try {
    fs::create_directories(out_dir);
    const std::string model_path = saltus::resolve_model_path(kModelName, out_dir + "/x.json");
    if (model_path.empty()) throw std::runtime_error(std::string("model not found: ") + kModelName);
    const BodyModel model = saltus::load_body_model(model_path);
    for (const MotionDesign& design : designs(model)) {
      if (only.empty() || design.file.find(only) != std::string::npos)
        make_motion(design, model, out_dir, verbose);
    }
  } catch (const std::exception& e) {
    std::cerr << "saltus_make_example_motions: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
