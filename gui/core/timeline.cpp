#include "core/timeline.h"

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <stdexcept>

namespace saltus::gui {

void Timeline::set_range(double duration, int frame_count) {
  if (!(duration > 0) || !std::isfinite(duration))
    throw std::invalid_argument("timeline duration must be positive");
  if (frame_count < 2) throw std::invalid_argument("timeline needs at least 2 frames");
  duration_ = duration;
  frame_count_ = frame_count;
  playing_ = false;
  seek(time_);
}

void Timeline::seek(double t) {
  if (!std::isfinite(t)) return;
  time_ = std::clamp(t, 0.0, duration_);
}

double Timeline::time_of_frame(int frame) const {
  const int f = std::clamp(frame, 0, frame_count_ - 1);
  // The last frame is exactly T, not (n-1)·dt, which rounding could put a hair short.
  return f == frame_count_ - 1 ? duration_ : f * frame_interval();
}

int Timeline::frame_at(double t) const {
  const double f = std::round(std::clamp(t, 0.0, duration_) / frame_interval());
  return std::clamp(static_cast<int>(f), 0, frame_count_ - 1);
}

void Timeline::step(int frames) {
  playing_ = false;
  if (frames == 0) return;
  // Position in frame units; a time within 1e-9 of a frame counts as on it.
  const double position = time_ / frame_interval();
  const double nearest = std::round(position);
  const bool on_frame = std::abs(position - nearest) < 1e-9;
  long target;
  if (frames > 0)
    target = static_cast<long>(on_frame ? nearest : std::floor(position)) + frames;
  else
    target = static_cast<long>(on_frame ? nearest : std::ceil(position)) + frames;
  const long last = frame_count_ - 1;
  if (loop_) {
    target %= (last + 1);
    if (target < 0) target += last + 1;
  } else {
    target = std::clamp(target, 0L, last);
  }
  time_ = time_of_frame(static_cast<int>(target));
}

void Timeline::set_speed(double speed) {
  if (!std::isfinite(speed)) return;
  speed_ = std::clamp(speed, kMinSpeed, kMaxSpeed);
}

void Timeline::play() {
  if (!loop_ && time_ >= duration_) time_ = 0.0;
  playing_ = true;
}

bool Timeline::advance(double wall_seconds) {
  if (!playing_ || !(wall_seconds > 0)) return false;
  double t = time_ + wall_seconds * speed_;
  if (t >= duration_) {
    if (loop_) {
      t = std::fmod(t, duration_);
    } else {
      t = duration_;
      playing_ = false;
    }
  }
  const bool changed = t != time_;
  time_ = t;
  return changed;
}

std::vector<KeyframeTick> keyframe_ticks(const std::vector<double>& given,
                                         const std::vector<double>& optimised, double duration) {
  std::vector<KeyframeTick> out;
  const double scale = duration > 0 ? 1.0 / duration : 0.0;
  auto add = [&](const std::vector<double>& times, TickKind kind) {
    for (std::size_t i = 0; i < times.size(); ++i) {
      KeyframeTick tick;
      tick.keyframe = static_cast<int>(i);
      tick.time = times[i];
      tick.fraction = std::clamp(times[i] * scale, 0.0, 1.0);
      tick.kind = kind;
      out.push_back(tick);
    }
  };
  add(given, TickKind::kGiven);
  add(optimised, TickKind::kOptimised);
  return out;
}

std::vector<double> speed_choices() {
  return {0.1, 0.25, 0.5, 1.0, 1.5, 2.0};
}

namespace {

std::string printed(const char* format, ...) __attribute__((format(printf, 1, 2)));
std::string printed(const char* format, ...) {
  char buffer[320];
  va_list args;
  va_start(args, format);
  std::vsnprintf(buffer, sizeof buffer, format, args);
  va_end(args);
  return buffer;
}

}  // namespace

std::vector<TimelineFlag> apparatus_flags(const ApparatusClearance& c,
                                          const std::optional<DiveEntry>& entry, double duration) {
  const auto fraction = [duration](double t) {
    return duration > 0.0 ? std::clamp(t / duration, 0.0, 1.0) : 0.0;
  };
  std::vector<TimelineFlag> out;
  TimelineFlag pass;
  pass.time = c.time_s;
  pass.fraction = fraction(c.time_s);
  pass.kind = c.collision ? FlagKind::kCollision : FlagKind::kClearance;
  const char* where = c.collision ? "inside its space by" : "clear by";
  if (c.kind == ApparatusKind::kPlatform)
    pass.text = printed(
        "Closest to the platform at %.3f s: %s %.2f m (%s, %.2f m %s its edge, %.2f m %s its "
        "top)%s",
        c.time_s, where, std::abs(c.min_distance_m), c.point.c_str(), std::abs(c.edge_m),
        c.edge_m >= 0 ? "behind" : "ahead of", std::abs(c.vertical_m),
        c.vertical_m >= 0 ? "below" : "above",
        c.collision ? ": the body would strike the platform" : "");
  else
    pass.text = printed(
        "Closest to the trampoline frame at %.3f s: %s %.2f m (%s, %.2f m %s the bed's edge)%s",
        c.time_s, where, std::abs(c.min_distance_m), c.point.c_str(), std::abs(c.edge_m),
        c.edge_m >= 0 ? "inside" : "beyond",
        c.collision ? ": the body would strike the frame" : "");
  out.push_back(pass);
  if (entry) {
    TimelineFlag e;
    e.time = entry->time_s;
    e.fraction = fraction(entry->time_s);
    e.kind = entry->vertical ? FlagKind::kEntry : FlagKind::kEntryOffLine;
    e.text = printed("Entry at %.3f s: %s first, body %.1f° from vertical, %s: %s (within %.0f°)",
                     entry->time_s, entry->first_contact.c_str(), entry->angle_to_vertical_deg,
                     entry->head_first ? "head first" : "feet first",
                     entry->vertical ? "vertical" : "not vertical", kVerticalEntryToleranceDeg);
    out.push_back(e);
  }
  std::stable_sort(out.begin(), out.end(),
                   [](const TimelineFlag& a, const TimelineFlag& b) { return a.time < b.time; });
  return out;
}

std::string format_time(double time, double duration) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.3f s / %.3f s", time, duration);
  return buffer;
}

}  // namespace saltus::gui
