#pragma once
/// @file
/// Picking keyframes from a captured motion (every frame a keyframe) so that the motion verbs'
/// interpolation through them (paper §5.2, knots at the keyframes) stays near the capture.

#include <optional>
#include <string>
#include <vector>

#include "saltus/body/body_model.h"
#include "saltus/motion/motion.h"

namespace saltus {

struct KeyframePick {
  std::vector<int> frames;  ///< indices into the captured motion's keyframes, increasing
  /// How far the interpolation through the picked keyframes is from the capture, over every
  /// captured frame and joint: quaternion distance (paper eq. 3) and rotation angle.
  double max_quaternion_error = 0.0;
  double max_rotation_error_deg = 0.0;
  int worst_frame = 0;  ///< where the largest error is (index into the captured motion)
  std::string rule;     ///< the rule used, in words, for result.json
};

/// The most keyframes pick_keyframes picks. Each step refits the curves through every picked
/// frame, so picking K costs about K² fits: a flight that no few keyframes reproduce (500
/// frames of a jerky clip took 81 s) stops here; every frame is `--keyframes all`.
inline constexpr int kMaxPickedKeyframes = 100;

/// Greedy refinement: start from the first and last frame; while the interpolation through the
/// picked frames misses some captured frame's joint rotation by more than the motion's
/// quaternion tolerance ε2 (or, when `count` is given, until there are `count` keyframes), add
/// the frame it misses most, up to kMaxPickedKeyframes (the pick's max_quaternion_error then
/// says how far the tolerance is missed). `count` must be in [2, min(number of frames,
/// kMaxPickedKeyframes)] (std::invalid_argument).
KeyframePick pick_keyframes(const Motion& captured, const BodyModel& model,
                            std::optional<int> count = std::nullopt);

/// The largest error of the interpolation through `frames` over every captured frame.
KeyframePick keyframe_errors_of(const Motion& captured, const std::vector<int>& frames);

/// A copy of `captured` keeping only the keyframes at `frames` (times unchanged: the first must
/// be 0, i.e. frames[0] == 0).
Motion keep_keyframes(const Motion& captured, const std::vector<int>& frames);

}  // namespace saltus
