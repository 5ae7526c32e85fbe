// The bundled example motions (examples/motions, examples/README.md) are physically consistent
// keyframes: their root keyframes were read off a free flight of their own joint movements. A
// free-flight simulation of each file must therefore land on its last keyframe; the trampoline
// skills must land upright and the dive must enter head down. Also checks the paper's keyframe
// counts (Table 1) and take-off states (§3.4, §6.2; the aerial full twist has M1's take-off), and
// that each exports in every format of `saltus export`.

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "saltus/evaluation/evaluate.h"
#include "saltus/evaluation/simulate.h"
#include "saltus/formats/motion_file.h"
#include "saltus/motion/motion.h"
#include "saltus/use_cases/captures.h"
#include "saltus/use_cases/motion_exports.h"
#include "support/temp_path.h"

namespace saltus {
namespace {

namespace fs = std::filesystem;

constexpr double kRadToDeg = 180.0 / M_PI;

std::vector<std::string> example_motion_files() {
  std::vector<std::string> files;
  for (const auto& entry : fs::directory_iterator(fs::path(SALTUS_EXAMPLES_DIR) / "motions")) {
    const std::string name = entry.path().filename().string();
    const std::string suffix = ".motion.json";
    if (name.size() > suffix.size() &&
        name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0)
      files.push_back(entry.path().string());
  }
  std::sort(files.begin(), files.end());
  return files;
}

bool starts_with(const std::string& text, const std::string& prefix) {
  return text.compare(0, prefix.size(), prefix) == 0;
}

std::string file_name(const std::string& path) {
  return fs::path(path).filename().string();
}

bool is_dive(const std::string& path) {
  return starts_with(file_name(path), "dive");
}

/// Keyframe counts of the paper's Table 1 (M1-M7) and of its §6.2 dive (10); -1 for a motion
/// that is not the paper's (the aerial full twist).
int expected_keyframes(const std::string& path) {
  const std::string name = file_name(path);
  if (is_dive(path)) return 10;
  const std::vector<int> table1 = {5, 7, 8, 9, 11, 11, 13};
  if (name.size() > 2 && name[0] == 'M' && name[1] >= '1' && name[1] <= '7')
    return table1[name[1] - '1'];
  return -1;
}

class ExampleMotion : public ::testing::TestWithParam<std::string> {};

TEST(ExampleMotions, TheWholeSetIsBundled) {
  std::vector<std::string> prefixes;
  for (const std::string& path : example_motion_files())
    prefixes.push_back(file_name(path).substr(0, is_dive(path) ? 4 : 2));
  for (const char* expected : {"M1", "M2", "M3", "M4", "M5", "M6", "M7", "dive"})
    EXPECT_NE(std::find(prefixes.begin(), prefixes.end(), expected), prefixes.end()) << expected;
}

TEST_P(ExampleMotion, HasThePapersKeyframeCountAndTakeoff) {
  const MotionFile file = load_motion_file(GetParam());
  const Motion& m = file.motion;
  if (expected_keyframes(GetParam()) >= 0) {
    EXPECT_EQ(static_cast<int>(m.keyframes.size()), expected_keyframes(GetParam()));
  }
  ASSERT_TRUE(m.takeoff.angular_momentum.has_value()) << "the flight's take-off must be stored";
  EXPECT_DOUBLE_EQ(m.tolerances.translation_m, 0.25);
  EXPECT_DOUBLE_EQ(m.tolerances.quaternion, 0.05);
  if (is_dive(GetParam())) {
    EXPECT_TRUE(m.takeoff.com_position.isApprox(Eigen::Vector3d(0, 6, 0)));
    EXPECT_TRUE(m.takeoff.com_velocity.isApprox(Eigen::Vector3d(0, 4, -0.5)));
  } else {
    EXPECT_TRUE(m.takeoff.com_position.isApprox(Eigen::Vector3d(0, 1, 0)));
    EXPECT_TRUE(m.takeoff.com_velocity.isApprox(Eigen::Vector3d(0.15, 10, 0.15)));
    EXPECT_DOUBLE_EQ(m.flight_time(), 2.04);
  }
}

/// Angle (deg) between the body's long axis (the root segment's y axis) and world up (down: −y).
double long_axis_angle_deg(const Eigen::Quaterniond& root, bool down) {
  const Eigen::Vector3d long_axis = root * Eigen::Vector3d::UnitY();
  return std::acos(std::clamp(down ? -long_axis.y() : long_axis.y(), -1.0, 1.0)) * kRadToDeg;
}

TEST_P(ExampleMotion, FreeFlightLandsOnTheLastKeyframe) {
  const MotionFile file = load_motion_file(GetParam());
  const SimulationResult flight = simulate_motion(file.motion, file.model);
  EXPECT_TRUE(flight.angular_momentum_from_file);
  const Eigen::Quaterniond& flight_end = flight.samples.back().segment_rotation[0];
  const Eigen::Quaterniond& last_keyframe = file.motion.keyframes.back().rotations[0];

  // Where the body's long axis points at the end of the flight: up after the trampoline skills,
  // down at the dive's water entry. A take-off twist leaves some tilt (examples/README.md): a
  // few degrees after whole somersaults, about twice the tilt of the angular momentum (14 deg
  // here) after the dive's one and a half. The dive's entry keyframe is designed exactly
  // vertical (paper §6.2), so there the flight misses its last keyframe by that tilt and the
  // optimiser has to close the gap (optimize_examples_test.cpp).
  if (is_dive(GetParam())) {
    EXPECT_LT(long_axis_angle_deg(last_keyframe, true), 0.01);
    EXPECT_LT(long_axis_angle_deg(flight_end, true), 15.0);
    EXPECT_LT(flight.landing_root_error_deg, 15.0);
  } else {
    EXPECT_LT(flight.landing_root_error_deg, 5.0);
    EXPECT_LT(long_axis_angle_deg(flight_end, false), 6.0);
  }
}

TEST_P(ExampleMotion, ExportsInEveryFormatForOtherTools) {
  const MotionFile file = load_motion_file(GetParam());
  const double fps = default_export_fps(file.motion);
  for (const ExportFormat& format : export_formats()) {
    const std::string out =
        test::temp_path(fs::path(GetParam()).stem().string() + "-" + format.name + format.extension)
            .string();
    const ExportSummary summary = export_source(GetParam(), format.name, out);
    EXPECT_EQ(summary.format, format.name);
    if (format.sampled) {
      EXPECT_EQ(summary.frames, std::round(file.motion.flight_time() * fps) + 1) << format.name;
    }
    ASSERT_FALSE(summary.files.empty()) << format.name;
    for (const std::string& written : summary.files)
      EXPECT_GT(fs::file_size(written), 0u) << written;
    EXPECT_GT(summary.bytes, 1000u) << format.name;
  }
}

std::string example_test_name(const ::testing::TestParamInfo<std::string>& info) {
  std::string name = fs::path(info.param).filename().string();
  name = name.substr(0, name.find('.'));
  for (char& c : name) {
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  }
  return name;
}

INSTANTIATE_TEST_SUITE_P(Bundled, ExampleMotion, ::testing::ValuesIn(example_motion_files()),
                         example_test_name);

}  // namespace
}  // namespace saltus
