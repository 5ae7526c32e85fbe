#include "core/parabola.h"

#include <algorithm>
#include <stdexcept>

#include "saltus/base/constants.h"
#include "saltus/dynamics/inverse_dynamics.h"
#include "saltus/evaluation/sampling.h"
#include "saltus/motion/interpolate.h"

namespace saltus::gui {

ParabolaSamples sample_parabola(const Takeoff& takeoff, double duration, int count) {
  if (count < 2) throw std::invalid_argument("parabola needs at least 2 points");
  if (!(duration > 0)) throw std::invalid_argument("parabola duration must be positive");
  ParabolaSamples out;
  out.times = uniform_times(duration, count);
  out.points.reserve(out.times.size());
  for (double t : out.times)
    out.points.push_back(ballistic_com(takeoff, t));
  // Apex: vertical velocity v_y + g_y t = 0.
  const double g = gravity().y();
  out.apex_time = std::clamp(-takeoff.com_velocity.y() / g, 0.0, duration);
  out.apex = ballistic_com(takeoff, out.apex_time);
  return out;
}

}  // namespace saltus::gui
