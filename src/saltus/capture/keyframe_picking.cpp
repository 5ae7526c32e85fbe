#include "saltus/capture/keyframe_picking.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "saltus/base/constants.h"
#include "saltus/capture/mocap_clip.h"
#include "saltus/math/bspline_basis.h"
#include "saltus/math/quaternion_spline.h"

namespace saltus {

KeyframePick keyframe_errors_of(const Motion& captured, const std::vector<int>& frames) {
  const int n = static_cast<int>(captured.keyframes.size());
  std::vector<double> times;
  for (int f : frames)
    times.push_back(captured.keyframes[f].time);
  const std::vector<double> knots = clamped_cubic_knots(times);
  const int segments = static_cast<int>(captured.keyframes.front().rotations.size());
  std::vector<double> worst(n, 0.0);
  std::vector<Eigen::Quaterniond> targets(frames.size());
  for (int s = 0; s < segments; ++s) {
    for (std::size_t i = 0; i < frames.size(); ++i)
      targets[i] = captured.keyframes[frames[i]].rotations[s];
    const QuaternionSpline<double> spline(knots, fit_quaternion_spline(knots, times, targets));
    for (int f = 0; f < n; ++f) {
      const Eigen::Quaterniond q = spline.evaluate(captured.keyframes[f].time).q;
      worst[f] = std::max(worst[f], quaternion_distance(q, captured.keyframes[f].rotations[s]));
    }
  }
  KeyframePick pick;
  pick.frames = frames;
  pick.worst_frame = static_cast<int>(std::max_element(worst.begin(), worst.end()) - worst.begin());
  pick.max_quaternion_error = worst[pick.worst_frame];
  // ‖q − q̄‖ = 2 sin(θ/4) for a rotation θ between them (sign-aligned).
  pick.max_rotation_error_deg =
      4.0 * std::asin(std::min(1.0, pick.max_quaternion_error / 2.0)) * kDegreesPerRadian;
  return pick;
}

KeyframePick pick_keyframes(const Motion& captured, const BodyModel& model,
                            std::optional<int> count) {
  const int n = static_cast<int>(captured.keyframes.size());
  if (n < 2) throw CaptureError(CapturePart::kFrames, "a captured motion needs at least 2 frames");
  const int most = std::min(n, kMaxPickedKeyframes);
  if (count && (*count < 2 || *count > most))
    throw CaptureError(CapturePart::kKeyframesOption,
                       "the keyframe count must be 2 to " + std::to_string(most) +
                           (most == n ? " (the captured flight's frames)" : " (or all)") +
                           ", found " + std::to_string(*count));
  if (static_cast<int>(captured.keyframes.front().rotations.size()) != model.size())
    throw std::invalid_argument("pick_keyframes: the motion does not fit the model");
  const double tolerance = captured.tolerances.quaternion;
  std::vector<int> frames{0, n - 1};
  KeyframePick pick = keyframe_errors_of(captured, frames);
  for (;;) {
    const bool done =
        count ? static_cast<int>(frames.size()) >= *count : pick.max_quaternion_error <= tolerance;
    if (done || static_cast<int>(frames.size()) == most) break;
    int next = pick.worst_frame;
    if (std::find(frames.begin(), frames.end(), next) != frames.end()) {
      // The worst frame is already a keyframe (the fit cannot meet it exactly): take the
      // missing frame furthest from any keyframe instead.
      int best_gap = -1;
      for (int f = 0; f < n; ++f) {
        if (std::find(frames.begin(), frames.end(), f) != frames.end()) continue;
        int gap = n;
        for (int k : frames)
          gap = std::min(gap, std::abs(f - k));
        if (gap > best_gap) best_gap = gap, next = f;
      }
    }
    frames.insert(std::upper_bound(frames.begin(), frames.end(), next), next);
    pick = keyframe_errors_of(captured, frames);
  }
  if (count) {
    pick.rule = "--keyframes " + std::to_string(*count) +
                ": starting from the first and last captured frame of the flight, the frame the "
                "interpolation through the picked keyframes misses most is added until there "
                "are that many";
  } else {
    pick.rule =
        "fewest keyframes (greedy: starting from the first and last captured frame of the "
        "flight, the frame the interpolation misses most is added) such that the interpolation "
        "through them reproduces every captured frame's joint rotations within the keyframe "
        "tolerance (quaternion distance <= " +
        std::to_string(tolerance) + "), at most " + std::to_string(kMaxPickedKeyframes);
  }
  return pick;
}

Motion keep_keyframes(const Motion& captured, const std::vector<int>& frames) {
  if (frames.empty() || frames.front() != 0)
    throw std::invalid_argument("keep_keyframes: the first captured frame must be kept");
  Motion out = captured;
  out.keyframes.clear();
  for (int f : frames)
    out.keyframes.push_back(captured.keyframes.at(f));
  out.spline.reset();
  return out;
}

}  // namespace saltus
