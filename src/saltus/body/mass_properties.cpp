#include "saltus/body/mass_properties.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "saltus/base/text_format.h"
#include "saltus/body/segment_names.h"

namespace saltus {

RigidMass rigid_mass_from_radii(double mass, const Eigen::Vector3d& com,
                                const Eigen::Vector3d& radii) {
  RigidMass piece;
  piece.mass = mass;
  piece.com = com;
  piece.inertia = (mass * radii.cwiseProduct(radii)).asDiagonal();
  return piece;
}

namespace {

/// Inertia about `point` of a piece whose inertia about its own CoM is known (parallel axis).
Eigen::Matrix3d inertia_about(const RigidMass& piece, const Eigen::Vector3d& point) {
  const Eigen::Vector3d d = piece.com - point;
  return piece.inertia +
         piece.mass * (d.squaredNorm() * Eigen::Matrix3d::Identity() - d * d.transpose());
}

}  // namespace

RigidMass combine(const RigidMass& a, const RigidMass& b) {
  RigidMass sum;
  sum.mass = a.mass + b.mass;
  if (!(sum.mass > 0.0))
    throw std::invalid_argument("combine: pieces of " + message_number(a.mass) + " and " +
                                message_number(b.mass) + " kg have no mass together");
  sum.com = (a.mass * a.com + b.mass * b.com) / sum.mass;
  sum.inertia = inertia_about(a, sum.com) + inertia_about(b, sum.com);
  return sum;
}

std::vector<Eigen::Vector3d> standing_origins(const BodyModel& model) {
  std::vector<Eigen::Vector3d> origins(model.segments.size(), Eigen::Vector3d::Zero());
  for (std::size_t i = 0; i < model.segments.size(); ++i) {
    const Segment& s = model.segments[i];
    if (s.parent >= 0) origins[i] = origins[static_cast<std::size_t>(s.parent)] + s.joint_position;
  }
  return origins;
}

StandingBody standing_body(const BodyModel& model) {
  if (model.segments.empty()) throw std::invalid_argument("standing_body: the model is empty");
  const std::vector<Eigen::Vector3d> origins = standing_origins(model);
  StandingBody out;
  out.lowest_y = origins[0].y();
  out.highest_y = origins[0].y();
  for (std::size_t i = 0; i < model.segments.size(); ++i) {
    const Segment& s = model.segments[i];
    RigidMass piece;
    piece.mass = s.mass;
    piece.com = origins[i] + s.com;
    piece.inertia = s.inertia;
    out.body = i == 0 ? piece : combine(out.body, piece);
    // The segment's extent: its origin and the far end of its drawing shape along its y axis.
    for (const double y : {origins[i].y(), origins[i].y() + s.shape.length}) {
      out.lowest_y = std::min(out.lowest_y, y);
      out.highest_y = std::max(out.highest_y, y);
    }
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(out.body.inertia,
                                                             Eigen::EigenvaluesOnly);
  out.principal_moments = eigen.eigenvalues();
  return out;
}

ModelSummary summarize_model(const BodyModel& model) {
  ModelSummary out;
  out.name = model.name;
  out.source = model.source;
  out.total_mass = model.total_mass();
  out.standing = standing_body(model);
  for (std::size_t i = 0; i < model.segments.size(); ++i) {
    const Segment& s = model.segments[i];
    SegmentSummary row;
    row.name = s.name;
    row.label = segment_label(s.name);
    row.mass = s.mass;
    row.mass_percent = 100.0 * s.mass / out.total_mass;
    row.length = std::abs(s.shape.length);
    if (row.length == 0.0)
      for (const Segment& child : model.segments)
        if (child.parent == static_cast<int>(i))
          row.length = std::max(row.length, child.joint_position.norm());
    row.com = s.com;
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(s.inertia, Eigen::EigenvaluesOnly);
    row.principal_moments = eigen.eigenvalues();
    out.segments.push_back(row);
  }
  return out;
}

}  // namespace saltus
