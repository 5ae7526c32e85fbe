#pragma once
/// @file
/// Symmetric band matrices and their L·D·Lᵀ factorisation in O(n·b²) time and O(n·b) memory
/// (Golub & Van Loan, Matrix Computations, 4th ed., §4.3.5). The spline fits are banded: a time
/// sample touches 4 consecutive control points, so their normal matrices have 3 control points'
/// worth of sub-diagonals, and a dense factorisation made the fit cubic in the keyframe count.

#include <Eigen/Core>

namespace saltus {

class BandedLdlt {
 public:
  /// An n×n symmetric matrix whose non-zero entries lie within `bandwidth` of the diagonal; all
  /// zero to start with.
  BandedLdlt(int n, int bandwidth);

  int size() const { return static_cast<int>(band_.cols()); }
  int bandwidth() const { return static_cast<int>(band_.rows()) - 1; }

  /// Entry (i, j) of the lower band: i >= j and i - j <= bandwidth() (the upper half mirrors it).
  double& operator()(int i, int j) { return band_(i - j, j); }
  double operator()(int i, int j) const { return band_(i - j, j); }
  /// Adds `value` to every diagonal entry (Levenberg-Marquardt damping).
  void add_to_diagonal(double value) { band_.row(0).array() += value; }
  /// The largest diagonal entry (before factorize()).
  double max_diagonal() const { return band_.row(0).maxCoeff(); }

  /// Factorises in place as L·D·Lᵀ without pivoting, which is stable for positive definite
  /// matrices. Returns false, and stops, at the first pivot that is not positive and finite
  /// (an indefinite or singular matrix).
  bool factorize();
  /// D after a successful factorize(): its smallest-to-largest ratio measures how close to
  /// singular the matrix is.
  const Eigen::VectorXd& pivots() const { return pivots_; }
  /// Solves A·x = b after a successful factorize(); b has size() rows and any number of columns.
  Eigen::MatrixXd solve(const Eigen::MatrixXd& b) const;

 private:
  Eigen::MatrixXd band_;  ///< band_(k, j) = A(j + k, j); after factorize(), L below and D on row 0
  Eigen::VectorXd pivots_;
};

}  // namespace saltus
