// The root wrench and its exact derivatives (optim/root_wrench_derivatives.h) against independent
// paths: the wrench against inverse dynamics of the trajectory that x describes, and every
// control and keyframe-time column against central differences of the wrench itself.

#include "saltus/optim/root_wrench_derivatives.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "saltus/motion/interpolate.h"
#include "support/test_motions.h"

namespace saltus {
namespace {

/// The tucked somersault at K, encoded relative to its interpolation, then moved away from it by a
/// seeded random step (controls by up to 0.05, interior times by up to 0.03 s).
struct Point {
  BodyModel model = test::bundled_model();
  TrajectoryLayout layout;
  TrajectoryReference reference;
  std::vector<double> x;

  explicit Point(int k, unsigned seed) {
    const Motion motion = test::tuck_motion(model);
    InterpolationOptions options;
    options.knots_per_interval = k;
    const Trajectory<double> curve = interpolate_keyframes(motion, model, options);
    layout.segment_count = model.size();
    layout.keyframe_count = static_cast<int>(motion.keyframes.size());
    layout.set_subdivisions(std::vector<int>(layout.keyframe_count - 1, k));
    for (const auto& r : curve.rotations)
      reference.joint_control.push_back(r.control());
    for (const Keyframe& key : motion.keyframes)
      reference.keyframe_times.push_back(key.time);
    x = variables_from(layout, reference, curve, reference.keyframe_times);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int i = 0; i < layout.control_variable_count(); ++i)
      x[i] += 0.05 * u(rng);
    for (int i = 1; i + 1 < layout.keyframe_count; ++i)
      x[layout.time_variable(i)] += 0.03 * u(rng);
  }
};

Vector6d wrench_by_inverse_dynamics(const Point& p, double t) {
  const Trajectory<double> curve = trajectory_from(p.layout, p.reference, p.x.data());
  BodyState<double> state(p.model.size());
  curve.sample(t, state);
  DynamicsData<double> data(p.model);
  inverse_dynamics(p.model, data, state);
  return root_wrench_force_first(data);
}

TEST(RootWrenchDerivatives, WrenchIsInverseDynamicsOfTheTrajectoryXDescribes) {
  for (int k : {1, 2}) {
    const Point p(k, 3 + k);
    RootWrenchDerivatives d(p.model, p.layout, p.reference);
    d.set_variables(p.x.data());
    for (double t : {0.0, 0.27, 0.8, 1.33, 2.04}) {
      const Vector6d expected = wrench_by_inverse_dynamics(p, t);
      EXPECT_LT((d.wrench(t) - expected).norm(), 1e-9 * (1 + expected.norm())) << "t=" << t;
    }
  }
}

TEST(RootWrenchDerivatives, JacobianMatchesCentralDifferences) {
  for (int k : {1, 2}) {
    Point p(k, 10 + k);
    RootWrenchDerivatives d(p.model, p.layout, p.reference);
    for (double t : {0.19, 0.77, 1.46}) {
      d.set_variables(p.x.data());
      LocalJacobian<6> j;
      d.wrench_jacobian(t, j);
      EXPECT_LT((j.value - d.wrench(t)).norm(), 1e-9 * (1 + j.value.norm()));
      auto difference = [&](int variable) {
        const double h = 1e-6, saved = p.x[variable];
        p.x[variable] = saved + h;
        d.set_variables(p.x.data());
        const Vector6d plus = d.wrench(t);
        p.x[variable] = saved - h;
        d.set_variables(p.x.data());
        const Vector6d minus = d.wrench(t);
        p.x[variable] = saved;
        return Vector6d((plus - minus) / (2 * h));
      };
      const double scale = 1 + j.value.norm();
      for (int c = 0; c < j.control.cols(); ++c)
        EXPECT_LT((j.control.col(c) - difference(j.first_control_variable + c)).norm(),
                  1e-5 * scale)
            << "K=" << k << " t=" << t << " control column " << c;
      for (int s = 0; s < j.time_count; ++s)
        EXPECT_LT((j.time.col(s) - difference(j.time_variable[s])).norm(), 1e-4 * scale)
            << "K=" << k << " t=" << t << " time " << j.time_variable[s];
      // Variables outside the block and the listed times do not move the wrench at all.
      for (int v = 0; v < p.layout.size(); v += 7) {
        const bool in_block =
            v >= j.first_control_variable && v < j.first_control_variable + j.control.cols();
        const bool listed =
            std::find(j.time_variable.begin(), j.time_variable.begin() + j.time_count, v) !=
            j.time_variable.begin() + j.time_count;
        if (!in_block && !listed) {
          EXPECT_EQ(difference(v).norm(), 0.0) << "variable " << v;
        }
      }
    }
  }
}

TEST(RootWrenchDerivatives, KeyframeValuesAndDerivativesMatchTheTrajectory) {
  Point p(2, 21);
  RootWrenchDerivatives d(p.model, p.layout, p.reference);
  d.set_variables(p.x.data());
  const Trajectory<double> curve = trajectory_from(p.layout, p.reference, p.x.data());
  const std::vector<double> times = keyframe_times_from(p.layout, p.reference, p.x.data());
  for (int i = 0; i < p.layout.keyframe_count; ++i) {
    EXPECT_LT((d.keyframe_translation_value(i) - curve.root_translation.evaluate(times[i]).position)
                  .norm(),
              1e-12);
    const Eigen::Quaterniond q = curve.rotations[5].evaluate(times[i]).q;
    EXPECT_LT(
        (d.keyframe_rotation_value(i, 5) - Eigen::Vector4d(q.w(), q.x(), q.y(), q.z())).norm(),
        1e-12);
    LocalJacobian<3> tj;
    d.keyframe_translation(i, tj);
    LocalJacobian<4> rj;
    d.keyframe_rotation(i, 5, rj);
    EXPECT_LT((tj.value - d.keyframe_translation_value(i)).norm(), 1e-14);
    EXPECT_LT((rj.value - d.keyframe_rotation_value(i, 5)).norm(), 1e-14);
    // One column of each against central differences: a time and a rotation control.
    auto at = [&](int variable, double shift) {
      std::vector<double> y = p.x;
      y[variable] += shift;
      RootWrenchDerivatives e(p.model, p.layout, p.reference);
      e.set_variables(y.data());
      return std::make_pair(e.keyframe_translation_value(i), e.keyframe_rotation_value(i, 5));
    };
    const double h = 1e-6;
    for (int s = 0; s < tj.time_count; ++s) {
      const auto plus = at(tj.time_variable[s], h), minus = at(tj.time_variable[s], -h);
      EXPECT_LT((tj.time.col(s) - (plus.first - minus.first) / (2 * h)).norm(), 1e-5) << i;
    }
    for (int c = 0; c < rj.control.cols(); c += 5) {
      const auto plus = at(rj.first_control_variable + c, h);
      const auto minus = at(rj.first_control_variable + c, -h);
      EXPECT_LT((rj.control.col(c) - (plus.second - minus.second) / (2 * h)).norm(), 1e-6)
          << i << " column " << c;
    }
  }
}

}  // namespace
}  // namespace saltus
