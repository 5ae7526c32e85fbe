#include "core/capture_keyframes.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/motion_edit.h"

namespace saltus::gui {

namespace {

constexpr double kSameTime = 1e-9;  ///< s

const std::vector<Keyframe>& frames_of(const CaptureFile& capture) {
  return capture.import.captured.keyframes;
}

/// The motion's keyframe at `time`, or -1.
int keyframe_at(const Motion& motion, double time) {
  for (std::size_t i = 0; i < motion.keyframes.size(); ++i)
    if (std::abs(motion.keyframes[i].time - time) <= kSameTime) return static_cast<int>(i);
  return -1;
}

}  // namespace

std::vector<int> capture_frames_in(const Motion& motion, const CaptureFile& capture) {
  std::vector<int> out;
  const std::vector<Keyframe>& frames = frames_of(capture);
  for (std::size_t f = 0; f < frames.size(); ++f)
    if (keyframe_at(motion, frames[f].time) >= 0) out.push_back(static_cast<int>(f));
  return out;
}

std::optional<std::string> capture_frame_toggle_problem(const Motion& motion,
                                                        const CaptureFile& capture, int frame) {
  const int count = static_cast<int>(frames_of(capture).size());
  if (frame < 0 || frame >= count)
    return "the capture's flight has frames 1 to " + std::to_string(count) + ", not " +
           std::to_string(frame + 1);
  if (frame == 0 || frame == count - 1) {
    if (keyframe_at(motion, frames_of(capture)[static_cast<std::size_t>(frame)].time) >= 0)
      return std::string(
          "the flight's first and last frames stay keyframes: they fix its start "
          "and end");
  }
  return std::nullopt;
}

Motion with_capture_frame_toggled(const Motion& motion, const BodyModel& model,
                                  const CaptureFile& capture, int frame) {
  if (const auto problem = capture_frame_toggle_problem(motion, capture, frame))
    throw std::invalid_argument(*problem);
  const Keyframe& captured = frames_of(capture)[static_cast<std::size_t>(frame)];
  Motion edited = motion;
  const int existing = keyframe_at(motion, captured.time);
  if (existing >= 0) {
    edited.keyframes.erase(edited.keyframes.begin() + existing);
  } else {
    const auto at =
        std::upper_bound(edited.keyframes.begin(), edited.keyframes.end(), captured.time,
                         [](double t, const Keyframe& k) { return t < k.time; });
    edited.keyframes.insert(at, captured);
  }
  // The keyframes no longer describe a stored optimised spline.
  edited.spline.reset();
  validate_motion(edited, model);
  return edited;
}

Motion with_capture_frames(const Motion& motion, const BodyModel& model, const CaptureFile& capture,
                           const std::vector<int>& frames) {
  Motion edited = keep_keyframes(capture.import.captured, frames);
  edited.name = motion.name;
  edited.model = motion.model;
  validate_motion(edited, model);
  return edited;
}

std::vector<int> automatic_capture_frames(const CaptureFile& capture, bool all) {
  if (!all) return pick_keyframes(capture.import.captured, capture.model).frames;
  std::vector<int> every(frames_of(capture).size());
  for (std::size_t i = 0; i < every.size(); ++i)
    every[i] = static_cast<int>(i);
  return every;
}

KeyframePick capture_pick_errors(const CaptureFile& capture, const std::vector<int>& frames) {
  return keyframe_errors_of(capture.import.captured, frames);
}

}  // namespace saltus::gui
