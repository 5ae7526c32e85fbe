#pragma once
/// @file
/// Gauss–Legendre quadrature on [0, 1]: n nodes integrate polynomials of degree 2n − 1 exactly.
/// The optimiser integrates the root wrench span by span with it (the spline is a polynomial
/// piece on each knot span, with kinks only at the knots).

#include <vector>

namespace saltus {

struct QuadratureRule {
  std::vector<double> nodes;    ///< in (0, 1), increasing
  std::vector<double> weights;  ///< positive, summing to 1
};

/// The n-point Gauss–Legendre rule on [0, 1] (n >= 1), nodes and weights to rounding (Newton on
/// the Legendre polynomial). Throws std::invalid_argument for n < 1.
QuadratureRule gauss_legendre(int n);

}  // namespace saltus
