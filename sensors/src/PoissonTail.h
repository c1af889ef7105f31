#pragma once
// Upper tail of the Poisson law, P(X >= n) for X ~ Poisson(lambda), as the
// regularized lower incomplete gamma P(n, lambda) (the identity for integer
// n; its continuous extension for the non-integer counts of N x Coates'
// flux). Returned as the pair (p, ln(1 - p)) so that a product of many
// (1 - p) stays exact both where p is tiny (a clear return) and where it is
// near 1 (noise). Private to the SPAD model (SpadEstimators.cpp).

namespace tofsim::sensors::detail {

struct PoissonTail {
  double p = 0.0;            ///< P(X >= n)
  double logNotTail = 0.0;   ///< ln P(X < n) = ln(1 - p)
};

/// n >= 0, lambda >= 0. n <= 0: p = 1; lambda = 0 and n > 0: p = 0.
PoissonTail poissonTail(double n, double lambda);

}  // namespace tofsim::sensors::detail
