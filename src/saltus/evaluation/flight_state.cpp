#include "saltus/evaluation/flight_state.h"

#include <cmath>
#include <stdexcept>

#include "saltus/base/constants.h"

namespace saltus {

FlightState fit_flight_state(const std::vector<SampleRecord>& samples) {
  if (samples.size() < 2 || !(samples.back().time > samples.front().time))
    throw std::invalid_argument("a flight state needs samples at two times at least");
  FlightState state;
  const double t0 = samples.front().time;
  const double duration = samples.back().time - t0;

  // CoM: c(t) − ½g(t − t0)² = p + v·(t − t0), least squares per coordinate.
  const Eigen::Vector3d g = gravity();
  double st = 0, stt = 0;
  Eigen::Vector3d sy = Eigen::Vector3d::Zero(), sty = Eigen::Vector3d::Zero();
  const double n = static_cast<double>(samples.size());
  for (const SampleRecord& r : samples) {
    const double t = r.time - t0;
    const Eigen::Vector3d y = r.com - 0.5 * g * t * t;
    st += t;
    stt += t * t;
    sy += y;
    sty += t * y;
  }
  const double determinant = n * stt - st * st;
  state.com_velocity = (n * sty - st * sy) / determinant;
  state.com_position = (sy - st * state.com_velocity) / n;
  double squares = 0.0;
  for (const SampleRecord& r : samples) {
    const double t = r.time - t0;
    squares +=
        (r.com - (state.com_position + state.com_velocity * t + 0.5 * g * t * t)).squaredNorm();
  }
  state.com_fit_rms_m = std::sqrt(squares / n);

  // L: the time average (the constant nearest to L(t) over the flight), trapezoidal rule.
  for (std::size_t k = 0; k + 1 < samples.size(); ++k)
    state.angular_momentum += 0.5 * (samples[k + 1].time - samples[k].time) *
                              (samples[k].angular_momentum + samples[k + 1].angular_momentum);
  state.angular_momentum /= duration;
  double spread = 0.0;
  for (std::size_t k = 0; k + 1 < samples.size(); ++k)
    spread += 0.5 * (samples[k + 1].time - samples[k].time) *
              ((samples[k].angular_momentum - state.angular_momentum).squaredNorm() +
               (samples[k + 1].angular_momentum - state.angular_momentum).squaredNorm());
  state.angular_momentum_spread = std::sqrt(spread / duration);
  return state;
}

}  // namespace saltus
