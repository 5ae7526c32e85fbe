#include "saltus/math/banded_ldlt.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace saltus {

BandedLdlt::BandedLdlt(int n, int bandwidth)
    : band_(Eigen::MatrixXd::Zero(std::max(bandwidth, 0) + 1, std::max(n, 0))) {
  if (n < 0 || bandwidth < 0) throw std::invalid_argument("BandedLdlt: negative size");
}

bool BandedLdlt::factorize() {
  const int n = size();
  const int b = bandwidth();
  pivots_.resize(n);
  for (int j = 0; j < n; ++j) {
    double d = band_(0, j);
    for (int k = std::max(0, j - b); k < j; ++k) {
      const double l = band_(j - k, k);
      d -= l * l * pivots_[k];
    }
    if (!(d > 0.0) || !std::isfinite(d)) {
      pivots_.conservativeResize(j);
      return false;
    }
    pivots_[j] = d;
    band_(0, j) = d;
    for (int i = j + 1; i <= std::min(n - 1, j + b); ++i) {
      double s = band_(i - j, j);
      for (int k = std::max(0, i - b); k < j; ++k)
        s -= band_(i - k, k) * band_(j - k, k) * pivots_[k];
      band_(i - j, j) = s / d;
    }
  }
  return true;
}

Eigen::MatrixXd BandedLdlt::solve(const Eigen::MatrixXd& rhs) const {
  const int n = size();
  const int b = bandwidth();
  if (rhs.rows() != n || pivots_.size() != n)
    throw std::invalid_argument("BandedLdlt::solve: not factorised, or a wrong right-hand side");
  Eigen::MatrixXd x = rhs;
  for (int i = 0; i < n; ++i)  // L·y = rhs
    for (int k = std::max(0, i - b); k < i; ++k)
      x.row(i) -= band_(i - k, k) * x.row(k);
  for (int i = n - 1; i >= 0; --i) {  // D·Lᵀ·x = y
    x.row(i) /= pivots_[i];
    for (int k = i + 1; k <= std::min(n - 1, i + b); ++k)
      x.row(i) -= band_(k - i, i) * x.row(k);
  }
  return x;
}

}  // namespace saltus
