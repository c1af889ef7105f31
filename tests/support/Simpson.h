#pragma once
// Composite Simpson's rule, the tests' dense integral of a smooth function
// (the closed forms the medium's renderers are checked against).

namespace tofsim::test {

/// Simpson's rule of f over [a, b] with `steps` (even) intervals; 0 when
/// the interval is empty.
template <class F>
double simpson(const F& f, double a, double b, int steps = 2000) {
  if (b <= a) return 0.0;
  const double h = (b - a) / steps;
  double sum = f(a) + f(b);
  for (int i = 1; i < steps; ++i) sum += f(a + i * h) * (i % 2 == 1 ? 4.0 : 2.0);
  return sum * h / 3.0;
}

}  // namespace tofsim::test
