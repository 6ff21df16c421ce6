// Gauss-Legendre quadrature (see quadrature.h).
#include "renderer/reference/quadrature.h"

#include <cmath>
#include <numbers>

namespace cloudsvc::reference {

QuadratureRule gauss_legendre(int n, double a, double b) {
  QuadratureRule rule;
  rule.nodes.resize(static_cast<std::size_t>(n));
  rule.weights.resize(static_cast<std::size_t>(n));
  const double half = 0.5 * (b - a), mid = 0.5 * (a + b);
  for (int i = 0; i < n; ++i) {
    // i-th root of P_n, starting from cos(pi (i + 3/4) / (n + 1/2)).
    double x = std::cos(std::numbers::pi * (i + 0.75) / (n + 0.5));
    double dp = 1.0;
    for (int iter = 0; iter < 100; ++iter) {
      // P_n(x) and P_n'(x) by the three-term recurrence (k+1) P_{k+1} = (2k+1) x P_k - k P_{k-1}.
      double p0 = 1.0, p1 = x;
      for (int k = 1; k < n; ++k) {
        const double p2 = ((2.0 * k + 1.0) * x * p1 - k * p0) / (k + 1.0);
        p0 = p1;
        p1 = p2;
      }
      const double pn = n == 0 ? 1.0 : p1, pn_1 = p0;
      dp = n * (x * pn - pn_1) / (x * x - 1.0);
      const double dx = pn / dp;
      x -= dx;
      if (std::abs(dx) < 1e-16) break;
    }
    rule.nodes[static_cast<std::size_t>(i)] = mid - half * x;
    rule.weights[static_cast<std::size_t>(i)] = half * 2.0 / ((1.0 - x * x) * dp * dp);
  }
  return rule;
}

QuadratureRule gauss_legendre_clustered(int n, double a, double b) {
  const QuadratureRule u = gauss_legendre(n, 0.0, 1.0);
  QuadratureRule rule;
  for (std::size_t i = 0; i < u.nodes.size(); ++i) {
    rule.nodes.push_back(a + (b - a) * u.nodes[i] * u.nodes[i]);
    rule.weights.push_back(std::abs(2.0 * (b - a) * u.nodes[i]) * u.weights[i]);
  }
  return rule;
}

}  // namespace cloudsvc::reference
