#pragma once
/// @file
/// The lower band that holds the optimiser's Hessian, and the Gauss–Newton updates every term
/// adds into it. A control variable couples with the controls at most 3 indices below its own
/// (they share a knot span) and with every time variable; a time variable couples with every
/// variable before it. Every term's curvature must lie inside this band: that is the sparsity
/// contract of the objective terms and constraint blocks.

#include <vector>

#include "saltus/optim/root_wrench_derivatives.h"
#include "saltus/optim/trajectory_layout.h"

namespace saltus {

class HessianBand {
 public:
  HessianBand() = default;
  explicit HessianBand(const TrajectoryLayout& layout);

  int size() const { return static_cast<int>(first_column_.size()); }
  int nonzeros() const { return nonzeros_; }
  /// Row and column of every entry, in value order (Ipopt's triplet structure).
  void structure(int* rows, int* columns) const;
  /// Position of entry (row, column), either order, in the value array.
  int index(int row, int column) const {
    if (column > row) std::swap(row, column);
    return static_cast<int>(row_start_[row] + (column - first_column_[row]));
  }
  int first_column(int row) const { return first_column_[row]; }

  /// values += weight · JᵀJ of a local Jacobian, over its non-zero control columns only (a
  /// keyframe quantity depends on one curve, 12 of the block's columns).
  template <int Rows>
  void add_gauss_newton(const LocalJacobian<Rows>& jac, double weight, double* values) const;

  /// values += the lower triangle of a dense symmetric block over one knot span's local
  /// variables: `width` contiguous controls from `first_control`, then `time_count` time slots
  /// (x indices `time_variable`), in that order.
  void add_span_block(const Eigen::MatrixXd& block, int first_control, int width, int time_count,
                      const std::array<int, kMaxLocalTimes>& time_variable, double* values) const;

  /// sᵀ·H·s for a Hessian stored as this band's values (the damping's model of a step): a dot
  /// product per stored row, which vectorises, instead of the scatter a full H·s needs.
  double quadratic_form(const std::vector<double>& values, const double* s) const;

 private:
  std::vector<int> first_column_;  ///< per row: the first column inside the band
  std::vector<long> row_start_;    ///< per row: its first entry in the value array (size + 1)
  int nonzeros_ = 0;
};

}  // namespace saltus
