#pragma once
/// @file
/// Playback maths behind the timeline widget: a current time on [0, T], the frame grid it snaps
/// to when stepping (the motion's samples), speed, loop, where the keyframe ticks go and the
/// flags of the closest pass to the apparatus and a dive's entry. No widgets, so all of it is
/// unit-tested.

#include <optional>
#include <string>
#include <vector>

#include "saltus/evaluation/clearance.h"

namespace saltus::gui {

class Timeline {
 public:
  static constexpr double kMinSpeed = 0.1;
  static constexpr double kMaxSpeed = 2.0;

  /// @param duration     flight time T, s (> 0)
  /// @param frame_count  frames on [0, T], both ends included (>= 2): the sample grid
  /// Throws std::invalid_argument otherwise. Keeps the current time (clamped), stops playback.
  void set_range(double duration, int frame_count);

  double duration() const { return duration_; }
  int frame_count() const { return frame_count_; }
  /// Time between two frames, s.
  double frame_interval() const { return duration_ / (frame_count_ - 1); }

  double time() const { return time_; }
  /// Moves to t, clamped to [0, T].
  void seek(double t);
  /// Nearest frame to the current time.
  int frame() const { return frame_at(time_); }
  /// Time of a frame (clamped to the valid frames).
  double time_of_frame(int frame) const;
  /// Nearest frame to t (clamped).
  int frame_at(double t) const;
  void seek_frame(int frame) { seek(time_of_frame(frame)); }
  /// Steps `frames` grid frames forward (> 0) or back (< 0) and pauses. From between two frames
  /// the first step lands on the neighbouring frame in that direction. With loop on, stepping past
  /// an end continues from the other end; without, it stops there.
  void step(int frames);

  double speed() const { return speed_; }
  /// Playback speed factor, clamped to [kMinSpeed, kMaxSpeed].
  void set_speed(double speed);
  bool loop() const { return loop_; }
  void set_loop(bool loop) { loop_ = loop; }

  bool playing() const { return playing_; }
  /// Starts playback; at the very end without loop it restarts from 0.
  void play();
  void pause() { playing_ = false; }
  void toggle_play() { playing_ ? pause() : play(); }

  /// Advances the time by wall_seconds × speed while playing. At the end it wraps to the start
  /// with loop on, else it stops at T and pauses. Returns whether the time changed.
  bool advance(double wall_seconds);

 private:
  double duration_ = 1.0;
  int frame_count_ = 2;
  double time_ = 0.0;
  double speed_ = 1.0;
  bool loop_ = true;
  bool playing_ = false;
};

enum class TickKind { kGiven, kOptimised };

/// A keyframe mark on the timeline.
struct KeyframeTick {
  int keyframe = 0;       ///< index in the motion
  double time = 0.0;      ///< s
  double fraction = 0.0;  ///< time / T, in [0, 1]: where along the slider
  TickKind kind = TickKind::kGiven;
};

/// Ticks for the given keyframe times and, when not empty, the optimised ones.
std::vector<KeyframeTick> keyframe_ticks(const std::vector<double>& given,
                                         const std::vector<double>& optimised, double duration);

enum class FlagKind {
  kClearance,     ///< the closest pass to the apparatus, clear of it
  kCollision,     ///< the closest pass is inside the platform's space or the frame
  kEntry,         ///< a dive's entry, vertical
  kEntryOffLine,  ///< a dive's entry, not vertical
};

/// A moment flagged on the timeline, with what a coach reads in its tooltip.
struct TimelineFlag {
  double time = 0.0;      ///< s
  double fraction = 0.0;  ///< time / T, in [0, 1]
  FlagKind kind = FlagKind::kClearance;
  std::string text;  ///< "Closest to the platform: inside its space by 0.52 m (left toes, ...)"
};

/// The flags of a flight: its closest pass to the apparatus and, for a dive, its entry
/// (evaluation/clearance.h), in time order. `duration` > 0.
std::vector<TimelineFlag> apparatus_flags(const ApparatusClearance& clearance,
                                          const std::optional<DiveEntry>& entry, double duration);

/// The speeds the speed selector offers, slowest first, 1× included.
std::vector<double> speed_choices();

/// "1.234 s / 2.040 s" for the time label.
std::string format_time(double time, double duration);

}  // namespace saltus::gui
