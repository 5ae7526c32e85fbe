#include "saltus/evaluation/rotation_metrics.h"

#include <Eigen/Cholesky>
#include <cmath>
#include <stdexcept>

#include "saltus/base/constants.h"
#include "saltus/evaluation/yeadon_angles.h"

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
    out.push_back(r);
  }
  // Yeadon's angles of the root, and the turns counted by them from the first sample.
  std::vector<Eigen::Quaterniond> roots;
  for (const SampleRecord& record : samples)
    roots.push_back(record.segment_rotation.at(0));
  const std::vector<Eigen::Vector3d> angles = unwrapped_angles(roots);
  for (std::size_t k = 0; k < out.size(); ++k) {
    out[k].somersault_deg = angles[k][0] * kDegreesPerRadian;
    out[k].tilt_deg = angles[k][1] * kDegreesPerRadian;
    out[k].twist_deg = angles[k][2] * kDegreesPerRadian;
    out[k].somersaults = (angles[k][0] - angles[0][0]) / (2.0 * M_PI);
    out[k].twists = (angles[k][2] - angles[0][2]) / (2.0 * M_PI);
  }
  return out;
}

}  // namespace saltus
