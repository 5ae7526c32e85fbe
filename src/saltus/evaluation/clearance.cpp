#include "saltus/evaluation/clearance.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>

#include "saltus/base/constants.h"
#include "saltus/body/segment_names.h"

namespace saltus {

namespace {

/// Signed distance of a point from an axis-aligned box given by its corners; negative inside.
double box_distance(const Eigen::Vector3d& p, const Eigen::Vector3d& low,
                    const Eigen::Vector3d& high) {
  const Eigen::Vector3d centre = 0.5 * (low + high), half = 0.5 * (high - low);
  const Eigen::Vector3d q = (p - centre).cwiseAbs() - half;
  return q.cwiseMax(0.0).norm() + std::min(q.maxCoeff(), 0.0);
}

/// Signed distance in the plane of (|x|, |z|) from the rectangle of half sizes (a, b) centred on
/// the origin; negative inside.
double rectangle_distance(double x, double z, double a, double b) {
  const double qx = std::abs(x) - a, qz = std::abs(z) - b;
  return std::hypot(std::max(qx, 0.0), std::max(qz, 0.0)) + std::min(std::max(qx, qz), 0.0);
}

/// How far inside the bed's edge a point of the trampoline frame lies, horizontally (negative:
/// over the frame or beyond it).
double inside_bed(const Eigen::Vector3d& local) {
  return -rectangle_distance(local.x(), local.z(), 0.5 * kBedWidth, 0.5 * kBedLength);
}

double trampoline_distance(const Eigen::Vector3d& local) {
  // The ring: inside the frame's outer rectangle, outside the bed's.
  const double outer =
      rectangle_distance(local.x(), local.z(), 0.5 * kFrameWidth, 0.5 * kFrameLength);
  const double inner = -inside_bed(local);
  const double ring = std::max(outer, -inner);  // the intersection of "in outer" and "out of bed"
  const double top = kFrameTop, bottom = kFrameTop - kFrameThickness;
  const double slab = std::abs(local.y() - 0.5 * (top + bottom)) - 0.5 * kFrameThickness;
  return std::hypot(std::max(ring, 0.0), std::max(slab, 0.0)) + std::min(std::max(ring, slab), 0.0);
}

std::vector<BodyPoint> body_points(const BodyModel& model, const SampleRecord& sample) {
  std::vector<BodyPoint> out;
  const std::size_t n = std::min(model.segments.size(), sample.segment_position.size());
  for (std::size_t i = 0; i < n; ++i)
    for (bool end : {false, true})
      out.push_back({static_cast<int>(i), end});
  return out;
}

/// Body line from the middle of the feet's ends to the head (the thorax's end).
Eigen::Vector3d body_line(const BodyModel& model, const SampleRecord& s, int foot_l, int foot_r,
                          int thorax) {
  const Eigen::Vector3d feet = 0.5 * (body_point_position(model, s, {foot_l, true}) +
                                      body_point_position(model, s, {foot_r, true}));
  return body_point_position(model, s, {thorax, true}) - feet;
}

}  // namespace

Eigen::Vector3d body_point_position(const BodyModel& model, const SampleRecord& sample,
                                    const BodyPoint& point) {
  const auto i = static_cast<std::size_t>(point.segment);
  const Eigen::Vector3d& origin = sample.segment_position.at(i);
  if (!point.end) return origin;
  return origin +
         sample.segment_rotation.at(i) * Eigen::Vector3d(0, model.segments.at(i).shape.length, 0);
}

std::string body_point_label(const BodyModel& model, const BodyPoint& point) {
  const Segment& segment = model.segments.at(static_cast<std::size_t>(point.segment));
  if (!point.end) {
    if (segment.parent < 0) return segment_label(segment.name) + " (the body's origin)";
    return joint_label(segment.joint);
  }
  // The bundled model's foot ends at the toes, its forearm carries the hand, its thorax the head.
  static const std::map<std::string, std::string> kEnds = {{"foot_l", "left toes"},
                                                           {"foot_r", "right toes"},
                                                           {"forearm_l", "left hand"},
                                                           {"forearm_r", "right hand"},
                                                           {"thorax", "head"}};
  const auto it = kEnds.find(segment.name);
  return it != kEnds.end() ? it->second : "end of the " + segment_label(segment.name);
}

double apparatus_distance(ApparatusKind kind, const Eigen::Vector3d& local, double drop) {
  if (kind == ApparatusKind::kTrampoline) return trampoline_distance(local);
  const Eigen::Vector3d low(-0.5 * kPlatformWidth, -drop, kPlatformEdgeAhead - kPlatformLength);
  const Eigen::Vector3d high(0.5 * kPlatformWidth, 0.0, kPlatformEdgeAhead);
  return box_distance(local, low, high);
}

ApparatusClearance apparatus_clearance(const BodyModel& model, const Apparatus& apparatus,
                                       const std::vector<SampleRecord>& samples) {
  if (samples.empty()) throw std::invalid_argument("apparatus_clearance: no samples");
  ApparatusClearance out;
  out.kind = apparatus.kind;
  const Eigen::Affine3d apparatus_from_world = world_from_apparatus(apparatus).inverse();
  const double drop = apparatus.takeoff_height - apparatus.landing_height;
  std::size_t from = 0;
  if (apparatus.kind == ApparatusKind::kPlatform)
    for (std::size_t k = 1; k < samples.size(); ++k)
      if (samples[k].com.y() > samples[from].com.y()) from = k;
  out.from_s = samples[from].time;
  out.min_distance_m = std::numeric_limits<double>::infinity();
  Eigen::Vector3d closest = Eigen::Vector3d::Zero();
  for (std::size_t k = 0; k < samples.size(); ++k) {
    double smallest = std::numeric_limits<double>::infinity();
    for (const BodyPoint& p : body_points(model, samples[k])) {
      const Eigen::Vector3d local =
          apparatus_from_world * body_point_position(model, samples[k], p);
      const double d = apparatus_distance(apparatus.kind, local, drop);
      smallest = std::min(smallest, d);
      if (k >= from && d < out.min_distance_m) {
        out.min_distance_m = d;
        out.time_s = samples[k].time;
        out.segment = model.segments[static_cast<std::size_t>(p.segment)].name;
        out.segment_end = p.end;
        out.point = body_point_label(model, p);
        closest = local;
      }
    }
    out.times.push_back(samples[k].time);
    out.distance.push_back(smallest);
  }
  if (apparatus.kind == ApparatusKind::kPlatform) {
    out.edge_m = kPlatformEdgeAhead - closest.z();
    out.vertical_m = -closest.y();
  } else {
    out.edge_m = inside_bed(closest);
    out.vertical_m = closest.y() - kFrameTop;
  }
  out.collision = out.min_distance_m < 0.0;
  return out;
}

std::optional<DiveEntry> dive_entry(const BodyModel& model, const Apparatus& apparatus,
                                    const std::vector<SampleRecord>& samples) {
  if (samples.empty()) throw std::invalid_argument("dive_entry: no samples");
  const int foot_l = model.segment_index("foot_l"), foot_r = model.segment_index("foot_r");
  const int thorax = model.segment_index("thorax");
  if (apparatus.kind != ApparatusKind::kPlatform || foot_l < 0 || foot_r < 0 || thorax < 0)
    return std::nullopt;
  // The first sample whose lowest point is at the water (the last one is, by apparatus_for).
  std::size_t k = 0;
  while (k + 1 < samples.size() && lowest_body_point(model, samples[k]) > apparatus.landing_height)
    ++k;
  double f = 1.0;  // weight of sample k against k - 1
  if (k > 0) {
    const double above = lowest_body_point(model, samples[k - 1]) - apparatus.landing_height;
    const double below = apparatus.landing_height - lowest_body_point(model, samples[k]);
    f = above + below > 0.0 ? above / (above + below) : 1.0;
  }
  const SampleRecord& b = samples[k];
  const SampleRecord& a = samples[k > 0 ? k - 1 : 0];
  DiveEntry out;
  out.time_s = (1.0 - f) * a.time + f * b.time;
  out.com_height_m = (1.0 - f) * a.com.y() + f * b.com.y() - apparatus.landing_height;
  const Eigen::Vector3d line = (1.0 - f) * body_line(model, a, foot_l, foot_r, thorax) +
                               f * body_line(model, b, foot_l, foot_r, thorax);
  const double horizontal = std::hypot(line.x(), line.z());
  out.angle_to_vertical_deg = std::atan2(horizontal, std::abs(line.y())) * kDegreesPerRadian;
  out.head_first = line.y() < 0.0;
  out.vertical = out.angle_to_vertical_deg <= kVerticalEntryToleranceDeg;
  BodyPoint first{0, false};
  double lowest = std::numeric_limits<double>::infinity();
  for (const BodyPoint& p : body_points(model, b)) {
    const double y = body_point_position(model, b, p).y();
    if (y < lowest) {
      lowest = y;
      first = p;
    }
  }
  out.first_contact = body_point_label(model, first);
  return out;
}

}  // namespace saltus
