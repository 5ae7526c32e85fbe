// dynamics/free_flight: a gap between output times of more RK4 steps than an int holds was a
// double-to-int cast past its range, undefined behaviour (issue 16: a flight of 2.2e8 s); it is
// refused with a message instead. The sanitizer build (float-cast-overflow) catches the cast.

#include "saltus/dynamics/free_flight.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace saltus {
namespace {

BodyModel one_segment() {
  BodyModel model;
  Segment s;
  s.name = "abdomen";
  s.joint = "root";
  s.mass = 10;
  s.inertia = Eigen::Vector3d(0.1, 0.2, 0.25).asDiagonal();
  model.segments.push_back(s);
  return model;
}

TEST(FreeFlight, TooManyStepsAreRefusedNotCast) {
  const BodyModel model = one_segment();
  const JointMotion still = [](double, BodyState<double>& state) {
    for (auto& joint : state.joints) {
      joint.omega.setZero();
      joint.alpha.setZero();
    }
  };
  FreeFlightInitialState initial;
  initial.com_position = Eigen::Vector3d(0, 1, 0);
  initial.com_velocity = Eigen::Vector3d(0, 5, 0);
  initial.angular_momentum = Eigen::Vector3d(1, 0, 0);
  EXPECT_THROW(simulate_free_flight(model, still, initial, {0.0, 2.2e8}, {}),
               std::invalid_argument);
  // Where it fits, the flight is simulated.
  EXPECT_EQ(simulate_free_flight(model, still, initial, {0.0, 0.01, 0.02}, {}).size(), 3u);
}

}  // namespace
}  // namespace saltus
