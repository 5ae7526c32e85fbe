#include "saltus/capture/flight.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "saltus/base/text_format.h"
#include "saltus/capture/mocap_clip.h"

namespace saltus {

namespace {

/// Height and speed of each foot's lowest point per frame.
struct FootTrack {
  std::vector<double> height;
  std::vector<double> speed;
};

FootTrack track_foot(const std::vector<RetargetedFrame>& frames, int side, double frame_time) {
  const int n = static_cast<int>(frames.size());
  FootTrack track;
  track.height.resize(n);
  track.speed.resize(n);
  for (int f = 0; f < n; ++f) {
    const auto& points = frames[f].foot_points[side];
    std::size_t lowest = 0;
    for (std::size_t k = 1; k < points.size(); ++k)
      if (points[k].y() < points[lowest].y()) lowest = k;
    track.height[f] = points[lowest].y();
    // The same point's speed towards the previous and the next frame, the smaller of the two:
    // a foot that has just landed or is about to push off is still on the ground.
    double speed = 1e300;
    if (f > 0)
      speed = (points[lowest] - frames[f - 1].foot_points[side][lowest]).norm() / frame_time;
    if (f + 1 < n)
      speed = std::min(
          speed, (frames[f + 1].foot_points[side][lowest] - points[lowest]).norm() / frame_time);
    track.speed[f] = speed;
  }
  return track;
}

double percentile(std::vector<double> values, double fraction) {
  std::sort(values.begin(), values.end());
  const double position = fraction * (values.size() - 1);
  const std::size_t i = static_cast<std::size_t>(std::floor(position));
  const std::size_t j = std::min(i + 1, values.size() - 1);
  return values[i] + (position - i) * (values[j] - values[i]);
}

BallisticFit finish_fit(BallisticFit fit, const std::vector<double>& times,
                        const std::vector<Eigen::Vector3d>& points) {
  double sum = 0.0;
  for (std::size_t i = 0; i < times.size(); ++i) {
    const double t = times[i];
    const Eigen::Vector3d p = fit.position + fit.velocity * t + 0.5 * fit.acceleration * t * t;
    const double r = (p - points[i]).norm();
    sum += r * r;
    fit.max_residual_m = std::max(fit.max_residual_m, r);
  }
  fit.rms_residual_m = std::sqrt(sum / times.size());
  return fit;
}

}  // namespace

FlightPhase detect_flight(const std::vector<RetargetedFrame>& frames, double frame_time,
                          const GroundContactOptions& options) {
  const int n = static_cast<int>(frames.size());
  if (n < 3)
    throw CaptureError(CapturePart::kFrames, "a clip of fewer than 3 frames has no flight phase");
  FlightPhase flight;
  std::array<FootTrack, 2> feet;
  for (int side = 0; side < 2; ++side) {
    feet[side] = track_foot(frames, side, frame_time);
    flight.ground_height[side] = percentile(feet[side].height, options.ground_percentile);
  }
  auto relative_height = [&](int f) {
    return std::min(feet[0].height[f] - flight.ground_height[0],
                    feet[1].height[f] - flight.ground_height[1]);
  };
  // A foot is on the ground when it is low, and the run of consecutive low frames it belongs to
  // has a moment where it stands still: a landing foot still sliding or sinking into a soft
  // floor counts from the frame it comes down, a foot swinging low through a clip that never
  // touches the ground (a free flight from take-off to landing) does not.
  std::array<std::vector<bool>, 2> contact;
  for (int side = 0; side < 2; ++side) {
    const FootTrack& foot = feet[side];
    auto low = [&](int f) {
      return foot.height[f] <= flight.ground_height[side] + options.height_tolerance_m;
    };
    contact[side].assign(n, false);
    for (int f = 0; f < n;) {
      if (!low(f)) {
        ++f;
        continue;
      }
      int g = f;
      bool still = false;
      while (g < n && low(g))
        still = still || foot.speed[g] <= options.speed_tolerance_m_s, ++g;
      for (int k = f; k < g; ++k)
        contact[side][k] = still;
      f = g;
    }
  }
  auto in_contact = [&](int f, int side) { return contact[side][f]; };
  // The longest run of frames with both feet off the ground (the first of equal runs).
  int best_start = 0, best_length = 0;
  for (int f = 0; f < n;) {
    if (in_contact(f, 0) || in_contact(f, 1)) {
      ++f;
      continue;
    }
    int g = f;
    while (g < n && !in_contact(g, 0) && !in_contact(g, 1))
      ++g;
    if (g - f > best_length) best_start = f, best_length = g - f;
    f = g;
  }
  if (best_length < 3)
    throw CaptureError(
        CapturePart::kFrames,
        "no flight phase found: the longest stretch with both feet off the ground has " +
            std::to_string(best_length) + " frame(s); give it with --flight START:END");
  flight.first_frame = best_start;
  flight.last_frame = best_start + best_length - 1;
  flight.method = best_length == n ? "no ground contact" : "feet";

  // Sub-frame estimates: where the lower foot crosses the contact height between the last
  // frame on the ground and the first in the air (the frames' midpoint when speed decided).
  const double h = options.height_tolerance_m;
  auto crossing = [&](int grounded, int airborne) {
    const double a = relative_height(grounded), b = relative_height(airborne);
    const double tg = grounded * frame_time, ta = airborne * frame_time;
    if (a < h && h <= b) return tg + (ta - tg) * (h - a) / (b - a);
    return 0.5 * (tg + ta);
  };
  flight.liftoff_time =
      flight.first_frame == 0 ? 0.0 : crossing(flight.first_frame - 1, flight.first_frame);
  flight.touchdown_time = flight.last_frame == n - 1
                              ? (n - 1) * frame_time
                              : crossing(flight.last_frame + 1, flight.last_frame);
  return flight;
}

FlightPhase flight_between(int frame_count, double frame_time, double start, double end) {
  if (!(start < end))
    throw CaptureError(CapturePart::kFlightOption, "the flight's start must be before its end");
  FlightPhase flight;
  // Frames inside [start, end], with a rounding allowance so "0.6875" selects frame 11.
  const double slack = 1e-6 * frame_time;
  flight.first_frame = std::max(0, static_cast<int>(std::ceil((start - slack) / frame_time)));
  flight.last_frame =
      std::min(frame_count - 1, static_cast<int>(std::floor((end + slack) / frame_time)));
  if (flight.last_frame - flight.first_frame + 1 < 3)
    throw CaptureError(CapturePart::kFlightOption,
                       "the flight " + message_number(start) + ":" + message_number(end) +
                           " s holds fewer than 3 of the clip's " + std::to_string(frame_count) +
                           " frames (" + message_number(frame_time) + " s apart)");
  flight.liftoff_time = start;
  flight.touchdown_time = end;
  flight.method = "given";
  return flight;
}

BallisticFit fit_ballistic_fixed(const std::vector<double>& times,
                                 const std::vector<Eigen::Vector3d>& points,
                                 const Eigen::Vector3d& acceleration) {
  if (times.size() != points.size() || times.size() < 2)
    throw std::invalid_argument("a ballistic fit needs at least 2 points");
  const int n = static_cast<int>(times.size());
  Eigen::MatrixXd a(n, 2);
  Eigen::MatrixXd b(n, 3);
  for (int i = 0; i < n; ++i) {
    a(i, 0) = 1.0;
    a(i, 1) = times[i];
    b.row(i) = (points[i] - 0.5 * acceleration * times[i] * times[i]).transpose();
  }
  const Eigen::MatrixXd x = a.colPivHouseholderQr().solve(b);
  BallisticFit fit;
  fit.position = x.row(0).transpose();
  fit.velocity = x.row(1).transpose();
  fit.acceleration = acceleration;
  return finish_fit(fit, times, points);
}

BallisticFit fit_ballistic_free(const std::vector<double>& times,
                                const std::vector<Eigen::Vector3d>& points) {
  if (times.size() != points.size() || times.size() < 3)
    throw std::invalid_argument("a free ballistic fit needs at least 3 points");
  const int n = static_cast<int>(times.size());
  Eigen::MatrixXd a(n, 3);
  Eigen::MatrixXd b(n, 3);
  for (int i = 0; i < n; ++i) {
    a(i, 0) = 1.0;
    a(i, 1) = times[i];
    a(i, 2) = 0.5 * times[i] * times[i];
    b.row(i) = points[i].transpose();
  }
  const Eigen::MatrixXd x = a.colPivHouseholderQr().solve(b);
  BallisticFit fit;
  fit.position = x.row(0).transpose();
  fit.velocity = x.row(1).transpose();
  fit.acceleration = x.row(2).transpose();
  return finish_fit(fit, times, points);
}

double ballistic_frame_time(double frame_time, double implied_gravity, double gravity) {
  if (!(implied_gravity > 0) || !(gravity > 0))
    throw std::invalid_argument("ballistic_frame_time: the accelerations must be > 0");
  return frame_time * std::sqrt(implied_gravity / gravity);
}

}  // namespace saltus
