#pragma once
// The scalar Sonine polynomials S_p = L_p^(1/2), p = 0, 2, 3, 4, from their explicit sums (written here, not the
// library's table): the weights of a₂, a₃, a₄ in f = f_M[1 + a₂S₂(c²) + a₃S₃(c²) + a₄S₄(c²)] for the tests' quadratures.
#include <cmath>

namespace granmix::test {

inline double scalar_sonine(int p, double x) {
  switch (p) {
    case 0: return 1.0;
    case 2: return x * x / 2 - 5 * x / 2 + 15.0 / 8;
    case 3: return -x * x * x / 6 + 7 * x * x / 4 - 35 * x / 8 + 35.0 / 16;
    case 4: return x * x * x * x / 24 - 3 * x * x * x / 4 + 63 * x * x / 16 - 105 * x / 16 + 315.0 / 128;
  }
  return NAN;
}

}  // namespace granmix::test
