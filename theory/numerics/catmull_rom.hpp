#pragma once
// Catmull–Rom cubic weights on a uniform grid (C¹: CVODE's Newton iterations see a smooth right-hand side). Used by the
// tables that follow a history in ln(temperature ratio): galerkin_decay.cpp, speed_grid_cooling.cpp.
#include <cmath>
#include <string>

#include "model/errors.hpp"

namespace granmix::theory {

// The weights of the grid nodes around x (in grid units): nodes ⌊x⌋ − 1 … ⌊x⌋ + 2, or ⌊x⌋ alone where x is a node (the
// own species, ρ = 1). what: named in the error for a non-finite x.
struct CatmullRom {
  long first;
  int count;
  double w[4];
};
inline CatmullRom catmull_rom(double x, const char* what) {
  if (!std::isfinite(x)) throw NumericalError(std::string(what) + " not finite and positive");
  const double f = std::floor(x), t = x - f;
  if (t == 0.0) return {long(f), 1, {1.0, 0.0, 0.0, 0.0}};
  return {long(f) - 1, 4,
          {0.5 * (-t + 2.0 * t * t - t * t * t), 0.5 * (2.0 - 5.0 * t * t + 3.0 * t * t * t), 0.5 * (t + 4.0 * t * t - 3.0 * t * t * t),
           0.5 * (-t * t + t * t * t)}};
}

}  // namespace granmix::theory
