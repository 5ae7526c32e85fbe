#pragma once
// Motions built in code for the physics tests: the bundled model and keyframed tuck, pike and
// twisting skills whose free flights serve as ground truth.

#include <string>

#include "saltus/body/body_model.h"
#include "saltus/formats/model_file.h"
#include "saltus/math/quaternion.h"
#include "saltus/motion/motion.h"

namespace saltus::test {

inline BodyModel bundled_model() {
  return load_body_model(std::string(SALTUS_RESOURCES_DIR) + "/models/zatsiorsky-66kg.json");
}

/// Joint angles of one keyframe, degrees about x unless named otherwise (see
/// examples/README.md for the sign conventions: flexion of shoulders, elbows and hips is negative
/// about x, knee flexion positive).
struct PoseDeg {
  double root_x = 0, root_y = 0;
  double shoulder = 0, elbow = 0, hip = 0, knee = 0, thoracic = 0;
  double abduct_l = 0, abduct_r = 0;  ///< shoulder abduction about z (left +, right −)
};

inline Keyframe keyframe(const BodyModel& model, double time, const PoseDeg& p) {
  Keyframe k;
  k.time = time;
  k.rotations.assign(model.size(), Eigen::Quaterniond::Identity());
  auto set = [&](const std::string& joint, Eigen::Vector3d deg) {
    k.rotations[model.joint_index(joint)] = quat_from_euler_deg(deg, "XYZ");
  };
  set("root", {p.root_x, p.root_y, 0});
  set("thoracic", {p.thoracic, 0, 0});
  set("shoulder_l", {p.shoulder, 0, p.abduct_l});
  set("shoulder_r", {p.shoulder, 0, -p.abduct_r});
  set("elbow_l", {p.elbow, 0, 0});
  set("elbow_r", {p.elbow, 0, 0});
  for (const char* side : {"_l", "_r"}) {
    set(std::string("hip") + side, {p.hip, 0, 0});
    set(std::string("knee") + side, {p.knee, 0, 0});
  }
  return k;
}

inline Motion base_motion(const std::string& name) {
  Motion m;
  m.name = name;
  m.model = "zatsiorsky-66kg";
  m.takeoff.com_position = Eigen::Vector3d(0, 1, 0);
  m.takeoff.com_velocity = Eigen::Vector3d(0.15, 10.0, 0.15);
  return m;
}

/// Tucked back somersault: open, tuck, hold, open.
inline Motion tuck_motion(const BodyModel& model) {
  Motion m = base_motion("tuck");
  m.keyframes = {keyframe(model, 0.0, {0, 0, -160}),
                 keyframe(model, 0.45, {-60, 0, -60, -60, -110, 120, 10}),
                 keyframe(model, 1.0, {-250, 0, -40, -80, -125, 135, 15}),
                 keyframe(model, 1.6, {-380, 0, -50, -40, -60, 60, 5}),
                 keyframe(model, 2.04, {-430, 0, -40, -10, -10, 5, 0})};
  return m;
}

/// Piked front somersault: legs straight, hips flexed.
inline Motion pike_motion(const BodyModel& model) {
  Motion m = base_motion("pike");
  m.keyframes = {keyframe(model, 0.0, {0, 0, -170}),
                 keyframe(model, 0.5, {70, 0, -90, 0, -100, 0, 20}),
                 keyframe(model, 1.1, {220, 0, -70, -10, -120, 0, 25}),
                 keyframe(model, 2.04, {360, 0, -30, 0, -10, 0, 0})};
  return m;
}

/// Front somersault with a twist driven by asymmetric arms.
inline Motion twist_motion(const BodyModel& model) {
  Motion m = base_motion("twist");
  PoseDeg a{0, 0, -170};
  PoseDeg b{100, 60, -20, -30, 0, 0, 0, 10, 150};
  PoseDeg c{200, 200, -10, -40, 0, 0, 0, 10, 160};
  PoseDeg d{360, 360, -20, -10, 0, 0, 0, 20, 20};
  m.keyframes = {keyframe(model, 0.0, a), keyframe(model, 0.6, b), keyframe(model, 1.3, c),
                 keyframe(model, 2.04, d)};
  return m;
}

}  // namespace saltus::test
