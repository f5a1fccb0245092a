#pragma once
// The scalar Sonine polynomials S_p = L_p^(1/2), p = 0, 2, 3, from their explicit sums (written here, not the
// library's table): the weights of a₂, a₃ in f = f_M[1 + a₂S₂(c²) + a₃S₃(c²)] for the tests' quadratures.
#include <cmath>

namespace granmix::test {

inline double scalar_sonine(int p, double x) {
  switch (p) {
    case 0: return 1.0;
    case 2: return x * x / 2 - 5 * x / 2 + 15.0 / 8;
    case 3: return -x * x * x / 6 + 7 * x * x / 4 - 35 * x / 8 + 35.0 / 16;
  }
  return NAN;
}

}  // namespace granmix::test
