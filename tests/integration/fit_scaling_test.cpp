// The spline fits cost linear time in the keyframe count (issue 16 item 8: a dense QR made
// `saltus evaluate` take 0.40 s at 100 keyframes, 5.6 s at 300 and 27.6 s at 500). Timed in CPU
// seconds, so a busy machine does not make the test fail; meaningless under sanitizers.

#include <gtest/gtest.h>
#include <sys/resource.h>

#include <cmath>
#include <ctime>
#include <nlohmann/json.hpp>
#include <random>

#include "saltus/base/constants.h"
#include "saltus/math/bspline_basis.h"
#include "saltus/math/quaternion_spline.h"
#include "saltus/math/vector_spline.h"
#include "support/cli_runner.h"

namespace saltus {
namespace {

double cpu_seconds() {
  return static_cast<double>(std::clock()) / CLOCKS_PER_SEC;
}

/// CPU seconds of one fit of each kind through `keyframes` targets of a smooth, seeded motion.
double fit_seconds(int keyframes) {
  std::mt19937 rng(static_cast<unsigned>(keyframes));
  std::uniform_real_distribution<double> phase(0.0, 1.0);
  const double duration = 2.0;
  std::vector<double> times;
  std::vector<Quat<double>> rotations;
  std::vector<Eigen::Vector3d> points;
  const double a = phase(rng);
  for (int i = 0; i < keyframes; ++i) {
    const double t = duration * i / (keyframes - 1);
    times.push_back(t);
    rotations.push_back(
        Quat<double>(Eigen::AngleAxisd(3.0 * t, Eigen::Vector3d::UnitX()) *
                     Eigen::AngleAxisd(std::sin(2 * t + a), Eigen::Vector3d::UnitZ())));
    points.emplace_back(t, std::sin(t), std::cos(3 * t));
  }
  const std::vector<double> knots = clamped_cubic_knots(times);
  double best = 1e9;
  for (int repeat = 0; repeat < 3; ++repeat) {
    const double start = cpu_seconds();
    const auto q = fit_quaternion_spline(knots, times, rotations);
    const auto c = fit_vector_spline(knots, times, points, 1e-6);
    best = std::min(best, cpu_seconds() - start);
    // The fits still interpolate (the banded solves are the same least squares).
    const QuaternionSpline<double> curve(knots, q);
    for (int i = 0; i < keyframes; i += keyframes / 10)
      EXPECT_LT(
          std::abs(std::abs(curve.evaluate(times[i]).q.coeffs().dot(rotations[i].coeffs())) - 1.0),
          1e-12)
          << i;
  }
  return best;
}

TEST(FitScaling, EightTimesTheKeyframesCostAboutEightTimesTheTime) {
#if SALTUS_SANITIZE
  GTEST_SKIP() << "timings are meaningless under sanitizers; the release build checks them";
#endif
  const double small = fit_seconds(100);
  const double large = fit_seconds(800);
  // Linear: 8x; the dense QR was cubic: 512x.
  EXPECT_LT(large, 24 * std::max(small, 1e-3)) << small << " s at 100, " << large << " s at 800";
}

/// A smooth motion of M1's model with `keyframes` keyframes over 2.04 s (4 ms apart at 500).
nlohmann::json many_keyframes(int keyframes) {
  const std::vector<std::string> joints = {
      "root",  "lumbar", "thoracic", "shoulder_l", "shoulder_r", "elbow_l", "elbow_r",
      "hip_l", "hip_r",  "knee_l",   "knee_r",     "ankle_l",    "ankle_r"};
  nlohmann::json motion = {
      {"format", "saltus-motion/1"},
      {"name", "many keyframes"},
      {"model", "zatsiorsky-66kg"},
      {"takeoff", {{"com_position", {0, 1, 0}}, {"com_velocity", {0.15, 10, 0.15}}}},
      {"keyframes", nlohmann::json::array()}};
  for (int i = 0; i < keyframes; ++i) {
    const double t = 2.04 * i / (keyframes - 1);
    nlohmann::json rotations;
    for (std::size_t j = 0; j < joints.size(); ++j) {
      const double angle =
          j == 0 ? -2 * kPi * t / 2.04 : 0.6 * std::sin(kPi * t / 2.04 * (1 + 0.1 * j));
      rotations[joints[j]] = {std::cos(angle / 2), std::sin(angle / 2), 0, 0};
    }
    motion["keyframes"].push_back({{"time", t}, {"rotations", rotations}});
  }
  return motion;
}

double children_cpu_seconds() {
  rusage usage{};
  getrusage(RUSAGE_CHILDREN, &usage);
  return usage.ru_utime.tv_sec + usage.ru_stime.tv_sec +
         1e-6 * (usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

TEST(FitScaling, EvaluateWith500KeyframesTakesUnderASecond) {
#if SALTUS_SANITIZE
  GTEST_SKIP() << "timings are meaningless under sanitizers; the release build checks them";
#endif
  test::TempDir dir;
  test::write_text(dir / "many.motion.json", many_keyframes(500).dump());
  const double before = children_cpu_seconds();
  const auto run =
      test::run_cli("evaluate " + (dir / "many.motion.json") + " --out " + (dir / "out") + " -q");
  const double seconds = children_cpu_seconds() - before;
  ASSERT_EQ(run.status, 0) << run.output;
  EXPECT_LT(seconds, 1.0) << "CPU seconds of saltus evaluate, 500 keyframes";
}

}  // namespace
}  // namespace saltus
