// math/banded_ldlt: the band solver behind the linear-cost spline fits (issue 16 item 8),
// against Eigen's dense LDLT on seeded families of band matrices.

#include "saltus/math/banded_ldlt.h"

#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <random>

namespace saltus {
namespace {

TEST(BandedLdlt, SolvesLikeADenseFactorisation) {
  std::mt19937 rng(16);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 60; ++trial) {
    const int n = 1 + static_cast<int>(rng() % 80);
    const int b = static_cast<int>(rng() % 12);
    // A = Bᵀ B + δ I with B banded: positive definite with bandwidth <= b.
    Eigen::MatrixXd factor = Eigen::MatrixXd::Zero(n, n);
    for (int i = 0; i < n; ++i)
      for (int j = std::max(0, i - b / 2); j <= std::min(n - 1, i + b / 2); ++j)
        factor(i, j) = u(rng);
    Eigen::MatrixXd dense = factor.transpose() * factor;
    dense.diagonal().array() += 1e-3;
    BandedLdlt band(n, b);
    for (int i = 0; i < n; ++i)
      for (int j = std::max(0, i - b); j <= i; ++j)
        band(i, j) = dense(i, j);
    ASSERT_TRUE(band.factorize()) << "n " << n << " b " << b;
    const Eigen::MatrixXd rhs = Eigen::MatrixXd::Random(n, 3);
    const Eigen::MatrixXd x = band.solve(rhs);
    const Eigen::MatrixXd reference = dense.ldlt().solve(rhs);
    EXPECT_LT((dense * x - rhs).norm(), 1e-9 * (1 + rhs.norm() * dense.norm()))
        << "n " << n << " b " << b;
    EXPECT_LT((x - reference).norm(), 1e-6 * (1 + reference.norm()));
    EXPECT_EQ(band.pivots().size(), n);
    EXPECT_GT(band.pivots().minCoeff(), 0.0);
  }
}

TEST(BandedLdlt, RefusesIndefiniteAndSingularMatrices) {
  BandedLdlt indefinite(3, 1);
  indefinite(0, 0) = 1;
  indefinite(1, 0) = 2;
  indefinite(1, 1) = 1;  // [[1, 2], [2, 1]] block: eigenvalues 3 and -1
  indefinite(2, 2) = 1;
  EXPECT_FALSE(indefinite.factorize());
  BandedLdlt singular(2, 1);
  singular(0, 0) = 1;
  singular(1, 0) = 1;
  singular(1, 1) = 1;
  EXPECT_FALSE(singular.factorize());
  BandedLdlt damped = singular;
  damped.add_to_diagonal(1e-3);
  EXPECT_TRUE(damped.factorize());
}

}  // namespace
}  // namespace saltus
