#include "saltus/evaluation/rotation_metrics.h"

#include <Eigen/Cholesky>
#include <cmath>
#include <stdexcept>

namespace saltus {

Eigen::Matrix3d whole_body_inertia_about_com(const BodyModel& model, const SampleRecord& sample) {
  const std::size_t n = model.segments.size();
  if (sample.segment_position.size() != n || sample.segment_rotation.size() != n)
    throw std::invalid_argument("sample does not hold one pose per model segment");
  Eigen::Matrix3d total = Eigen::Matrix3d::Zero();
  for (std::size_t i = 0; i < n; ++i) {
    const Segment& s = model.segments[i];
    const Eigen::Matrix3d world_from_segment = sample.segment_rotation[i].toRotationMatrix();
    const Eigen::Vector3d com_world = sample.segment_position[i] + world_from_segment * s.com;
    const Eigen::Vector3d r = com_world - sample.com;
    total += world_from_segment * s.inertia * world_from_segment.transpose();
    total += s.mass * (r.squaredNorm() * Eigen::Matrix3d::Identity() - r * r.transpose());
  }
  return total;
}

std::vector<RotationSample> rotation_metrics(const BodyModel& model,
                                             const std::vector<SampleRecord>& samples) {
  std::vector<RotationSample> out;
  out.reserve(samples.size());
  for (std::size_t k = 0; k < samples.size(); ++k) {
    const SampleRecord& record = samples[k];
    RotationSample r;
    r.time = record.time;
    r.angular_momentum = record.angular_momentum;
    r.inertia = whole_body_inertia_about_com(model, record);
    r.somersault_inertia = r.inertia(0, 0);
    // The whole-body inertia of a body with positive segment masses is positive definite.
    r.angular_velocity = r.inertia.ldlt().solve(r.angular_momentum);
    r.somersault_rate = r.angular_velocity.x();
    const Eigen::Vector3d long_axis = record.segment_rotation[0] * Eigen::Vector3d::UnitY();
    r.twist_rate = r.angular_velocity.dot(long_axis);
    if (k > 0) {
      const RotationSample& previous = out.back();
      const double dt = r.time - previous.time;
      r.somersaults = previous.somersaults +
                      0.5 * dt * (previous.somersault_rate + r.somersault_rate) / (2.0 * M_PI);
      r.twists = previous.twists + 0.5 * dt * (previous.twist_rate + r.twist_rate) / (2.0 * M_PI);
    }
    out.push_back(r);
  }
  return out;
}

}  // namespace saltus
