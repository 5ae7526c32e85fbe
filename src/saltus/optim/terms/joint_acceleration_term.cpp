#include "saltus/optim/terms/joint_acceleration_term.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "saltus/math/bspline_basis.h"

namespace saltus {

double joint_subtree_inertia(const BodyModel& model, int segment) {
  // Standing: every rotation identity, so a segment's origin is its parent's plus its joint
  // position, and every frame is the world's.
  std::vector<Eigen::Vector3d> origin(model.size(), Eigen::Vector3d::Zero());
  for (int i = 1; i < model.size(); ++i)
    origin[i] = origin[model.segments[i].parent] + model.segments[i].joint_position;
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();
  for (int i = segment; i < model.size(); ++i) {
    int a = i;
    while (a > segment)
      a = model.segments[a].parent;
    if (a != segment) continue;  // not below the joint
    const Segment& s = model.segments[i];
    const Eigen::Vector3d r = origin[i] + s.com - origin[segment];
    inertia +=
        s.inertia + s.mass * (r.squaredNorm() * Eigen::Matrix3d::Identity() - r * r.transpose());
  }
  return Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(inertia).eigenvalues().maxCoeff();
}

JointAccelerationTerm::JointAccelerationTerm(const TrajectoryLayout& layout, const BodyModel& model,
                                             const std::vector<double>& knots, double weight)
    : layout_(layout) {
  const double duration = knots.back() - knots.front();
  // Two-point Gauss–Legendre on [0, 1]: exact for the square of δ̈, linear on a span.
  const double xi[2] = {0.5 - 0.5 / std::sqrt(3.0), 0.5 + 0.5 / std::sqrt(3.0)};
  for (int s = 3; s + 4 < static_cast<int>(knots.size()); ++s) {
    const double h = knots[s + 1] - knots[s];
    if (!(h > 0) || !(duration > 0)) continue;
    for (double x : xi) {
      const SpanBasis<double> basis = cubic_basis_on_span(knots, s, knots[s] + x * h);
      Point p;
      p.first_control = basis.first_control();
      for (int j = 0; j < 4; ++j)
        p.coefficient[j] = std::sqrt(0.5 * h / duration) * basis.value[2][j];
      points_.push_back(p);
    }
  }
  joint_scale_.assign(layout.segment_count, 0.0);
  for (int k = 1; k < layout.segment_count && k < model.size(); ++k)
    joint_scale_[k] =
        std::sqrt(weight) * std::max(joint_subtree_inertia(model, k), kMinJointInertia);
}

std::vector<double> JointAccelerationTerm::evaluate(const double* x, double* gradient) const {
  std::vector<double> r;
  r.reserve(points_.size() * 3 * layout_.segment_count);
  for (const Point& p : points_)
    for (int k = 1; k < layout_.segment_count; ++k)
      for (int d = 0; d < 3; ++d) {
        double value = 0.0;
        for (int j = 0; j < 4; ++j)
          value += p.coefficient[j] * x[layout_.control_variable(1 + k, p.first_control + j, d)];
        value *= joint_scale_[k];
        if (gradient)
          for (int j = 0; j < 4; ++j)
            gradient[layout_.control_variable(1 + k, p.first_control + j, d)] +=
                2.0 * value * joint_scale_[k] * p.coefficient[j];
        r.push_back(value);
      }
  return r;
}

double JointAccelerationTerm::value(NlpEvaluations& at) {
  double sum = 0.0;
  for (double r : evaluate(at.x(), nullptr))
    sum += r * r;
  return sum;
}

void JointAccelerationTerm::add_gradient(NlpEvaluations& at, double* gradient) {
  evaluate(at.x(), gradient);
}

void JointAccelerationTerm::add_curvature(NlpEvaluations&, double factor, const HessianBand& band,
                                          double* values) {
  for (const Point& p : points_)
    for (int k = 1; k < layout_.segment_count; ++k) {
      const double scale = 2.0 * factor * joint_scale_[k] * joint_scale_[k];
      for (int d = 0; d < 3; ++d)
        for (int a = 0; a < 4; ++a)
          for (int b = 0; b <= a; ++b) {
            const int row = layout_.control_variable(1 + k, p.first_control + a, d);
            const int column = layout_.control_variable(1 + k, p.first_control + b, d);
            values[band.index(row, column)] += scale * p.coefficient[a] * p.coefficient[b];
          }
    }
}

std::vector<double> JointAccelerationTerm::residuals(NlpEvaluations& at) {
  return evaluate(at.x(), nullptr);
}

}  // namespace saltus
