#include "saltus/math/gauss_legendre.h"

#include <cmath>
#include <stdexcept>

#include "saltus/base/constants.h"

namespace saltus {

QuadratureRule gauss_legendre(int n) {
  if (n < 1) throw std::invalid_argument("a Gauss-Legendre rule needs at least one node");
  QuadratureRule rule;
  rule.nodes.resize(n);
  rule.weights.resize(n);
  // Roots of P_n on [−1, 1] by Newton from Tricomi's estimate; P_n and P_n' by the three-term
  // recurrence. Symmetric, so half are computed.
  for (int i = 0; i < (n + 1) / 2; ++i) {
    double x = std::cos(kPi * (i + 0.75) / (n + 0.5));
    double derivative = 1.0;
    for (int iteration = 0; iteration < 100; ++iteration) {
      double p0 = 1.0, p1 = x;
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      derivative = n * (x * p1 - p0) / (x * x - 1.0);
      const double step = p1 / derivative;
      x -= step;
      if (std::abs(step) < 1e-16) break;
    }
    const double weight = 2.0 / ((1.0 - x * x) * derivative * derivative);
    // Map [−1, 1] to [0, 1]: node (1 ∓ x)/2, weight / 2.
    rule.nodes[i] = 0.5 * (1.0 - x);
    rule.nodes[n - 1 - i] = 0.5 * (1.0 + x);
    rule.weights[i] = rule.weights[n - 1 - i] = 0.5 * weight;
  }
  return rule;
}

QuadratureRule gauss_lobatto(int n) {
  if (n < 2) throw std::invalid_argument("a Gauss-Lobatto rule needs at least two nodes");
  QuadratureRule rule;
  rule.nodes.resize(n);
  rule.weights.resize(n);
  const int m = n - 1;  // interior nodes: roots of P'_m; weights 2/(n(n − 1)·P_m(x)²)
  auto legendre = [m](double x, double& p, double& dp, double& ddp) {
    double p0 = 1.0, p1 = x;
    for (int k = 2; k <= m; ++k) {
      const double p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
      p0 = p1;
      p1 = p2;
    }
    p = m == 0 ? 1.0 : p1;
    // P' and P'' from the Legendre equation: (1 − x²)P'' − 2xP' + m(m + 1)P = 0.
    dp = m * (x * p1 - p0) / (x * x - 1.0);
    ddp = (2.0 * x * dp - m * (m + 1.0) * p) / (1.0 - x * x);
  };
  for (int i = 0; i < (n + 1) / 2; ++i) {
    double x = -1.0;
    if (i > 0) {
      // Chebyshev–Gauss–Lobatto estimate, then Newton on P'_m.
      x = -std::cos(kPi * i / m);
      for (int iteration = 0; iteration < 100; ++iteration) {
        double p, dp, ddp;
        legendre(x, p, dp, ddp);
        const double step = dp / ddp;
        x -= step;
        if (std::abs(step) < 1e-16) break;
      }
    }
    double p, dp, ddp;
    if (i == 0) {
      p = (m % 2 == 0) ? 1.0 : -1.0;  // P_m(−1)
    } else {
      legendre(x, p, dp, ddp);
    }
    const double weight = 2.0 / (n * (n - 1.0) * p * p);
    rule.nodes[i] = 0.5 * (1.0 + x);
    rule.nodes[n - 1 - i] = 0.5 * (1.0 - x);
    rule.weights[i] = rule.weights[n - 1 - i] = 0.5 * weight;
  }
  return rule;
}

}  // namespace saltus
