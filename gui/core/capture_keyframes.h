#pragma once
/// @file
/// Keyframes picked on a motion capture's timeline (the Capture panel): which captured flight
/// frames are keyframes of the motion, a frame added (with its captured pose) or removed, and
/// the library's automatic pick. Every edit returns a new Motion checked by the library's parser
/// (validate_motion); the other keyframes stay as they are, edited or not.

#include <optional>
#include <string>
#include <vector>

#include "saltus/capture/keyframe_picking.h"
#include "saltus/motion/motion.h"
#include "saltus/use_cases/captures.h"

namespace saltus::gui {

/// The captured flight frames (indices into capture.import.captured.keyframes) that are
/// keyframes of `motion`: a keyframe at the frame's time (within 1e-9 s). Increasing.
std::vector<int> capture_frames_in(const Motion& motion, const CaptureFile& capture);

/// Why frame `frame` cannot be added to or removed from `motion`'s keyframes, or nullopt: the
/// flight's first and last frames fix its start and end and stay keyframes; a frame must exist.
std::optional<std::string> capture_frame_toggle_problem(const Motion& motion,
                                                        const CaptureFile& capture, int frame);

/// `motion` with captured frame `frame` added as a keyframe (its captured pose and root
/// position) when no keyframe is at its time, else with that keyframe removed. Throws
/// std::invalid_argument with capture_frame_toggle_problem's sentence, or InputError from the
/// library's parser.
Motion with_capture_frame_toggled(const Motion& motion, const BodyModel& model,
                                  const CaptureFile& capture, int frame);

/// The motion's keyframes replaced by the captured frames `frames` (keep_keyframes); the
/// motion's name and model reference stay.
Motion with_capture_frames(const Motion& motion, const BodyModel& model, const CaptureFile& capture,
                           const std::vector<int>& frames);

/// The library's automatic pick (pick_keyframes: the fewest frames whose interpolation stays
/// within the keyframe tolerance of every captured frame), or every frame with `all`.
std::vector<int> automatic_capture_frames(const CaptureFile& capture, bool all);

/// How far the interpolation through `frames` misses the capture (keyframe_errors_of), for the
/// panel: "at most 4.1° (frame 13)".
KeyframePick capture_pick_errors(const CaptureFile& capture, const std::vector<int>& frames);

}  // namespace saltus::gui
