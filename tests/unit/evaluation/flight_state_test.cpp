// The take-off state a sampled motion implies (evaluation/flight_state.h): a simulated free flight
// gives back the state it was started from, with nothing left over; a CoM off the parabola by a
// constant and an angular momentum swinging by a sine give the closed-form fit and spread.

#include "saltus/evaluation/flight_state.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "saltus/base/constants.h"
#include "saltus/dynamics/free_flight.h"
#include "saltus/motion/interpolate.h"
#include "support/test_motions.h"

namespace saltus {
namespace {

TEST(FitFlightState, AFreeFlightGivesBackItsTakeoffState) {
  const BodyModel model = test::bundled_model();
  const Trajectory<double> joints = interpolate_keyframes(test::twist_motion(model), model);
  FreeFlightInitialState initial;
  initial.com_position = Eigen::Vector3d(0.1, 1.1, -0.2);
  initial.com_velocity = Eigen::Vector3d(0.3, 9.5, 0.1);
  initial.angular_momentum = Eigen::Vector3d(28.0, -3.0, 1.5);
  initial.root_orientation = joints.rotations[0].evaluate(0.0).q;
  const std::vector<double> times = uniform_times(2.04, 121);
  const auto states = simulate_free_flight(
      model,
      [&joints](double t, BodyState<double>& s) {
        for (int k = 1; k < joints.segment_count(); ++k) {
          const auto q = joints.rotations[k].evaluate(t);
          s.joints[k] = {q.q, q.omega, q.alpha};
        }
      },
      initial, times,
      [&] {
        FreeFlightOptions options;
        options.breakpoints = joints.knots;
        return options;
      }());
  const FlightState fit = fit_flight_state(evaluate_states(model, times, states));
  EXPECT_LT((fit.com_position - initial.com_position).norm(), 1e-7);
  EXPECT_LT((fit.com_velocity - initial.com_velocity).norm(), 1e-6);
  EXPECT_LT(fit.com_fit_rms_m, 1e-7);
  EXPECT_LT((fit.angular_momentum - initial.angular_momentum).norm(), 1e-5);
  EXPECT_LT(fit.angular_momentum_spread, 1e-5);
}

TEST(FitFlightState, ClosedFormFitAndSpread) {
  // CoM = parabola + d: the fit absorbs d into the position. L = L0 + A·sin(2πt/T) over whole
  // periods: average L0, RMS spread |A|/√2 (the trapezoidal rule is exact for it).
  const Eigen::Vector3d p(0, 1, 0), v(0.2, 8.0, 0), d(0.01, -0.02, 0.03);
  const Eigen::Vector3d l0(-25, 1, 2), amplitude(3, 0, -4);
  const double duration = 2.0;
  std::vector<SampleRecord> samples(81);
  for (std::size_t k = 0; k < samples.size(); ++k) {
    const double t = duration * k / (samples.size() - 1);
    samples[k].time = 0.5 + t;  // the state is at the first sample, whatever its time
    samples[k].com = p + d + v * t + 0.5 * gravity() * t * t;
    samples[k].angular_momentum = l0 + amplitude * std::sin(2 * kPi * t / duration * 3);
  }
  const FlightState fit = fit_flight_state(samples);
  EXPECT_LT((fit.com_position - (p + d)).norm(), 1e-12);
  EXPECT_LT((fit.com_velocity - v).norm(), 1e-12);
  EXPECT_LT(fit.com_fit_rms_m, 1e-12);
  EXPECT_LT((fit.angular_momentum - l0).norm(), 1e-12);
  EXPECT_NEAR(fit.angular_momentum_spread, amplitude.norm() / std::sqrt(2.0), 1e-12);
  samples.resize(1);
  EXPECT_THROW(fit_flight_state(samples), std::invalid_argument);
}

}  // namespace
}  // namespace saltus
