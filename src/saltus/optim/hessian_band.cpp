#include "saltus/optim/hessian_band.h"

#include <algorithm>

namespace saltus {

HessianBand::HessianBand(const TrajectoryLayout& layout) {
  const int n = layout.size();
  first_column_.resize(n);
  row_start_.resize(n + 1);
  long total = 0;
  for (int r = 0; r < n; ++r) {
    if (r < layout.control_variable_count()) {
      const int control = r / layout.curve_block();
      first_column_[r] = std::max(0, control - 3) * layout.curve_block();
    } else {
      first_column_[r] = 0;
    }
    row_start_[r] = total;
    total += r - first_column_[r] + 1;
  }
  row_start_[n] = total;
  nonzeros_ = static_cast<int>(total);
}

void HessianBand::structure(int* rows, int* columns) const {
  long e = 0;
  for (int r = 0; r < size(); ++r)
    for (int c = first_column_[r]; c <= r; ++c, ++e) {
      rows[e] = r;
      columns[e] = c;
    }
}

template <int Rows>
void HessianBand::add_gauss_newton(const LocalJacobian<Rows>& jac, double weight,
                                   double* values) const {
  const int first = jac.first_control_variable;
  const int width = static_cast<int>(jac.control.cols());
  std::vector<int> used;
  for (int c = 0; c < width; ++c)
    if (!jac.control.col(c).isZero(0.0)) used.push_back(c);
  const int count = static_cast<int>(used.size());
  for (int a = 0; a < count; ++a) {
    const int ca = used[a];
    for (int b = 0; b <= a; ++b) {
      const int cb = used[b];
      values[index(first + ca, first + cb)] +=
          weight * jac.control.col(ca).dot(jac.control.col(cb));
    }
  }
  for (int p = 0; p < jac.time_count; ++p) {
    const int tv = jac.time_variable[p];
    for (int a = 0; a < count; ++a)
      values[index(tv, first + used[a])] += weight * jac.time.col(p).dot(jac.control.col(used[a]));
    for (int q = 0; q < jac.time_count; ++q)
      if (jac.time_variable[q] <= tv)
        values[index(tv, jac.time_variable[q])] += weight * jac.time.col(p).dot(jac.time.col(q));
  }
}

template void HessianBand::add_gauss_newton<3>(const LocalJacobian<3>&, double, double*) const;
template void HessianBand::add_gauss_newton<4>(const LocalJacobian<4>&, double, double*) const;

void HessianBand::add_span_block(const Eigen::MatrixXd& block, int first_control, int width,
                                 int time_count,
                                 const std::array<int, kMaxLocalTimes>& time_variable,
                                 double* values) const {
  // Controls are contiguous from `first_control`; time slot p is variable time_variable[p]
  // (beyond every control).
  for (int a = 0; a < width; ++a)
    Eigen::Map<Eigen::RowVectorXd>(values + index(first_control + a, first_control), a + 1) +=
        block.row(a).head(a + 1);
  for (int p = 0; p < time_count; ++p) {
    const int tv = time_variable[p];
    Eigen::Map<Eigen::RowVectorXd>(values + index(tv, first_control), width) +=
        block.row(width + p).head(width);
    for (int q = 0; q < time_count; ++q) {
      const int other = time_variable[q];
      // Row width + max(p, q) holds the pair in the lower triangle.
      if (other <= tv)
        values[index(tv, other)] += block(width + std::max(p, q), width + std::min(p, q));
    }
  }
}

double HessianBand::quadratic_form(const std::vector<double>& values, const double* s) const {
  const int n = size();
  double sum = 0.0;
  for (int r = 0; r < n; ++r) {
    const double* row = values.data() + row_start_[r];
    const int first = first_column_[r];
    double below_diagonal = 0.0;
    for (int c = first; c < r; ++c)
      below_diagonal += row[c - first] * s[c];
    sum += s[r] * (2.0 * below_diagonal + row[r - first] * s[r]);
  }
  return sum;
}

}  // namespace saltus
