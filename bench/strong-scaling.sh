#!/usr/bin/env bash
# Strong scaling of the DSMC scheduler on this machine: the same validation (default: the
# quick scenes bo1-fig02, bo1-fig05, bo2-fig05, mg-fig01) as 1 process x 1 thread, 1 x 2 threads,
# 2 MPI ranks x 1 thread, and 1 MPI rank x 2 threads (bound and unbound); wall time of the DSMC phase (summary.json
# dsmc_wall_seconds), speed-up against 1 x 1, and a check that the outputs are the same bytes.
# Usage: bench/strong-scaling.sh [BUILD] [SCENE.toml ...]   (prints a TSV on stdout)
set -euo pipefail
build=${1:-build}; shift || true
scenes=("$@")
[ ${#scenes[@]} -gt 0 ] || scenes=(compare/scenes/{bo1-fig02,bo1-fig05,bo2-fig05,mg-fig01}.toml)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir "$work/scenes"
cp "${scenes[@]}" "$work/scenes/"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
run() {  # name, launcher..., then granmix arguments after --
  local name=$1; shift
  local launch=()
  while [ "$1" != "--" ]; do launch+=("$1"); shift; done; shift
  "${launch[@]}" "$build/granmix" validate --scenes "$work/scenes" --out "$work/$name" "$@" > /dev/null 2>&1 || true
  python3 -c "import json,sys; s=json.load(open('$work/$name/summary.json')); print(s['dsmc_wall_seconds'], s['cpu_seconds'])"
}
echo "# granmix strong scaling, $(nproc) cores, load $(cut -d' ' -f1 /proc/loadavg) at start, $(date -u +%FT%TZ), git $(git rev-parse --short HEAD)"
printf "layout\tranks\tthreads\tdsmc_wall_s\tcpu_s\tspeedup\tsame_bytes\n"
base=""
# mpi: Open MPI's default binding (each rank to one core when np <= 2: two threads of one rank then
# share a core); mpi-unbound: --bind-to none, what hybrid ranks x threads runs need.
for layout in "serial 1 1" "serial 1 2" "mpi 2 1" "mpi 1 2" "mpi-unbound 1 2"; do
  set -- $layout
  kind=$1 ranks=$2 threads=$3 name="$1-$2x$3"
  case $kind in
    serial) r=$(run "$name" env -- --threads "$threads") ;;
    mpi) r=$(run "$name" mpirun --oversubscribe -n "$ranks" -- --threads "$threads") ;;
    *) r=$(run "$name" mpirun --oversubscribe --bind-to none -n "$ranks" -- --threads "$threads") ;;
  esac
  wall=${r% *} cpu=${r#* }
  [ -n "$base" ] || base=$wall
  same=yes
  for f in $(cd "$work/serial-1x1" && find . -name dsmc.tsv); do
    cmp -s <(grep -v '^#' "$work/serial-1x1/$f") <(grep -v '^#' "$work/$name/$f") || same=no
  done
  printf "%s\t%s\t%s\t%.2f\t%.2f\t%.2f\t%s\n" "$kind" "$ranks" "$threads" "$wall" "$cpu" "$(python3 -c "print($base/$wall)")" "$same"
done
