// The flight phase from the feet, and the ballistic fits, on synthetic feet and CoM paths whose
// true lift-off, touch-down and accelerations are known in closed form.

#include "saltus/capture/flight.h"

#include <gtest/gtest.h>

#include <cmath>

namespace saltus {
namespace {

constexpr double kG = 9.81;

/// A standing jump: both feet still on the floor (y = 0, the toe 3 cm lower than the heel's
/// point) until `liftoff`, then their lowest point rises ballistically at `v0` and lands again;
/// feet still afterwards.
std::vector<RetargetedFrame> jump(double dt, int frames, double liftoff, double v0) {
  const double airborne = 2 * v0 / kG;
  std::vector<RetargetedFrame> out(frames);
  for (int f = 0; f < frames; ++f) {
    const double t = f * dt;
    const double tau = t - liftoff;
    const double height = tau > 0 && tau < airborne ? v0 * tau - 0.5 * kG * tau * tau : 0.0;
    // Drift forwards in the air so the speed test sees a moving foot.
    const double forward = std::clamp(tau, 0.0, airborne) * 0.8;
    for (int side = 0; side < 2; ++side) {
      const double x = side == 0 ? 0.1 : -0.1;
      out[f].foot_points[side] = {Eigen::Vector3d(x, height + 0.03, forward),
                                  Eigen::Vector3d(x, height, forward + 0.15)};
    }
  }
  return out;
}

TEST(Flight, FeetFindTheJumpsLiftOffAndTouchDown) {
  const double dt = 0.02, liftoff = 0.5, v0 = 2.5, h = GroundContactOptions{}.height_tolerance_m;
  const auto frames = jump(dt, 80, liftoff, v0);
  const FlightPhase flight = detect_flight(frames, dt);
  EXPECT_EQ(flight.method, "feet");
  // Where the lowest point crosses the contact height, in closed form.
  const double up = (v0 - std::sqrt(v0 * v0 - 2 * kG * h)) / kG;
  const double down = 2 * v0 / kG - up;
  EXPECT_NEAR(flight.liftoff_time, liftoff + up, 0.004);  // frames interpolate linearly
  EXPECT_NEAR(flight.touchdown_time, liftoff + down, 0.004);
  EXPECT_EQ(flight.first_frame, static_cast<int>(std::ceil((liftoff + up) / dt)));
  EXPECT_EQ(flight.last_frame, static_cast<int>(std::floor((liftoff + down) / dt)));
  EXPECT_NEAR(flight.ground_height[0], 0.0, 1e-12);
}

TEST(Flight, AClipWithoutGroundContactIsAllFlight) {
  // The jump's airborne part alone: the feet are lowest at both ends but never still there.
  const double dt = 0.01, v0 = 3.0;
  const auto all = jump(dt, 200, 0.0, v0);
  const int n = static_cast<int>(std::floor(2 * v0 / kG / dt));
  const std::vector<RetargetedFrame> frames(all.begin(), all.begin() + n);
  const FlightPhase flight = detect_flight(frames, dt);
  EXPECT_EQ(flight.method, "no ground contact");
  EXPECT_EQ(flight.first_frame, 0);
  EXPECT_EQ(flight.last_frame, n - 1);
}

TEST(Flight, NoFlightAsksForOne) {
  const auto frames = jump(0.02, 30, 10.0, 2.0);  // lift-off after the clip
  EXPECT_THROW(detect_flight(frames, 0.02), std::invalid_argument);
  const FlightPhase given = flight_between(30, 0.02, 0.1, 0.3);
  EXPECT_EQ(given.first_frame, 5);
  EXPECT_EQ(given.last_frame, 15);
  EXPECT_EQ(given.method, "given");
  EXPECT_THROW(flight_between(30, 0.02, 0.1, 0.13), std::invalid_argument);
  EXPECT_THROW(
      {
        try {
          flight_between(30, 0.02, 0.1, 0.13);
        } catch (const CaptureError& e) {
          EXPECT_EQ(e.part(), CapturePart::kFlightOption) << "the user's --flight is named";
          throw;
        }
      },
      CaptureError);
}

TEST(Flight, BallisticFitsRecoverTheParabolaAndAWrongFrameTime) {
  const Eigen::Vector3d p0(0.1, 1.0, -0.2), v0(0.3, 2.0, -1.0), g(0, -kG, 0);
  const double true_dt = 0.02, stated_dt = 0.008;
  std::vector<double> true_times, stated_times;
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i < 25; ++i) {
    const double t = i * true_dt;
    true_times.push_back(t);
    stated_times.push_back(i * stated_dt);
    points.push_back(p0 + v0 * t + 0.5 * g * t * t);
  }
  const BallisticFit fixed = fit_ballistic_fixed(true_times, points, g);
  EXPECT_LT((fixed.position - p0).norm(), 1e-12);
  EXPECT_LT((fixed.velocity - v0).norm(), 1e-11);
  EXPECT_LT(fixed.rms_residual_m, 1e-12);
  // Read at the wrong frame time the flight falls at (true/stated)² times g.
  const BallisticFit free = fit_ballistic_free(stated_times, points);
  const double implied = -free.acceleration.y();
  EXPECT_NEAR(implied, kG * std::pow(true_dt / stated_dt, 2), 1e-8);
  EXPECT_NEAR(free.acceleration.x(), 0.0, 1e-8);
  EXPECT_NEAR(ballistic_frame_time(stated_dt, implied, kG), true_dt, 1e-12);
  // A wrong g shows as a residual.
  EXPECT_GT(fit_ballistic_fixed(stated_times, points, g).rms_residual_m, 0.01);
}

}  // namespace
}  // namespace saltus
