// The optimiser's variable layout (optim/trajectory_layout.h): every variable has one index, the
// four controls a sample touches are one contiguous block, knots and keyframe spans follow from
// the keyframe times as the B-spline code lays them out, and x encodes a trajectory exactly.

#include "saltus/optim/trajectory_layout.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>

#include "saltus/motion/interpolate.h"
#include "support/test_motions.h"

namespace saltus {
namespace {

TrajectoryLayout layout_for(int segments, int keyframes, int k, bool timing) {
  TrajectoryLayout layout;
  layout.segment_count = segments;
  layout.keyframe_count = keyframes;
  layout.knots_per_interval = k;
  layout.optimize_timing = timing;
  return layout;
}

TEST(TrajectoryLayout, GivesEveryVariableOneIndex) {
  for (int k : {1, 2, 3}) {
    for (bool timing : {true, false}) {
      const TrajectoryLayout layout = layout_for(13, 6, k, timing);
      EXPECT_EQ(layout.control_count(), 5 * k + 3);
      std::vector<int> seen;
      for (int curve = 0; curve < layout.curve_count(); ++curve)
        for (int control = 0; control < layout.control_count(); ++control)
          for (int dim = 0; dim < 3; ++dim)
            seen.push_back(layout.control_variable(curve, control, dim));
      EXPECT_EQ(static_cast<int>(seen.size()), layout.control_variable_count());
      EXPECT_EQ(layout.time_variable(0), -1);
      EXPECT_EQ(layout.time_variable(5), -1);
      for (int i = 1; i <= 4; ++i) {
        if (timing) {
          seen.push_back(layout.time_variable(i));
        } else {
          EXPECT_EQ(layout.time_variable(i), -1);
        }
      }
      std::sort(seen.begin(), seen.end());
      std::vector<int> all(layout.size());
      std::iota(all.begin(), all.end(), 0);
      EXPECT_EQ(seen, all) << "K=" << k << " timing " << timing;
    }
  }
}

TEST(TrajectoryLayout, TheFourControlsOfASpanAreOneContiguousBlock) {
  const TrajectoryLayout layout = layout_for(13, 5, 2, true);
  for (int first = 0; first + 3 < layout.control_count(); ++first) {
    int low = layout.size(), high = -1;
    for (int curve = 0; curve < layout.curve_count(); ++curve)
      for (int j = first; j < first + 4; ++j)
        for (int dim = 0; dim < 3; ++dim) {
          low = std::min(low, layout.control_variable(curve, j, dim));
          high = std::max(high, layout.control_variable(curve, j, dim));
        }
    EXPECT_EQ(low, first * layout.curve_block());
    EXPECT_EQ(high - low + 1, 4 * layout.curve_block());
  }
}

TEST(TrajectoryLayout, KnotsAndKeyframeSpansFollowTheBsplineLayout) {
  const std::vector<double> times = {0.0, 0.31, 0.9, 1.2, 1.75, 2.04};
  for (int k : {1, 2, 3}) {
    const TrajectoryLayout layout = layout_for(2, 6, k, true);
    const std::vector<double> knots = clamped_cubic_knots(refine_breakpoints(times, k));
    ASSERT_EQ(static_cast<int>(knots.size()), layout.control_count() + 4);
    for (int m = 0; m < static_cast<int>(knots.size()); ++m) {
      const TrajectoryLayout::KnotDependence d = layout.knot_dependence(m);
      EXPECT_NEAR((1 - d.weight) * times[d.left] + d.weight * times[d.left + 1], knots[m], 1e-15)
          << "K=" << k << " knot " << m;
    }
    for (int i = 0; i < 6; ++i)
      EXPECT_EQ(layout.keyframe_span(i), find_span(knots, times[i])) << "K=" << k << " " << i;
  }
}

TEST(TrajectoryLayout, VariablesEncodeTheTrajectoryExactly) {
  const BodyModel model = test::bundled_model();
  const Motion motion = test::tuck_motion(model);
  for (int k : {1, 2}) {
    InterpolationOptions options;
    options.knots_per_interval = k;
    const Trajectory<double> curve = interpolate_keyframes(motion, model, options);
    const TrajectoryLayout layout = layout_for(model.size(), 5, k, true);
    // The reference controls sit away from the curve's (δ ≠ 0), one of them with its sign
    // flipped: the encoding must reproduce the curve's own controls, signs included.
    TrajectoryReference reference;
    for (const auto& r : curve.rotations) {
      reference.joint_control.push_back(r.control());
      for (Eigen::Quaterniond& q : reference.joint_control.back())
        q = q * quat_exp(Eigen::Vector3d(0.1, -0.2, 0.05));
    }
    reference.joint_control[3][2].coeffs() *= -1.0;
    for (const Keyframe& key : motion.keyframes)
      reference.keyframe_times.push_back(key.time);
    const std::vector<double> times = reference.keyframe_times;
    const std::vector<double> x = variables_from(layout, reference, curve, times);
    EXPECT_EQ(keyframe_times_from(layout, reference, x.data()), times);
    const Trajectory<double> back = trajectory_from(layout, reference, x.data());
    for (double t = 0.0; t <= 2.04; t += 0.051) {
      EXPECT_LT(
          (back.root_translation.evaluate(t).position - curve.root_translation.evaluate(t).position)
              .norm(),
          1e-12);
      for (int s = 0; s < model.size(); ++s)
        EXPECT_LT(
            (back.rotations[s].evaluate(t).q.coeffs() - curve.rotations[s].evaluate(t).q.coeffs())
                .norm(),
            1e-12)
            << "K=" << k << " segment " << s << " t=" << t;
    }
  }
}

}  // namespace
}  // namespace saltus
