// Gauss-Legendre quadrature nodes and weights (Abramowitz & Stegun 25.4.29), used for the
// direction integrals of the atmosphere tables.
#pragma once

#include <vector>

namespace cloudsvc::reference {

struct QuadratureRule {
  std::vector<double> nodes;    // in (a, b)
  std::vector<double> weights;  // sum to b - a
};

// n-point Gauss-Legendre rule on [a, b]: exact for polynomials of degree 2n - 1. Nodes are
// the roots of P_n found by Newton's method from Chebyshev-like starting points.
QuadratureRule gauss_legendre(int n, double a, double b);

// n-point rule on [a, b] (a > b allowed) with nodes clustered towards a: Gauss-Legendre in
// u on [0, 1] after the substitution x = a + (b - a) u^2 (dx = 2 (b - a) u du). For
// integrands that vary fastest at one end, e.g. the radiance of rays grazing the horizon.
QuadratureRule gauss_legendre_clustered(int n, double a, double b);

}  // namespace cloudsvc::reference
