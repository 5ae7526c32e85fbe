#pragma once
/// @file
/// Gauss quadrature on [0, 1]: Legendre (n nodes, exact to degree 2n − 1) and Lobatto (the ends
/// included, exact to degree 2n − 3). The optimiser integrates the root wrench span by span with
/// Lobatto nodes (the spline is smooth on each knot span and kinks only at the knots).

#include <vector>

namespace saltus {

struct QuadratureRule {
  std::vector<double> nodes;    ///< in [0, 1], increasing
  std::vector<double> weights;  ///< positive, summing to 1
};

/// The n-point Gauss–Legendre rule on [0, 1] (n >= 1), nodes and weights to rounding (Newton on
/// the Legendre polynomial). Throws std::invalid_argument for n < 1.
QuadratureRule gauss_legendre(int n);

/// The n-point Gauss–Lobatto rule on [0, 1] (n >= 2): both ends are nodes, the others the roots
/// of P'_{n−1}; exact for degree 2n − 3. The ends matter where a function may kink or peak
/// there (a spline's knots), which a Gauss–Legendre rule never looks at.
QuadratureRule gauss_lobatto(int n);

}  // namespace saltus
