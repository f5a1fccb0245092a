#!/usr/bin/env bash
# Installs the Debian packages granmix builds on, only those that are missing.
# Idempotent; runs apt-get directly as root, through sudo otherwise.
set -euo pipefail

packages=(
  build-essential cmake pkg-config
  libsundials-dev      # CVODE 6.x: temperature ODEs, exact viscoelastic contact problem
  libgsl-dev           # root finding, adaptive quadrature
  libeigen3-dev        # small dense linear systems
  libboost-dev         # Boost.Math special functions
  catch2               # unit tests (v2, catch2/catch.hpp)
  gnuplot-nox          # figures
  libtomlplusplus-dev  # scene files
  libcli11-dev         # command line
  libfmt-dev
  nlohmann-json3-dev
  libpcg-cpp-dev       # random streams for DSMC
  libopenmpi-dev openmpi-bin  # MPI: DSMC units over ranks (GRANMIX_MPI, compare/scheduler.cpp)
  python3              # make mutants (tests/mutants/run_mutants.py, standard library only)
  python3-dev pybind11-dev    # the Python module granmix (python/, GRANMIX_PYTHON)
  python3-numpy python3-pytest  # its arrays and its tests (tests/python)
  python3-matplotlib   # examples/python/ternary.py's figure (its test is skipped without it)
  ccache               # make mutants rebuilds incrementally
)
if [ "${1:-}" = "--fuzz" ]; then  # make fuzz only: libFuzzer and the clang sanitizer runtimes
  packages=(clang libclang-rt-dev)
fi

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed'; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

if [ "$(id -u)" -eq 0 ]; then sudo=(); else sudo=(sudo); fi
echo "install-deps: installing ${missing[*]}"
"${sudo[@]}" apt-get update -qq
DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
echo "install-deps: done"
