#!/usr/bin/env bash
# Runs each libFuzzer harness of tests/fuzz for SECONDS, one after the other (niced), from the
# committed corpus tests/fuzz/corpus/<harness> (the scene harness also from every compare/scenes
# file). New inputs go to BUILD/fuzz-corpus/<harness> (merge the useful ones into the committed
# corpus with `-merge=1`); crashes, leaks, UB and inputs slower than 2 s go to BUILD/fuzz-findings/
# and fail the run.  Usage: scripts/run-fuzzers.sh BUILD SECONDS [HARNESS...]
set -euo pipefail
cd "$(dirname "$0")/.."
build=$1 seconds=$2
shift 2
harnesses=("$@")
[ ${#harnesses[@]} -gt 0 ] || harnesses=(scene hcs_args tsv_roundtrip)
mkdir -p "$build/fuzz-findings"
status=0
for h in "${harnesses[@]}"; do
  work="$build/fuzz-corpus/$h"
  mkdir -p "$work"
  seeds=("tests/fuzz/corpus/$h")
  [ "$h" = scene ] && seeds+=(compare/scenes)
  log="$build/fuzz-findings/$h.log"
  echo "fuzz $h: ${seconds} s, log $log"
  if ! nice -n 10 "$build/tests/fuzz/fuzz_$h" -max_total_time="$seconds" -timeout=2 -rss_limit_mb=2048 -print_final_stats=1 \
      -artifact_prefix="$build/fuzz-findings/$h-" "$work" "${seeds[@]}" > "$log" 2>&1; then
    echo "fuzz $h: FINDING (see $log and $build/fuzz-findings/$h-*)"
    status=1
  fi
  grep -E "^#[0-9]+.*(DONE|cov:)" "$log" | tail -n 1 || true
  grep -E "stat::number_of_executed_units" "$log" || true
done
exit $status
