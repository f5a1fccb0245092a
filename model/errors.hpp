#pragma once
// The two kinds of failure the command line maps to exit codes (docs/architecture.md §3):
// InputError -> 2 (bad scene or command line), NumericalError -> 3 (a solver failed).
#include <stdexcept>
#include <string>

namespace granmix {

struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct NumericalError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace granmix
