// formats/finite_check: the last guard before a result is written (issue 16 item 4): a NaN or
// an infinity anywhere is named, never written as null or "nan" with exit 0.

#include "saltus/formats/finite_check.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "saltus/base/input_error.h"
#include "support/input_errors.h"

namespace saltus {
namespace {

using test::input_error;

TEST(FiniteCheck, NamesTheFirstNonFiniteNumberOfAResult) {
  nlohmann::json result = {{"status", "evaluated"},
                           {"iterations", nullptr},
                           {"before", {{"objective", 1.0}, {"avg_root_force", 2.0}}},
                           {"keyframe_times_before", {0.0, 1.0}}};
  EXPECT_EQ(input_error([&] { require_finite(result, "m.motion.json"); }), "");
  result["before"]["avg_root_force"] = std::nan("");
  EXPECT_NE(input_error([&] { require_finite(result, "m.motion.json"); })
                .find("m.motion.json: the computed result is not finite (result.json "
                      "/before/avg_root_force)"),
            std::string::npos);
  result["before"]["avg_root_force"] = 2.0;
  result["keyframe_times_before"][1] = -std::numeric_limits<double>::infinity();
  EXPECT_NE(input_error([&] { require_finite(result, "m"); }).find("/keyframe_times_before/1"),
            std::string::npos);
}

TEST(FiniteCheck, NamesTheColumnAndTimeOfATrajectory) {
  std::vector<SampleRecord> samples(3);
  for (int k = 0; k < 3; ++k) {
    samples[k].time = k * 0.5;
    samples[k].segment_position = {Eigen::Vector3d::Zero()};
    samples[k].segment_rotation = {Eigen::Quaterniond::Identity()};
  }
  EXPECT_EQ(input_error([&] { require_finite(samples, "m", "trajectory.csv"); }), "");
  samples[2].root_wrench[4] = std::numeric_limits<double>::infinity();
  EXPECT_NE(input_error([&] {
              require_finite(samples, "m", "trajectory.csv");
            }).find("trajectory.csv root wrench at t = 1 s"),
            std::string::npos);
}

TEST(FiniteCheck, NamesTheQuantityAndTimeOfSampledStates) {
  const std::vector<double> times = {0.0, 0.25};
  std::vector<BodyState<double>> states(2, BodyState<double>(2));
  EXPECT_EQ(input_error([&] { require_finite(states, times, "m", "export"); }), "");
  states[1].joints[1].alpha.y() = std::nan("");
  EXPECT_NE(input_error([&] {
              require_finite(states, times, "m", "export");
            }).find("m: the computed result is not finite (export joint 1 at t = 0.25 s)"),
            std::string::npos);
  states[1].joints[1].alpha.y() = 0.0;
  states[0].root_velocity.x() = std::numeric_limits<double>::infinity();
  EXPECT_NE(input_error([&] {
              require_finite(states, times, "m", "export");
            }).find("export root translation at t = 0 s"),
            std::string::npos);
}

}  // namespace
}  // namespace saltus
