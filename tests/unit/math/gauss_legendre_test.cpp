// Gauss rules on [0, 1] (math/gauss_legendre.h) against their defining properties and the
// textbook rules. Legendre: n nodes integrate every monomial up to degree 2n − 1 exactly and
// miss t^(2n) by the remainder formula's amount; the 1-, 2- and 3-point rules are the closed
// forms (midpoint; 1/2 ± √3/6; 1/2 ± √15/10 with weights 5/18, 4/9, 5/18). Lobatto: both ends
// are nodes, exact up to degree 2n − 3, t^(2n − 2) missed by its remainder; the 2-, 3- and
// 4-point rules are the trapezoid, Simpson and 1/2 ± √5/10 with weights 1/12, 5/12.

#include "saltus/math/gauss_legendre.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace saltus {
namespace {

double integrate_power(const QuadratureRule& rule, int power) {
  double sum = 0.0;
  for (std::size_t i = 0; i < rule.nodes.size(); ++i)
    sum += rule.weights[i] * std::pow(rule.nodes[i], power);
  return sum;
}

TEST(GaussLegendre, IntegratesPolynomialsUpToDegreeTwoNMinusOneExactly) {
  for (int n = 1; n <= 12; ++n) {
    const QuadratureRule rule = gauss_legendre(n);
    ASSERT_EQ(static_cast<int>(rule.nodes.size()), n);
    ASSERT_EQ(static_cast<int>(rule.weights.size()), n);
    for (int i = 0; i < n; ++i) {
      EXPECT_GT(rule.nodes[i], 0.0);
      EXPECT_LT(rule.nodes[i], 1.0);
      EXPECT_GT(rule.weights[i], 0.0);
      if (i > 0) {
        EXPECT_GT(rule.nodes[i], rule.nodes[i - 1]);
      }
      // Symmetric about 1/2.
      EXPECT_NEAR(rule.nodes[i] + rule.nodes[n - 1 - i], 1.0, 1e-15);
      EXPECT_NEAR(rule.weights[i], rule.weights[n - 1 - i], 1e-15);
    }
    for (int power = 0; power <= 2 * n - 1; ++power)
      EXPECT_NEAR(integrate_power(rule, power), 1.0 / (power + 1), 1e-14)
          << "n=" << n << " t^" << power;
    // t^(2n): its 2n-th derivative is the constant (2n)!, so the remainder formula is exact:
    // ∫ − Q = (n!)⁴ / ((2n + 1)·((2n)!)²).
    const double miss =
        std::pow(std::tgamma(n + 1.0), 4) / ((2 * n + 1) * std::pow(std::tgamma(2 * n + 1.0), 2));
    EXPECT_NEAR(1.0 / (2 * n + 1) - integrate_power(rule, 2 * n), miss, 1e-3 * miss + 1e-16)
        << "n=" << n;
  }
}

TEST(GaussLegendre, SmallRulesAreTheClosedForms) {
  const QuadratureRule one = gauss_legendre(1);
  EXPECT_DOUBLE_EQ(one.nodes[0], 0.5);
  EXPECT_DOUBLE_EQ(one.weights[0], 1.0);
  const QuadratureRule two = gauss_legendre(2);
  EXPECT_NEAR(two.nodes[0], 0.5 - std::sqrt(3.0) / 6, 1e-15);
  EXPECT_NEAR(two.weights[0], 0.5, 1e-15);
  const QuadratureRule three = gauss_legendre(3);
  EXPECT_NEAR(three.nodes[0], 0.5 - std::sqrt(15.0) / 10, 1e-15);
  EXPECT_NEAR(three.nodes[1], 0.5, 1e-15);
  EXPECT_NEAR(three.weights[0], 5.0 / 18, 1e-15);
  EXPECT_NEAR(three.weights[1], 4.0 / 9, 1e-15);
  EXPECT_THROW(gauss_legendre(0), std::invalid_argument);
}

TEST(GaussLobatto, IncludesTheEndsAndIntegratesUpToDegreeTwoNMinusThreeExactly) {
  for (int n = 2; n <= 12; ++n) {
    const QuadratureRule rule = gauss_lobatto(n);
    ASSERT_EQ(static_cast<int>(rule.nodes.size()), n);
    ASSERT_EQ(static_cast<int>(rule.weights.size()), n);
    EXPECT_EQ(rule.nodes.front(), 0.0) << "n=" << n;
    EXPECT_EQ(rule.nodes.back(), 1.0) << "n=" << n;
    double total = 0.0;
    for (int i = 0; i < n; ++i) {
      total += rule.weights[i];
      EXPECT_GT(rule.weights[i], 0.0);
      if (i > 0) {
        EXPECT_GT(rule.nodes[i], rule.nodes[i - 1]) << "n=" << n;
      }
      EXPECT_NEAR(rule.nodes[i] + rule.nodes[n - 1 - i], 1.0, 1e-15);
      EXPECT_NEAR(rule.weights[i], rule.weights[n - 1 - i], 1e-15);
    }
    // The end weights are 1/(n(n − 1)) on [0, 1] (2/(n(n − 1)) on [−1, 1]).
    EXPECT_NEAR(rule.weights.front(), 1.0 / (n * (n - 1.0)), 1e-15) << "n=" << n;
    EXPECT_NEAR(total, 1.0, 1e-14) << "n=" << n;
    for (int power = 0; power <= 2 * n - 3; ++power)
      EXPECT_NEAR(integrate_power(rule, power), 1.0 / (power + 1), 1e-14)
          << "n=" << n << " t^" << power;
    // t^(2n − 2), by the exact remainder: ∫ − Q = −n(n − 1)³((n − 2)!)⁴ / ((2n − 1)((2n − 2)!)²)
    // (the trapezoid's −1/6 for t², Simpson's −1/120 for t⁴).
    const double miss = -n * std::pow(n - 1.0, 3) * std::pow(std::tgamma(n - 1.0), 4) /
                        ((2 * n - 1) * std::pow(std::tgamma(2 * n - 1.0), 2));
    EXPECT_NEAR(1.0 / (2 * n - 1) - integrate_power(rule, 2 * n - 2), miss,
                1e-3 * std::abs(miss) + 1e-16)
        << "n=" << n;
  }
}

TEST(GaussLobatto, SmallRulesAreTheClosedForms) {
  const QuadratureRule two = gauss_lobatto(2);  // trapezoid
  EXPECT_DOUBLE_EQ(two.weights[0], 0.5);
  EXPECT_DOUBLE_EQ(two.weights[1], 0.5);
  const QuadratureRule three = gauss_lobatto(3);  // Simpson
  EXPECT_NEAR(three.nodes[1], 0.5, 1e-15);
  EXPECT_NEAR(three.weights[0], 1.0 / 6, 1e-15);
  EXPECT_NEAR(three.weights[1], 2.0 / 3, 1e-15);
  const QuadratureRule four = gauss_lobatto(4);
  EXPECT_NEAR(four.nodes[1], 0.5 - std::sqrt(5.0) / 10, 1e-15);
  EXPECT_NEAR(four.nodes[2], 0.5 + std::sqrt(5.0) / 10, 1e-15);
  EXPECT_NEAR(four.weights[0], 1.0 / 12, 1e-15);
  EXPECT_NEAR(four.weights[1], 5.0 / 12, 1e-15);
  EXPECT_THROW(gauss_lobatto(1), std::invalid_argument);
}

}  // namespace
}  // namespace saltus
