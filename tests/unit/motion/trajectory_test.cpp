// Trajectory::sample (motion/trajectory.h) fills a whole body state whose rates are those of its
// positions: the root's velocity and acceleration and each joint's angular velocity and
// acceleration against central differences of the sampled positions and rotations.

#include "saltus/motion/trajectory.h"

#include <gtest/gtest.h>

#include "saltus/motion/interpolate.h"
#include "support/test_motions.h"

namespace saltus {
namespace {

TEST(Trajectory, SampledRatesAreTheDerivativesOfTheSampledPoses) {
  const BodyModel model = test::bundled_model();
  const Trajectory<double> trajectory = interpolate_keyframes(test::twist_motion(model), model);
  EXPECT_EQ(trajectory.duration(), 2.04);
  EXPECT_EQ(trajectory.segment_count(), model.size());
  const double h = 1e-5;
  BodyState<double> before(model.size()), here(model.size()), after(model.size());
  for (double t : {0.13, 0.71, 1.4, 1.93}) {
    trajectory.sample(t - h, before);
    trajectory.sample(t, here);
    trajectory.sample(t + h, after);
    const Eigen::Vector3d velocity = (after.root_position - before.root_position) / (2 * h);
    const Eigen::Vector3d acceleration = (after.root_velocity - before.root_velocity) / (2 * h);
    EXPECT_LT((here.root_velocity - velocity).norm(), 1e-6 * (1 + velocity.norm())) << t;
    EXPECT_LT((here.root_acceleration - acceleration).norm(), 1e-5 * (1 + acceleration.norm()));
    for (int s = 0; s < model.size(); ++s) {
      // Child-frame angular velocity: 2·vec(q* q̇).
      const Eigen::Vector4d dq =
          (after.joints[s].q.coeffs() - before.joints[s].q.coeffs()) / (2 * h);
      const Eigen::Vector3d omega =
          2.0 * (here.joints[s].q.conjugate() * Eigen::Quaterniond(dq)).vec();
      const Eigen::Vector3d alpha = (after.joints[s].omega - before.joints[s].omega) / (2 * h);
      EXPECT_LT((here.joints[s].omega - omega).norm(), 1e-6 * (1 + omega.norm())) << t << " " << s;
      EXPECT_LT((here.joints[s].alpha - alpha).norm(), 1e-5 * (1 + alpha.norm())) << t << " " << s;
    }
  }
}

}  // namespace
}  // namespace saltus
