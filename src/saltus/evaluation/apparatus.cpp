#include "saltus/evaluation/apparatus.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace saltus {

double lowest_body_point(const BodyModel& model, const SampleRecord& sample) {
  double lowest = std::numeric_limits<double>::infinity();
  const std::size_t n = std::min(model.segments.size(), sample.segment_position.size());
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector3d& origin = sample.segment_position[i];
    const Eigen::Vector3d end =
        origin + sample.segment_rotation[i] * Eigen::Vector3d(0, model.segments[i].shape.length, 0);
    lowest = std::min({lowest, origin.y(), end.y()});
  }
  return lowest;
}

Eigen::Affine3d world_from_apparatus(const Apparatus& a) {
  const double heading = std::atan2(a.direction.x(), a.direction.z());
  Eigen::Affine3d t = Eigen::Affine3d::Identity();
  t.translate(a.takeoff_point);
  t.rotate(Eigen::AngleAxisd(heading, Eigen::Vector3d::UnitY()));
  return t;
}

Apparatus apparatus_for(const BodyModel& model, const Takeoff& takeoff,
                        const std::vector<SampleRecord>& samples) {
  if (samples.empty()) throw std::invalid_argument("apparatus_for: no samples");
  const SampleRecord& first = samples.front();
  const SampleRecord& last = samples.back();
  Apparatus out;
  out.takeoff_height = lowest_body_point(model, first);
  const double end = lowest_body_point(model, last);
  out.kind =
      out.takeoff_height - end >= kDiveDrop ? ApparatusKind::kPlatform : ApparatusKind::kTrampoline;
  out.landing_height = out.kind == ApparatusKind::kPlatform ? end : out.takeoff_height;
  out.takeoff_point =
      Eigen::Vector3d(takeoff.com_position.x(), out.takeoff_height, takeoff.com_position.z());
  Eigen::Vector3d horizontal(takeoff.com_velocity.x(), 0.0, takeoff.com_velocity.z());
  if ((out.kind == ApparatusKind::kTrampoline || horizontal.norm() < 1e-6) &&
      !first.segment_rotation.empty())
    horizontal = first.segment_rotation.front() * Eigen::Vector3d::UnitZ();
  horizontal.y() = 0.0;
  if (horizontal.norm() > 1e-9) out.direction = horizontal.normalized();
  return out;
}

}  // namespace saltus
