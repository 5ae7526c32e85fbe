#include "saltus/math/vector_spline.h"

#include <stdexcept>
#include <string>

#include "saltus/math/banded_ldlt.h"

namespace saltus {

std::vector<Eigen::Vector3d> fit_vector_spline(const std::vector<double>& knots,
                                               const std::vector<double>& times,
                                               const std::vector<Eigen::Vector3d>& points,
                                               double smoothness_weight) {
  if (knots.size() < 8)
    throw std::invalid_argument("fit_vector_spline: a cubic knot vector needs at least 8 knots");
  if (times.size() != points.size())
    throw std::invalid_argument("fit_vector_spline: " + std::to_string(times.size()) +
                                " times but " + std::to_string(points.size()) + " points");
  if (times.empty()) throw std::invalid_argument("fit_vector_spline: no points to fit");
  if (smoothness_weight < 0.0)
    throw std::invalid_argument("fit_vector_spline: smoothness_weight must be non-negative");
  const int n = control_count(knots);
  const double t_begin = knots[3];
  const double t_end = knots[n];
  // Normal equations (AᵀA + λ DᵀD) C = Aᵀ P, A the basis matrix, D the second-difference
  // operator on control points; the three coordinates share the matrix. A sample touches 4
  // consecutive control points, a difference 3: the matrix has 3 sub-diagonals.
  BandedLdlt normal(n, 3);
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(n, 3);
  for (std::size_t i = 0; i < times.size(); ++i) {
    const double t = times[i];
    if (!(t >= t_begin && t <= t_end))
      throw std::invalid_argument("fit_vector_spline: time " + std::to_string(t) +
                                  " outside the knot range [" + std::to_string(t_begin) + ", " +
                                  std::to_string(t_end) + "]");
    const SpanBasis<double> basis = cubic_basis(knots, t);
    const int first = basis.first_control();
    for (int a = 0; a < 4; ++a) {
      for (int b = 0; b <= a; ++b)
        normal(first + a, first + b) += basis.value[0][a] * basis.value[0][b];
      rhs.row(first + a) += basis.value[0][a] * points[i].transpose();
    }
  }
  const double stencil[3] = {1.0, -2.0, 1.0};
  for (int j = 1; j + 1 < n; ++j) {
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b <= a; ++b)
        normal(j - 1 + a, j - 1 + b) += smoothness_weight * stencil[a] * stencil[b];
  }
  // A (numerically) zero pivot means some combination of control points is seen by neither the
  // samples nor the regulariser: too few samples and no smoothness weight.
  const bool factorised = normal.factorize();
  const Eigen::VectorXd& pivots = normal.pivots();
  if (!factorised || !(pivots.minCoeff() > 1e-14 * pivots.maxCoeff()))
    throw std::invalid_argument(
        "fit_vector_spline: the control points are not determined (too few samples for the "
        "knots and no smoothness weight)");
  const Eigen::MatrixXd solution = normal.solve(rhs);
  std::vector<Eigen::Vector3d> control(n);
  for (int j = 0; j < n; ++j)
    control[j] = solution.row(j).transpose();
  return control;
}

}  // namespace saltus
