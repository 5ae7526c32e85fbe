#include "saltus/optim/automatic_resolution.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "saltus/dynamics/inverse_dynamics.h"
#include "saltus/motion/interpolate.h"

namespace saltus {

std::vector<int> first_subdivisions(const Motion& motion, const BodyModel& model,
                                    const AutomaticResolution& rules) {
  std::vector<int> out;
  const Trajectory<double> straight = interpolate_keyframes(motion, model, {});
  const int samples = 8;
  BodyState<double> current(model.size());
  DynamicsData<double> data(model);
  std::vector<Eigen::Matrix3d> last;
  for (std::size_t i = 0; i + 1 < motion.keyframes.size(); ++i) {
    const double a = motion.keyframes[i].time, b = motion.keyframes[i + 1].time;
    // The world orientation of every segment, sampled on the interval (a fast turn between two
    // keyframes shows only inside it); `turn` is the fastest sampled rate times the interval.
    double turn = 0.0;
    for (int s = 0; s <= samples; ++s) {
      straight.sample(a + (b - a) * s / samples, current);
      inverse_dynamics(model, data, current);
      if (s > 0)
        for (int k = 0; k < model.size(); ++k)
          turn = std::max(
              turn,
              Eigen::AngleAxisd(last[k].transpose() * data.world_rotation[k]).angle() * samples);
      last = data.world_rotation;
    }
    const int by_turn = static_cast<int>(std::ceil(turn / rules.turn_per_span - 1e-9));
    const int by_length = static_cast<int>(std::ceil((b - a) / rules.max_span - 1e-9));
    out.push_back(std::clamp(std::max(by_turn, by_length), 1, rules.max_spans_per_interval));
  }
  return out;
}

bool refine(std::vector<int>& subdivisions, const std::vector<double>& residual,
            const std::vector<double>& keyframe_times, const AutomaticResolution& rules) {
  bool changed = false;
  for (std::size_t i = 0; i < subdivisions.size(); ++i) {
    const double mean_square = residual[i] / (keyframe_times[i + 1] - keyframe_times[i]);
    const double factor =
        std::ceil(std::pow(mean_square / (6.0 * rules.target_force * rules.target_force),
                           0.5 / rules.convergence_order) -
                  1e-9);
    const int spans = std::min(rules.max_spans_per_interval,
                               static_cast<int>(std::max(1.0, factor)) * subdivisions[i]);
    if (spans > subdivisions[i]) changed = true;
    subdivisions[i] = std::max(subdivisions[i], spans);
  }
  return changed;
}

}  // namespace saltus
