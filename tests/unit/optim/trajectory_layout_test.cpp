// The optimiser's variable layout (optim/trajectory_layout.h): every variable has one index, the
// four controls a sample touches are one contiguous block, knots and keyframe spans follow from
// the keyframe times as the B-spline code lays them out, and x encodes a trajectory exactly.

#include "saltus/optim/trajectory_layout.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <stdexcept>
#include <vector>

#include "saltus/motion/interpolate.h"
#include "support/test_motions.h"

namespace saltus {
namespace {

TrajectoryLayout layout_for(int segments, const std::vector<int>& subdivisions, bool timing) {
  TrajectoryLayout layout;
  layout.segment_count = segments;
  layout.keyframe_count = static_cast<int>(subdivisions.size()) + 1;
  layout.set_subdivisions(subdivisions);
  layout.optimize_timing = timing;
  return layout;
}

/// K knot spans in each of the keyframes − 1 intervals.
TrajectoryLayout layout_for(int segments, int keyframes, int k, bool timing) {
  return layout_for(segments, std::vector<int>(keyframes - 1, k), timing);
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
  // Uniform K and uneven spans per interval: each knot is the blend of its two keyframe times
  // that refine_breakpoints makes, and each keyframe sits on its span and at its knot.
  const std::vector<double> times = {0.0, 0.31, 0.9, 1.2, 1.75, 2.04};
  for (const std::vector<int>& subdivisions : std::vector<std::vector<int>>{
           {1, 1, 1, 1, 1}, {2, 2, 2, 2, 2}, {3, 3, 3, 3, 3}, {1, 3, 2, 1, 4}, {4, 1, 1, 2, 1}}) {
    const TrajectoryLayout layout = layout_for(2, subdivisions, true);
    EXPECT_EQ(layout.subdivisions(), subdivisions);
    const std::vector<double> knots = clamped_cubic_knots(refine_breakpoints(times, subdivisions));
    ASSERT_EQ(static_cast<int>(knots.size()), layout.control_count() + 4);
    EXPECT_EQ(layout.control_count(),
              std::accumulate(subdivisions.begin(), subdivisions.end(), 0) + 3);
    for (int m = 0; m < static_cast<int>(knots.size()); ++m) {
      const TrajectoryLayout::KnotDependence d = layout.knot_dependence(m);
      EXPECT_NEAR((1 - d.weight) * times[d.left] + d.weight * times[d.left + 1], knots[m], 1e-15)
          << "subdivisions[1]=" << subdivisions[1] << " knot " << m;
    }
    for (int i = 0; i < 6; ++i) {
      EXPECT_EQ(layout.keyframe_span(i), find_span(knots, times[i])) << i;
      EXPECT_EQ(knots[layout.keyframe_knot(i)], times[i]) << i;
    }
  }
}

TEST(TrajectoryLayout, RejectsSubdivisionsThatDoNotFitTheKeyframes) {
  TrajectoryLayout layout;
  layout.segment_count = 2;
  layout.keyframe_count = 4;
  EXPECT_THROW(layout.set_subdivisions({1, 2}), std::invalid_argument);
  EXPECT_THROW(layout.set_subdivisions({1, 2, 1, 1}), std::invalid_argument);
  EXPECT_THROW(layout.set_subdivisions({1, 0, 1}), std::invalid_argument);
  layout.set_subdivisions({2, 1, 3});
  EXPECT_EQ(layout.keyframe_breakpoint, (std::vector<int>{0, 2, 3, 6}));
}

TEST(TrajectoryLayout, VariablesEncodeTheTrajectoryExactly) {
  const BodyModel model = test::bundled_model();
  const Motion motion = test::tuck_motion(model);
  for (const std::vector<int>& subdivisions :
       std::vector<std::vector<int>>{{1, 1, 1, 1}, {2, 2, 2, 2}, {1, 3, 2, 1}}) {
    InterpolationOptions options;
    options.subdivisions = subdivisions;
    const Trajectory<double> curve = interpolate_keyframes(motion, model, options);
    const TrajectoryLayout layout = layout_for(model.size(), subdivisions, true);
    ASSERT_EQ(static_cast<int>(curve.rotations[0].control().size()), layout.control_count());
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
            << "subdivisions[1]=" << subdivisions[1] << " segment " << s << " t=" << t;
    }
  }
}

}  // namespace
}  // namespace saltus
