#pragma once
// One-dimensional root by GSL Brent bracketing; the bracket [-1, 1] is doubled until f changes
// sign (up to |x| <= limit), so callers work in log variables (ln of a temperature ratio).
// Converges to the last representable bits of x (relative 2e-16).
#include <functional>
#include <string>

namespace granmix::theory {

struct Root {
  double x = 0.0;
  int iterations = 0;
};

Root bracketed_root(const std::function<double(double)>& f, const std::string& what, double limit = 200.0);

}  // namespace granmix::theory
