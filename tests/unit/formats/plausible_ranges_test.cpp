// formats/plausible_ranges.h as the model and motion readers apply it (issue 16 items 4-5):
// seeded families of plausible inputs are accepted, the bounds themselves hold where they are
// stated, and the angular-momentum bound is checked against an independent path (the momentum
// of a body turning at a known rate, from the dynamics layer).

#include "saltus/formats/plausible_ranges.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <random>

#include "saltus/base/input_error.h"
#include "saltus/dynamics/inverse_dynamics.h"
#include "saltus/dynamics/momentum.h"
#include "saltus/formats/model_file.h"
#include "saltus/formats/motion_file.h"
#include "support/cli_runner.h"
#include "support/input_errors.h"

namespace saltus {
namespace {

using test::read_json;
nlohmann::json model_json() {
  return read_json(std::string(SALTUS_RESOURCES_DIR) + "/models/zatsiorsky-66kg.json");
}

nlohmann::json m1_json() {
  return read_json(test::m1_path());
}

/// The JSON pointer of the InputError `f` throws ("none" if it throws none).
template <typename F>
std::string error_path(F f) {
  const std::optional<InputError> e = test::thrown_input_error(f);
  return e ? e->json_path() : "none";
}

TEST(PlausibleRanges, SeededFamiliesOfPlausibleModelsAreAccepted) {
  // Masses and sizes from a child to a heavyweight, inertias of random rigid bodies (random
  // positive point masses give principal moments that obey the triangle inequality), some as 6
  // values in a rotated frame.
  std::mt19937 rng(16);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int trial = 0; trial < 200; ++trial) {
    nlohmann::json model = model_json();
    for (auto& segment : model["segments"]) {
      const double mass = 0.2 + 40.0 * unit(rng);
      Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();
      for (int p = 0; p < 4; ++p) {
        const Eigen::Vector3d r = 0.3 * Eigen::Vector3d(unit(rng), unit(rng), unit(rng)) -
                                  Eigen::Vector3d::Constant(0.15);
        inertia += mass / 4 * (r.squaredNorm() * Eigen::Matrix3d::Identity() - r * r.transpose());
      }
      const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(inertia);
      segment["mass"] = mass;
      if (trial % 2 == 0) {
        const Eigen::Vector3d m = eigen.eigenvalues();
        segment["inertia"] = {m[0], m[1], m[2]};
      } else {
        segment["inertia"] = {inertia(0, 0), inertia(1, 1), inertia(2, 2),
                              inertia(0, 1), inertia(0, 2), inertia(1, 2)};
      }
      segment["com"][1] = segment["com"][1].get<double>() * (0.5 + unit(rng));
    }
    EXPECT_NO_THROW(parse_body_model(model, "m.json")) << model.dump();
  }
}

TEST(PlausibleRanges, ModelBoundsHoldWhereStated) {
  const auto with = [](const std::function<void(nlohmann::json&)>& change) {
    nlohmann::json model = model_json();
    change(model["segments"][4]);
    return error_path([&] { parse_body_model(model, "m.json"); });
  };
  EXPECT_EQ(with([](auto& s) { s["mass"] = plausible::kMaxSegmentMass; }), "none");
  EXPECT_EQ(with([](auto& s) { s["mass"] = plausible::kMaxSegmentMass * 1.001; }),
            "/segments/4/mass");
  EXPECT_EQ(with([](auto& s) { s["mass"] = 1e-320; }), "/segments/4/mass");
  // A flat body: Iz = Ix + Iy exactly, the triangle inequality's boundary.
  EXPECT_EQ(with([](auto& s) { s["inertia"] = {0.002, 0.003, 0.005}; }), "none");
  EXPECT_EQ(with([](auto& s) { s["inertia"] = {0.002, 0.003, 0.00501}; }), "/segments/4/inertia");
  EXPECT_EQ(with([](auto& s) { s["inertia"] = {0.01, 0.01, 1.0}; }), "/segments/4/inertia");
  EXPECT_EQ(with([](auto& s) { s["inertia"] = {0.01, 0.01, 1.0, 0, 0, 0}; }),
            "/segments/4/inertia");
  EXPECT_EQ(with([](auto& s) { s["inertia"] = {1e300, 1e300, 1e300, 0, 0, 0}; }),
            "/segments/4/inertia");
  EXPECT_EQ(with([](auto& s) {
              s["joint_position"] = {0, -plausible::kMaxSegmentLength, 0};
            }),
            "none");
  EXPECT_EQ(with([](auto& s) {
              s["joint_position"] = {0, -11, 0};
            }),
            "/segments/4/joint_position/1");
  EXPECT_EQ(with([](auto& s) { s["shape"]["length"] = -1e308; }), "/segments/4/shape/length");
  EXPECT_EQ(with([](auto& s) { s["shape"]["colour"] = "red"; }), "/segments/4/shape/colour");
}

TEST(PlausibleRanges, MotionBoundsHoldWhereStated) {
  const BodyModel model = parse_body_model(model_json(), "model.json");
  const auto with = [&](const std::function<void(nlohmann::json&)>& change) {
    nlohmann::json motion = m1_json();
    change(motion);
    return error_path([&] { parse_motion(motion, "m.json", model); });
  };
  EXPECT_EQ(with([](auto&) {}), "none");
  EXPECT_EQ(with([](auto& m) { m["takeoff"]["com_velocity"] = {0, 99.9, 0}; }), "none");
  EXPECT_EQ(with([](auto& m) {
              m["takeoff"]["com_velocity"] = {60, 60, 60};
            }),
            "/takeoff/com_velocity");
  EXPECT_EQ(with([](auto& m) { m["keyframes"][1]["time"] = plausible::kMinKeyframeGap; }), "none");
  EXPECT_EQ(with([](auto& m) { m["keyframes"][1]["time"] = 0.999 * plausible::kMinKeyframeGap; }),
            "/keyframes/1/time");
  EXPECT_EQ(with([](auto& m) { m["keyframes"][4]["time"] = plausible::kMaxFlightTime; }), "none");
  EXPECT_EQ(with([](auto& m) { m["keyframes"][4]["time"] = 60.001; }), "/keyframes/4/time");
  EXPECT_EQ(with([](auto& m) { m["tolerances"]["quaternion"] = 2.5; }), "/tolerances/quaternion");
  EXPECT_EQ(with([](auto& m) { m["description"] = "a known free-text field"; }), "none");
  EXPECT_EQ(with([](auto& m) { m["comment"] = "x"; }), "/comment");
  EXPECT_EQ(
      with([](auto& m) {
        m["keyframes"][2]["rotations"]["knee_l"] = {{"euler_deg", {1e5, 0, 0}}, {"order", "XYZ"}};
      }),
      "/keyframes/2/rotations/knee_l/euler_deg/0");
}

/// Whole-body angular momentum about the CoM (world) of M1's first pose turning rigidly at
/// `omega` (world frame, rad/s): from the dynamics layer's momentum, not the reader's inertia.
Eigen::Vector3d momentum_turning_at(const BodyModel& model, const Motion& motion,
                                    const Eigen::Vector3d& omega) {
  BodyState<double> state(model.size());
  for (int i = 0; i < model.size(); ++i)
    state.joints[i].q = motion.keyframes.front().rotations[i];
  const Eigen::Matrix3d r0 = state.joints[0].q.toRotationMatrix();
  state.joints[0].omega = r0.transpose() * omega;  // the root's own frame
  DynamicsData<double> data(model);
  inverse_dynamics(model, data, state);
  // The root origin's velocity that keeps the CoM still: v = −ω × (G − O).
  state.root_velocity = -omega.cross(data.com - data.world_position[0]);
  inverse_dynamics(model, data, state);
  return whole_body_momentum(model, data).angular_about_com;
}

TEST(PlausibleRanges, AngularMomentumIsBoundedByTheRateItGivesTheBody) {
  const BodyModel model = parse_body_model(model_json(), "model.json");
  const nlohmann::json base = m1_json();
  const Motion motion = parse_motion(base, "m.json", model);
  std::mt19937 rng(7);
  std::normal_distribution<double> normal;
  for (int trial = 0; trial < 20; ++trial) {
    const Eigen::Vector3d axis =
        Eigen::Vector3d(normal(rng), normal(rng), normal(rng)).normalized();
    for (const double factor : {0.95, 1.05}) {
      const Eigen::Vector3d l =
          momentum_turning_at(model, motion, factor * plausible::kMaxBodyAngularVelocity * axis);
      nlohmann::json document = base;
      document["takeoff"]["angular_momentum"] = {l.x(), l.y(), l.z()};
      EXPECT_EQ(error_path([&] { parse_motion(document, "m.json", model); }),
                factor < 1 ? "none" : "/takeoff/angular_momentum")
          << "axis " << axis.transpose() << " factor " << factor;
    }
  }
}

}  // namespace
}  // namespace saltus
